#pragma once
/// @file Segment-to-segment integration of dual mortar coupling terms (Wohlmuth 2000; Puso and
/// Laursen 2004; Popp, Gee, Wall 2009, IJNME 79; Popp, Gitterle, Gee, Wall 2010, IJNME 83).
///
/// Dual basis. On a slave face with bilinear shape functions N_k (closest_point.hpp corner order)
/// the dual functions Phi_j = sum_k A_jk N_k satisfy the biorthogonality
///   int_e Phi_j N_k dA = delta_jk D_j,   A = D M^-1,  D = diag(int_e N_j dA),
///   M_jk = int_e N_j N_k dA,
/// and sum_j Phi_j = 1 (1' D = 1' M because sum_k N_k = 1). D and M are integrated on the
/// reference square with a 4 x 4 Gauss rule, exact for flat faces (N_j N_k J has degree 3 per
/// direction) and accurate to O(warp^8) otherwise.
///
/// Segmentation (auxiliary plane of Puso and Laursen 2004). A slave face e and a master face m
/// are projected along n_0, the slave normal at the face centre, onto the plane through the slave
/// centre x_0 normal to n_0, with in-plane axes t_1, t_2 (t_1 x t_2 = n_0). The slave polygon is
/// counter-clockwise; the master polygon, whose normal points the other way, is reversed. The
/// master polygon is clipped by the (convex) slave polygon (Sutherland-Hodgman); the intersection
/// is fanned into triangles about its vertex mean, and each triangle gets a collapsed
/// (Duffy / Stroud conical product) Gauss rule of 5 x 5 points, exact for polynomials of total
/// degree 8. A plane point p is mapped to slave coordinates xi_s by inverting the projected
/// (planar) slave bilinear map, and to master coordinates xi_m by inverting the projected master
/// map (Newton): xi_m is the projection pi(x) of the slave point x(xi_s) onto the master face
/// along n_0. The slave area element is dA = (J_s / J_p) dA_p with J_s = |x_,xi x x_,eta| of the
/// 3D slave face and J_p the Jacobian of its planar projection, both at xi_s. Then
///   coupling(j, a) = int_(e cut pi^-1(m)) Phi_j(xi_s) N_a(xi_m) dA.
/// For flat parallelogram faces the integrand is a polynomial of degree 4 in the plane
/// coordinates and the result is exact to round-off; on flat non-parallelogram or warped faces
/// the inverse maps are not polynomial and the rule is accurate, not exact.
///
/// Usage:
///   const DualBasis dual = dual_basis(slave_quad);
///   const std::optional<SegmentCoupling> s = integrate_segment(slave_quad, dual, master_quad);
///   if (s) M_j_a += s->coupling(j, a);   // j, a corner indices of the two faces

#include "contact/closest_point.hpp"

#include "common/error.hpp"

#include <optional>
#include <vector>

#include <Eigen/Dense>

