#include "contact/mortar_face_integration.hpp"

#include "contact/mortar_edge_integration.hpp"

#include "common/error.hpp"
#include "fem/reference_face.hpp"

#include <cmath>
#include <limits>

namespace feticon::contact
{
namespace
{
using mesh::FaceKind;

/// Auxiliary plane of a slave face of any type: its point and normal at the reference centre.
struct FacePlane
{
  Eigen::Vector3d origin;
  Eigen::Vector3d normal;
  Eigen::Vector3d axis_1;
  Eigen::Vector3d axis_2;

  Eigen::Vector2d project(const Eigen::Vector3d& x) const { return {axis_1.dot(x - origin), axis_2.dot(x - origin)}; }
};

Eigen::Vector2d reference_centre(FaceKind kind)
{
  return mesh::face_corners(kind) == 3 ? Eigen::Vector2d(1.0 / 3, 1.0 / 3) : Eigen::Vector2d(0, 0);
}

FacePlane face_plane(const FaceGeometry& face)
{
  const Eigen::Vector2d centre = reference_centre(face.kind);
  FacePlane plane;
  plane.origin = face_point(face, centre);
  plane.normal = face_normal(face, centre);
  // x_,xi is orthogonal to n = x_,xi x x_,eta / |.| by construction.
  const Eigen::Vector3d d_xi = face.x.transpose() * fem::face_shape_gradients(face.kind, centre).col(0);
  plane.axis_1 = d_xi.normalized();
  plane.axis_2 = plane.normal.cross(plane.axis_1);
  return plane;
}

/// A linear sub-facet of a face (face_sub_facets): its corners in 3D, in the auxiliary plane and
/// in the parent face's reference coordinates.
struct SubFacet
{
  int n = 0; ///< 3 or 4 corners
  Eigen::Matrix<double, 4, 3> x;
  Eigen::Matrix<double, 4, 2> plane;
  Eigen::Matrix<double, 4, 2> parent;

  std::vector<Eigen::Vector2d> polygon(bool reversed) const
  {
    std::vector<Eigen::Vector2d> out(n);
    for (int k = 0; k < n; ++k)
      out[k] = plane.row(reversed ? n - 1 - k : k).transpose();
    return out;
  }

