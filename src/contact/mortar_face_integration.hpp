#pragma once
/// @file Dual mortar integrals on faces of every type (tri3, tri6, quad4, quad8): the dual basis
/// of a slave face and the coupling of a (slave face, master face) segment. quad4 against quad4
/// keeps mortar_integration.hpp's own code (the arithmetic of hex8 runs); this file is the same
/// method written over the face types' shape functions (fem/reference_face.hpp).
///
/// Quadratic slave faces (Popp, Gitterle, Gee & Wall 2010, IJNME 83, section 4.3). The dual
/// basis needs positive nodal integrals D_j = int N_j dA, but int N_j dA is 0 at a tri6's corners
/// and -A/12 at a quad8's: there is no dual basis of the standard functions with D > 0, and the
/// consistent loads of a uniform pressure pull at those corners. The slave functions are
/// therefore transformed, with alpha = quadratic_dual_alpha:
///   N~_c = N_c + alpha sum_(edge nodes m of c) N_m   (corner c),
///   N~_m = (1 - 2 alpha) N_m                         (edge node m),
/// which keeps sum N~ = 1 and gives int N~_c dA = 2 alpha A/3 (tri6) or (2 alpha/3 - 1/12) A
/// (quad8), positive for alpha > 1/8, and int N~_m dA = (1 - 2 alpha) A/3 > 0 for alpha < 1/2.
/// The dual functions are built on N~ (Phi_j = sum_k A_jk N~_k, int Phi_j N~_k = delta_jk D~_j).
/// A slave position x = sum N_k x_k = sum N~_k x~_k has the transformed nodal values
///   x~_c = x_c,  x~_m = (x_m - alpha (x_c1 + x_c2)) / (1 - 2 alpha)   (c1, c2 the ends of m's edge),
/// so the weighted gap of an edge node couples it to its edge's corners (mortar_constraints.hpp).
/// alpha = 1/5 as CalculiX's quad8 mortar (dualshape8qtilde.f, Sitzmann's thesis), for both
/// types: corners D~ = 2A/15 (tri6) and A/20 (quad8), edge nodes 3A/15.
///
/// Segmentation. Each face is cut into its linear sub-facets (face_geometry.hpp: a tri6 into four
/// triangles, a quad8 into four corner triangles and the quadrilateral of its edge nodes; tri3
/// and quad4 are one facet). Every (slave sub-facet, master sub-facet) pair is projected on the
/// slave face's auxiliary plane (centre point and normal), clipped and integrated as in
/// mortar_integration.hpp; a plane point maps to the sub-facet's own coordinates (affine for a
/// triangle, bilinear for a quadrilateral) and from there to the parent face's reference
/// coordinates, where the quadratic shape functions are evaluated. The area element is that of
/// the sub-facet. For flat faces this is exact (the patch test); on curved quadratic faces the
/// sub-facets are chords of the surface, accurate to O(h^2) in the geometry.
///
/// Usage:
///   const FaceDualBasis dual = face_dual_basis(slave_face);
///   if (auto m = integrate_face_segment(slave_face, dual, master_face)) coupling(j, a) += (*m)(j, a);

#include "contact/face_geometry.hpp"
#include "contact/mortar_integration.hpp"

#include <optional>

#include <Eigen/Dense>

namespace feticon::contact
{
/// Weight of its edge nodes' functions that a quadratic face's corner function takes (file comment).
inline constexpr double quadratic_dual_alpha = 0.2;

/// Whether a face type has edge nodes (and so transformed slave functions): tri6, quad8, line3
/// (mortar_edge_integration.hpp).
bool is_quadratic(mesh::FaceKind kind);

/// The slave functions N~(xi): the standard ones for tri3, quad4 and line2, transformed for
/// tri6, quad8 and line3 (file comment).
fem::FaceValues transformed_shape_values(mesh::FaceKind kind, const Eigen::Vector2d& xi);

/// Dual basis of one slave face of any type.
struct FaceDualBasis
{
  /// Coefficients A: Phi_j = sum_k A(j, k) N~_k.
  Eigen::MatrixXd coefficients;
  /// D~_j = int N~_j dA (m^2), positive.
  Eigen::VectorXd nodal_area;
};

/// @brief Dual basis of the slave face (current node coordinates, m); of an edge of a 2D cell
/// (line2, line3) with the area element ds times the model's measure (mortar_edge_integration.hpp).
/// @throws feticon::Error if a nodal area D~_j is not positive (a degenerate face).
FaceDualBasis face_dual_basis(const FaceGeometry& slave);

/// @brief Mortar integrals int Phi_j N_a^m dA of the slave face (dual basis `dual`) against the
/// master face: rows the slave face's nodes, columns the master face's (standard functions).
/// An edge of a 2D cell goes to integrate_edge_segment (mortar_edge_integration.hpp).
/// @return nothing if they do not overlap in the slave face's auxiliary plane, or the master
/// face does not face the slave (SegmentOptions::min_facing).
/// @throws feticon::Error if a slave sub-facet is not convex in the auxiliary plane.
std::optional<Eigen::MatrixXd> integrate_face_segment(const FaceGeometry& slave, const FaceDualBasis& dual,
                                                      const FaceGeometry& master, const SegmentOptions& options = {});

/// The rectangle that a slave face's nodes span in its auxiliary plane (centre point, x_,xi
/// and the normal there: the plane of integrate_face_segment, integrate_edge_segment and
/// mortar_integration.hpp's integrate_segment). A master face whose nodes all project beside
/// it overlaps it nowhere (every segment polygon or interval lies in both rectangles), so those
/// routines would return nothing: the search's candidates, whose boxes are grown by the search
/// distance in every direction, are sorted out before them (on the 2D Hertz mesh at 120
/// elements across 2a, 86 candidates a slave edge, of which 2 or 3 overlap).
class SlaveFootprint
{
public:
  explicit SlaveFootprint(const FaceGeometry& slave);
  /// False only if the master's projected nodes lie wholly beside the rectangle (by more than
  /// 1e-9 of its size, so that a master the routines would integrate is never left out).
  bool may_overlap(const FaceGeometry& master) const;

private:
  Eigen::Vector3d _origin, _axis_1, _axis_2;
  Eigen::Vector2d _low, _high;
  double _margin = 0;
};
} // namespace feticon::contact