namespace feticon::contact
{
/// Points and weights of a quadrature rule on a 2D domain.
struct QuadratureRule2d
{
  std::vector<Eigen::Vector2d> points;
  std::vector<double> weights;
};

/// @brief Gauss-Legendre rule on [-1, 1]: n points, exact for degree 2n - 1.
/// @return nodes (ascending) as `points` (first component; second 0) and weights summing to 2.
QuadratureRule2d gauss_legendre_1d(int n);

/// @brief Tensor Gauss-Legendre rule with n x n points on the square [-1, 1]^2 (weights sum to 4).
QuadratureRule2d gauss_square(int n);

/// @brief Collapsed Gauss rule with n x n points on the triangle (0,0), (1,0), (0,1), exact for
/// polynomials of total degree 2n - 2. The weights sum to 1 (multiply by the triangle area).
QuadratureRule2d gauss_triangle(int n);

/// Dual basis of one slave face (file comment).
struct DualBasis
{
  /// Coefficients A: Phi_j = sum_k A(j, k) N_k.
  Eigen::Matrix4d coefficients = Eigen::Matrix4d::Identity();
  /// D_j = int_e N_j dA = int_e Phi_j N_j dA (m^2).
  Eigen::Vector4d nodal_area = Eigen::Vector4d::Zero();
};

/// @brief The coefficients A = D M^-1 of a dual basis from the nodal areas D and the mass
/// matrix M of a slave face (file comment).
/// @throws feticon::Error if a nodal area is not positive (a degenerate slave face).
template <class Vector, class Matrix>
Matrix dual_coefficients(const Vector& nodal_area, const Matrix& mass)
{
  FETICON_CHECK((nodal_area.array() > 0).all(),
                "mortar: degenerate slave face (nodal areas " << nodal_area.transpose() << " m^2); check the mesh");
  return nodal_area.asDiagonal() * mass.inverse();
}

/// @brief Nodal areas int_e N_j dA of a face (m^2), 4 x 4 Gauss as dual_basis; no checks.
Eigen::Vector4d face_nodal_areas(const QuadCoordinates& face);

/// @brief Dual basis of the slave face `slave` (current corner coordinates, m).
/// @throws feticon::Error if the face is degenerate (a zero or negative nodal area).
DualBasis dual_basis(const QuadCoordinates& slave);

/// @brief Dual functions Phi_j(xi), j = 0..3, of a face with dual basis `dual`.
Eigen::Vector4d dual_shape_functions(const DualBasis& dual, const Eigen::Vector2d& xi);

/// @brief Sutherland-Hodgman: the part of polygon `subject` inside the convex counter-clockwise
/// polygon `clip` (points on the clip boundary count as inside). Empty if they do not overlap.
std::vector<Eigen::Vector2d> clip_polygon(const std::vector<Eigen::Vector2d>& subject,
                                          const std::vector<Eigen::Vector2d>& clip);

/// Signed area of a polygon (> 0 counter-clockwise), shoelace formula.
double polygon_area(const std::vector<Eigen::Vector2d>& polygon);

/// Whether the polygon (corners in order) turns left at every corner by more than round-off.
bool strictly_convex_ccw(const std::vector<Eigen::Vector2d>& polygon);

/// Bilinear shape-function derivatives dN_a/dxi (column 0) and dN_a/deta (column 1) at xi.
Eigen::Matrix<double, 4, 2> bilinear_derivatives(const Eigen::Vector2d& xi);

/// Area element |x_,xi x x_,eta| of a 3D bilinear face at xi.
double surface_jacobian(const QuadCoordinates& quad, const Eigen::Vector2d& xi);

/// @brief Calls f(point, weight) for every point of `rule` (gauss_triangle) on the triangles
/// that fan the convex polygon about its vertex mean (which lies inside it); weight is the
/// rule's weight times the triangle's area, so the weights sum to the polygon's area.
template <class Function>
void for_each_fan_point(const std::vector<Eigen::Vector2d>& polygon, const QuadratureRule2d& rule, Function&& f)
{
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& vertex : polygon)
    centre += vertex;
  centre /= static_cast<double>(polygon.size());
  for (size_t k = 0; k < polygon.size(); ++k)
  {
    const Eigen::Vector2d edge_1 = polygon[k] - centre;
    const Eigen::Vector2d edge_2 = polygon[(k + 1) % polygon.size()] - centre;
    const double triangle_area = 0.5 * (edge_1(0) * edge_2(1) - edge_1(1) * edge_2(0));
    for (size_t q = 0; q < rule.points.size(); ++q)
      f(Eigen::Vector2d(centre + rule.points[q](0) * edge_1 + rule.points[q](1) * edge_2),
        rule.weights[q] * triangle_area);
  }
}

/// @brief Inverse of the planar bilinear map p(xi) = sum_a N_a(xi) corners_a (Newton from 0).
/// @return xi with p(xi) = point to |dxi| < 1e-14, or nothing if Newton fails (singular map).
std::optional<Eigen::Vector2d> inverse_bilinear(const Eigen::Matrix<double, 4, 2>& corners,
                                                const Eigen::Vector2d& point);

/// Mortar integrals of one (slave face, master face) segment.
struct SegmentCoupling
{
  /// coupling(j, a) = int Phi_j N_a^m dA over the segment, j slave and a master corner (m^2).
  Eigen::Matrix4d coupling = Eigen::Matrix4d::Zero();
  /// Slave area of the segment, int dA (m^2).
  double area = 0;
};

/// Parameters of integrate_segment.
struct SegmentOptions
{
  /// Points per direction of the collapsed triangle rule (exact for degree 2n - 2).
  int triangle_points = 5;
  /// A master face is skipped when -n_m . n_0 < min_facing (n_m its centre normal): it faces away
  /// from the slave face or is seen edge-on (0.1: more than about 84 degrees from antiparallel).
  double min_facing = 0.1;
  /// Segments with a plane area below this fraction of the slave face's are dropped (round-off
  /// slivers along shared edges of matching meshes).
  double min_area_fraction = 1e-12;
};

/// @brief Mortar integrals of the slave face `slave` (dual basis `dual`) against the master face
/// `master` (file comment).
/// @return nothing if the faces do not overlap in the auxiliary plane, the master face does not
/// face the slave (SegmentOptions::min_facing), or a projected face is not strictly convex.
std::optional<SegmentCoupling> integrate_segment(const QuadCoordinates& slave, const DualBasis& dual,
                                                 const QuadCoordinates& master, const SegmentOptions& options = {});
} // namespace feticon::contact