  /// The parent coordinates of plane point p, and the 3D area over the plane area there.
  std::optional<std::pair<Eigen::Vector2d, double>> locate(const Eigen::Vector2d& p) const
  {
    if (n == 3)
    {
      Eigen::Matrix2d edges;
      edges << plane(1, 0) - plane(0, 0), plane(2, 0) - plane(0, 0), plane(1, 1) - plane(0, 1),
          plane(2, 1) - plane(0, 1);
      const double planar = edges.determinant();
      if (!(std::abs(planar) > 0))
        return std::nullopt;
      const Eigen::Vector2d st = edges.inverse() * (p - plane.row(0).transpose());
      const Eigen::Vector2d xi = parent.row(0).transpose() + st(0) * (parent.row(1) - parent.row(0)).transpose() +
          st(1) * (parent.row(2) - parent.row(0)).transpose();
      const double area = (x.row(1) - x.row(0)).cross(x.row(2) - x.row(0)).norm();
      return std::pair{xi, area / std::abs(planar)};
    }
    const std::optional<Eigen::Vector2d> eta = inverse_bilinear(plane, p);
    if (!eta)
      return std::nullopt;
    const Eigen::Vector4d shape = quad_shape_functions(*eta);
    const Eigen::Vector2d xi = parent.transpose() * shape;
    const double planar = std::abs((plane.transpose() * bilinear_derivatives(*eta)).determinant());
    return std::pair{xi, surface_jacobian(x, *eta) / planar};
  }
};

std::vector<SubFacet> sub_facets(const FaceGeometry& face, const FacePlane& plane)
{
  std::vector<SubFacet> out;
  for (const std::vector<int>& nodes : face_sub_facets(face.kind))
  {
    SubFacet facet;
    facet.n = static_cast<int>(nodes.size());
    for (int k = 0; k < facet.n; ++k)
    {
      facet.x.row(k) = face.x.row(nodes[k]);
      facet.plane.row(k) = plane.project(Eigen::Vector3d(face.x.row(nodes[k]).transpose())).transpose();
      facet.parent.row(k) = face_node_xi(face.kind, nodes[k]).transpose();
    }
    out.push_back(facet);
  }
  return out;
}

/// 5 x 5 points on the reference triangle, as integrate_segment's default.
const QuadratureRule2d& segment_rule()
{
  static const QuadratureRule2d rule = gauss_triangle(SegmentOptions{}.triangle_points);
  return rule;
}
} // namespace

bool is_quadratic(FaceKind kind)
{
  return kind == FaceKind::tri6 || kind == FaceKind::quad8 || kind == FaceKind::line3;
}

fem::FaceValues transformed_shape_values(FaceKind kind, const Eigen::Vector2d& xi)
{
  fem::FaceValues N = fem::face_shape_values(kind, xi);
  if (!is_quadratic(kind))
    return N;
  const int corners = mesh::face_corners(kind);
  constexpr double alpha = quadratic_dual_alpha;
  // Edge node corners + e joins corners e and e + 1 (a line3's one edge node joins its ends).
  for (int e = 0; e < mesh::face_nodes(kind) - corners; ++e)
  {
    const double edge = N(corners + e);
    N(e) += alpha * edge;
    N((e + 1) % corners) += alpha * edge;
    N(corners + e) = (1 - 2 * alpha) * edge;
  }
  return N;
}

FaceDualBasis face_dual_basis(const FaceGeometry& slave)
{
  // Degree 8 on triangles, 7 per direction on quadrilaterals: N~ N~ times the area element;
  // degree 9 on edges, where the area element also holds the measure (linear in axisymmetry).
  static const QuadratureRule2d triangle = gauss_triangle(5);
  static const QuadratureRule2d square = gauss_square(4);
  static const QuadratureRule2d segment = gauss_legendre_1d(5);
  const bool line = mesh::is_line(slave.kind);
  const bool tri = mesh::face_corners(slave.kind) == 3;
  const QuadratureRule2d& rule = line ? segment : tri ? triangle : square;
  const double reference_area = tri ? 0.5 : 1.0; // gauss_triangle's weights sum to 1, the others' to 2^dimension
  const auto n = static_cast<Eigen::Index>(slave.x.rows());
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(n, n);
  FaceDualBasis dual;
  dual.nodal_area = Eigen::VectorXd::Zero(n);
  for (size_t q = 0; q < rule.points.size(); ++q)
  {
    const Eigen::Vector2d& xi = rule.points[q];
    const Eigen::VectorXd shape = transformed_shape_values(slave.kind, xi);
    const Eigen::Matrix<double, 3, 2> t = slave.x.transpose() * fem::face_shape_gradients(slave.kind, xi);
    const double element =
        line ? t.col(0).norm() * slave.planar.measure(face_point(slave, xi)) : t.col(0).cross(t.col(1)).norm();
    const double weight = reference_area * rule.weights[q] * element;
    mass += weight * shape * shape.transpose();
    dual.nodal_area += weight * shape;
  }
  dual.coefficients = dual_coefficients(dual.nodal_area, mass);
  return dual;
}

SlaveFootprint::SlaveFootprint(const FaceGeometry& slave)
{
  const FacePlane plane = face_plane(slave);
  _origin = plane.origin;
  _axis_1 = plane.axis_1;
  _axis_2 = plane.axis_2;
  _low = _high = plane.project(slave.x.row(0).transpose());
  for (Eigen::Index k = 1; k < slave.x.rows(); ++k)
  {
    const Eigen::Vector2d p = plane.project(slave.x.row(k).transpose());
    _low = _low.cwiseMin(p);
    _high = _high.cwiseMax(p);
  }
  _margin = 1e-9 * (_high - _low).maxCoeff();
}

bool SlaveFootprint::may_overlap(const FaceGeometry& master) const
{
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (Eigen::Index k = 0; k < master.x.rows(); ++k)
  {
    const Eigen::Vector3d d = master.x.row(k).transpose() - _origin;
    const Eigen::Vector2d p(_axis_1.dot(d), _axis_2.dot(d));
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (low.array() <= _high.array() + _margin).all() && (high.array() >= _low.array() - _margin).all();
}

std::optional<Eigen::MatrixXd> integrate_face_segment(const FaceGeometry& slave, const FaceDualBasis& dual,
                                                      const FaceGeometry& master, const SegmentOptions& options)
{
  if (mesh::is_line(slave.kind))
    return integrate_edge_segment(slave, dual, master, options);
  const FacePlane plane = face_plane(slave);
  if (!(-face_normal(master, reference_centre(master.kind)).dot(plane.normal) >= options.min_facing))
    return std::nullopt;
  const QuadratureRule2d custom = options.triangle_points == SegmentOptions{}.triangle_points
      ? QuadratureRule2d{}
      : gauss_triangle(options.triangle_points);
  const QuadratureRule2d& rule = custom.points.empty() ? segment_rule() : custom;
  const std::vector<SubFacet> slave_facets = sub_facets(slave, plane);
  const std::vector<SubFacet> master_facets = sub_facets(master, plane);

  double slave_area = 0;
  for (const SubFacet& s : slave_facets)
    slave_area += polygon_area(s.polygon(false));
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(slave.x.rows(), master.x.rows());
  bool overlap = false;
  for (const SubFacet& s : slave_facets)
  {
    const std::vector<Eigen::Vector2d> slave_polygon = s.polygon(false);
    FETICON_CHECK(strictly_convex_ccw(slave_polygon),
                  "mortar: a slave face is not convex in its auxiliary plane "
                      << "(first node " << slave.x.row(0) << "); check the mesh");
    for (const SubFacet& m : master_facets)
    {
      // The master normal is opposite to the plane's: its reversed corners turn counter-clockwise.
      const std::vector<Eigen::Vector2d> master_polygon = m.polygon(true);
      if (!strictly_convex_ccw(master_polygon))
        continue;
      const std::vector<Eigen::Vector2d> polygon = clip_polygon(master_polygon, slave_polygon);
      if (polygon.empty() || !(polygon_area(polygon) > options.min_area_fraction * slave_area))
        continue;
      overlap = true;
      for_each_fan_point(polygon, rule, [&](const Eigen::Vector2d& point, double weight) {
        const auto on_slave = s.locate(point);
        const auto on_master = m.locate(point);
        FETICON_CHECK(on_slave && on_master,
                      "mortar: a face map failed at plane point " << point.transpose() << "; check the mesh");
        const double area = weight * on_slave->second;
        const fem::FaceValues phi = dual.coefficients * transformed_shape_values(slave.kind, on_slave->first);
        coupling += area * phi * fem::face_shape_values(master.kind, on_master->first).transpose();
      });
    }
  }
  if (!overlap)
    return std::nullopt;
  return coupling;
}
} // namespace feticon::contact
