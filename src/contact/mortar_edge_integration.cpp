#include "contact/mortar_edge_integration.hpp"

#include "common/error.hpp"
#include "fem/reference_face.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace feticon::contact
{
namespace
{
/// A chord of an edge (face_sub_facets: corner to corner, or corner to edge node) on the slave's
/// auxiliary line: its ends' line coordinates t, parent coordinates xi and 3D points.
struct Chord
{
  double t[2];
  double xi[2];
  Eigen::Vector3d x[2];

  double low() const { return std::min(t[0], t[1]); }
  double high() const { return std::max(t[0], t[1]); }
  /// The parent coordinate and 3D point at line coordinate t (linear along the chord).
  std::pair<double, Eigen::Vector3d> at(double line) const
  {
    const double s = (line - t[0]) / (t[1] - t[0]);
    return {xi[0] + s * (xi[1] - xi[0]), x[0] + s * (x[1] - x[0])};
  }
  /// ds / dt: the chord's length over its projected length.
  double stretch() const { return (x[1] - x[0]).norm() / std::abs(t[1] - t[0]); }
};

/// The one or two chords of an edge (line2, line3), without allocating.
struct Chords
{
  std::array<Chord, 2> items;
  size_t size = 0;
  const Chord* begin() const { return items.data(); }
  const Chord* end() const { return items.data() + size; }
};

Chords chords(const FaceGeometry& edge, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis)
{
  Chords out;
  for (const std::vector<int>& ends : face_sub_facets(edge.kind))
  {
    FETICON_ASSERT(out.size < out.items.size(), "an edge of more than two chords");
    Chord& chord = out.items[out.size++];
    for (int k = 0; k < 2; ++k)
    {
      chord.x[k] = edge.x.row(ends[k]).transpose();
      chord.t[k] = axis.dot(chord.x[k] - origin);
      chord.xi[k] = face_node_xi(edge.kind, ends[k])(0);
    }
  }
  return out;
}

/// Gauss-Legendre with 5 points, exact to degree 9: Phi N^m (degree 4) times the measure (linear
/// in axisymmetry) and the line3 length element.
const QuadratureRule2d& edge_rule()
{
  static const QuadratureRule2d rule = gauss_legendre_1d(5);
  return rule;
}
} // namespace

std::optional<Eigen::MatrixXd> integrate_edge_segment(const FaceGeometry& slave, const FaceDualBasis& dual,
                                                      const FaceGeometry& master, const SegmentOptions& options)
{
  const Eigen::Vector2d centre(0, 0);
  const Eigen::Vector3d normal = face_normal(slave, centre);
  if (!(-face_normal(master, centre).dot(normal) >= options.min_facing))
    return std::nullopt;
  const Eigen::Vector3d origin = face_point(slave, centre);
  const Eigen::Vector3d axis =
      (slave.x.transpose() * fem::face_shape_gradients(slave.kind, centre).col(0)).normalized();
  const Chords slave_chords = chords(slave, origin, axis);
  const Chords master_chords = chords(master, origin, axis);

  double slave_length = 0;
  for (const Chord& s : slave_chords)
  {
    FETICON_CHECK(s.t[1] > s.t[0],
                  "mortar: a slave edge folds back on its tangent (first node " << slave.x.row(0)
                                                                                << "); check the mesh");
    slave_length += s.t[1] - s.t[0];
  }
  const QuadratureRule2d& rule = edge_rule();
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(slave.x.rows(), master.x.rows());
  bool overlap = false;
  for (const Chord& s : slave_chords)
    for (const Chord& m : master_chords)
    {
      const double low = std::max(s.low(), m.low()), high = std::min(s.high(), m.high());
      if (!(high - low > options.min_area_fraction * slave_length) || !(m.high() - m.low() > 0))
        continue;
      overlap = true;
      const double half = 0.5 * (high - low), mid = 0.5 * (high + low);
      for (size_t q = 0; q < rule.points.size(); ++q)
      {
        const double t = mid + half * rule.points[q](0);
        const auto [xi_slave, x_slave] = s.at(t);
        const double xi_master = m.at(t).first;
        const double weight = rule.weights[q] * half * s.stretch() * slave.planar.measure(x_slave);
        const fem::FaceValues phi = dual.coefficients * transformed_shape_values(slave.kind, {xi_slave, 0});
        coupling += weight * phi * fem::face_shape_values(master.kind, {xi_master, 0}).transpose();
      }
    }
  if (!overlap)
    return std::nullopt;
  return coupling;
}
} // namespace feticon::contact
