#include "contact/mortar_integration.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace feticon::contact
{
Eigen::Matrix<double, 4, 2> bilinear_derivatives(const Eigen::Vector2d& xi)
{
  Eigen::Matrix<double, 4, 2> d;
  for (int a = 0; a < 4; ++a)
  {
    d(a, 0) = 0.25 * quad_corners[a][0] * (1 + quad_corners[a][1] * xi(1));
    d(a, 1) = 0.25 * quad_corners[a][1] * (1 + quad_corners[a][0] * xi(0));
  }
  return d;
}

double surface_jacobian(const QuadCoordinates& quad, const Eigen::Vector2d& xi)
{
  const Eigen::Matrix<double, 3, 2> tangents = quad.transpose() * bilinear_derivatives(xi);
  return tangents.col(0).cross(tangents.col(1)).norm();
}

namespace
{
/// Auxiliary plane of a slave face: origin x_0 (face centre), normal n_0, axes t_1 x t_2 = n_0.
struct AuxiliaryPlane
{
  Eigen::Vector3d origin;
  Eigen::Vector3d normal;
  Eigen::Vector3d axis_1;
  Eigen::Vector3d axis_2;

  Eigen::Vector2d project(const Eigen::Vector3d& x) const { return {axis_1.dot(x - origin), axis_2.dot(x - origin)}; }
  Eigen::Matrix<double, 4, 2> project(const QuadCoordinates& quad) const
  {
    Eigen::Matrix<double, 4, 2> corners;
    for (int a = 0; a < 4; ++a)
      corners.row(a) = project(Eigen::Vector3d(quad.row(a).transpose())).transpose();
    return corners;
  }
};

AuxiliaryPlane auxiliary_plane(const QuadCoordinates& slave)
{
  AuxiliaryPlane plane;
  plane.origin = quad_point(slave, Eigen::Vector2d::Zero());
  plane.normal = quad_normal(slave, Eigen::Vector2d::Zero());
  // x_,xi at the centre is orthogonal to n_0 = x_,xi x x_,eta / |.| by construction.
  const Eigen::Vector3d d_xi = slave.transpose() * bilinear_derivatives(Eigen::Vector2d::Zero()).col(0);
  plane.axis_1 = d_xi.normalized();
  plane.axis_2 = plane.normal.cross(plane.axis_1);
  return plane;
}

double cross_2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a(0) * b(1) - a(1) * b(0); }

} // namespace

QuadratureRule2d gauss_legendre_1d(int n)
{
  FETICON_CHECK(n >= 1 && n <= 64, "gauss_legendre_1d: n = " << n << " must be in [1, 64]");
  QuadratureRule2d rule;
  rule.points.resize(n, Eigen::Vector2d::Zero());
  rule.weights.resize(n);
  for (int i = 0; i < n; ++i)
  {
    // Newton on P_n from the Chebyshev-like guess of the i-th largest root.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1;
    for (int iteration = 0; iteration < 100; ++iteration)
    {
      double previous = 1; // P_(k-1)
      double value = x;    // P_k, three-term recurrence up to k = n
      for (int k = 2; k <= n; ++k)
      {
        const double next = ((2 * k - 1) * x * value - (k - 1) * previous) / k;
        previous = value;
        value = next;
      }
      derivative = n * (x * value - previous) / (x * x - 1);
      const double step = value / derivative;
      x -= step;
      if (std::abs(step) < 1e-15)
        break;
    }
    rule.points[n - 1 - i](0) = x;
    rule.weights[n - 1 - i] = 2 / ((1 - x * x) * derivative * derivative);
  }
  return rule;
}

QuadratureRule2d gauss_square(int n)
{
  const QuadratureRule2d line = gauss_legendre_1d(n);
  QuadratureRule2d rule;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      rule.points.emplace_back(line.points[i](0), line.points[j](0));
      rule.weights.push_back(line.weights[i] * line.weights[j]);
    }
  return rule;
}

QuadratureRule2d gauss_triangle(int n)
{
  // Duffy map (u, v) in [0, 1]^2 -> (u (1 - v), v), Jacobian 1 - v: x^a y^b becomes
  // u^a (1 - v)^(a+1) v^b, integrated exactly by n Gauss points per direction if a + b <= 2n - 2.
  const QuadratureRule2d line = gauss_legendre_1d(n);
  QuadratureRule2d rule;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const double u = 0.5 * (1 + line.points[i](0));
      const double v = 0.5 * (1 + line.points[j](0));
      rule.points.emplace_back(u * (1 - v), v);
      // Weights 0.25 w_i w_j (1 - v) sum to the area 1/2; times 2 to sum to 1.
      rule.weights.push_back(0.5 * line.weights[i] * line.weights[j] * (1 - v));
    }
  return rule;
}

namespace
{
/// 4 x 4 Gauss on the reference square, shared by face_nodal_areas and dual_basis so that both
/// give the same D_j.
const QuadratureRule2d& face_rule()
{
  static const QuadratureRule2d rule = gauss_square(4);
  return rule;
}
} // namespace

Eigen::Vector4d face_nodal_areas(const QuadCoordinates& face)
{
  const QuadratureRule2d& rule = face_rule();
  Eigen::Vector4d areas = Eigen::Vector4d::Zero();
  for (size_t q = 0; q < rule.points.size(); ++q)
    areas += rule.weights[q] * surface_jacobian(face, rule.points[q]) * quad_shape_functions(rule.points[q]);
  return areas;
}

DualBasis dual_basis(const QuadCoordinates& slave)
{
  const QuadratureRule2d& rule = face_rule();
  Eigen::Matrix4d mass = Eigen::Matrix4d::Zero();
  DualBasis dual;
  for (size_t q = 0; q < rule.points.size(); ++q)
  {
    const Eigen::Vector4d shape = quad_shape_functions(rule.points[q]);
    const double weight = rule.weights[q] * surface_jacobian(slave, rule.points[q]);
    mass += weight * shape * shape.transpose();
    dual.nodal_area += weight * shape;
  }
  dual.coefficients = dual_coefficients(dual.nodal_area, mass);
  return dual;
}

Eigen::Vector4d dual_shape_functions(const DualBasis& dual, const Eigen::Vector2d& xi)
{
  return dual.coefficients * quad_shape_functions(xi);
}

bool strictly_convex_ccw(const std::vector<Eigen::Vector2d>& polygon)
{
  const double tolerance = 1e-12 * std::abs(polygon_area(polygon));
  const auto n = polygon.size();
  for (size_t k = 0; k < n; ++k)
  {
    const Eigen::Vector2d& a = polygon[k];
    const Eigen::Vector2d& b = polygon[(k + 1) % n];
    const Eigen::Vector2d& c = polygon[(k + 2) % n];
    if (!(cross_2d(b - a, c - b) > tolerance))
      return false;
  }
  return true;
}
double polygon_area(const std::vector<Eigen::Vector2d>& polygon)
{
  double twice_area = 0;
  for (size_t k = 0; k < polygon.size(); ++k)
    twice_area += cross_2d(polygon[k], polygon[(k + 1) % polygon.size()]);
  return 0.5 * twice_area;
}

std::vector<Eigen::Vector2d> clip_polygon(const std::vector<Eigen::Vector2d>& subject,
                                          const std::vector<Eigen::Vector2d>& clip)
{
  std::vector<Eigen::Vector2d> output = subject;
  std::vector<Eigen::Vector2d> input;
  for (size_t e = 0; e < clip.size() && !output.empty(); ++e)
  {
    const Eigen::Vector2d& start = clip[e];
    const Eigen::Vector2d edge = clip[(e + 1) % clip.size()] - start;
    // > 0 left of the edge, i.e. inside the counter-clockwise clip polygon.
    auto side = [&](const Eigen::Vector2d& p) { return cross_2d(edge, p - start); };
    input.swap(output);
    output.clear();
    for (size_t k = 0; k < input.size(); ++k)
    {
      const Eigen::Vector2d& current = input[k];
      const Eigen::Vector2d& previous = input[(k + input.size() - 1) % input.size()];
      const double side_current = side(current);
      const double side_previous = side(previous);
      const bool current_inside = side_current >= 0;
      const bool previous_inside = side_previous >= 0;
      if (current_inside != previous_inside)
      {
        const double t = side_previous / (side_previous - side_current);
        output.push_back(previous + t * (current - previous));
      }
      if (current_inside)
        output.push_back(current);
    }
  }
  if (output.size() < 3)
    output.clear();
  return output;
}

std::optional<Eigen::Vector2d> inverse_bilinear(const Eigen::Matrix<double, 4, 2>& corners,
                                                const Eigen::Vector2d& point)
{
  Eigen::Vector2d xi = Eigen::Vector2d::Zero();
  for (int iteration = 0; iteration < 30; ++iteration)
  {
    const Eigen::Vector2d residual = point - corners.transpose() * quad_shape_functions(xi);
    const Eigen::Matrix2d jacobian = corners.transpose() * bilinear_derivatives(xi);
    const double determinant = jacobian.determinant();
    if (!(std::abs(determinant) > 0) || !std::isfinite(determinant))
      return std::nullopt;
    const Eigen::Vector2d step = jacobian.inverse() * residual;
    if (!step.allFinite())
      return std::nullopt;
    xi += step;
    // Quadratic convergence: a step below 1e-14 leaves an error of order 1e-28 (round-off).
    if (step.lpNorm<Eigen::Infinity>() < 1e-14)
      return xi;
  }
  return std::nullopt;
}

std::optional<SegmentCoupling> integrate_segment(const QuadCoordinates& slave, const DualBasis& dual,
                                                 const QuadCoordinates& master, const SegmentOptions& options)
{
  static const QuadratureRule2d default_rule = gauss_triangle(SegmentOptions{}.triangle_points);
  const bool default_points = options.triangle_points == SegmentOptions{}.triangle_points;
  const QuadratureRule2d custom_rule = default_points ? QuadratureRule2d{} : gauss_triangle(options.triangle_points);
  const QuadratureRule2d& rule = default_points ? default_rule : custom_rule;
  const AuxiliaryPlane plane = auxiliary_plane(slave);
  if (!(-quad_normal(master, Eigen::Vector2d::Zero()).dot(plane.normal) >= options.min_facing))
    return std::nullopt;

  const Eigen::Matrix<double, 4, 2> slave_corners = plane.project(slave);
  const Eigen::Matrix<double, 4, 2> master_corners = plane.project(master);
  std::vector<Eigen::Vector2d> slave_polygon(4);
  std::vector<Eigen::Vector2d> master_polygon(4);
  for (int a = 0; a < 4; ++a)
  {
    slave_polygon[a] = slave_corners.row(a).transpose();
    // The master normal is opposite to n_0: reverse its corners to turn counter-clockwise.
    master_polygon[a] = master_corners.row(3 - a).transpose();
  }
  FETICON_CHECK(strictly_convex_ccw(slave_polygon),
                "mortar: a slave face is not convex in its auxiliary plane (corners "
                    << slave.row(0) << "; " << slave.row(1) << "; " << slave.row(2) << "; " << slave.row(3)
                    << "); check the mesh");
  if (!strictly_convex_ccw(master_polygon))
    return std::nullopt;

  const std::vector<Eigen::Vector2d> polygon = clip_polygon(master_polygon, slave_polygon);
  if (polygon.empty() || !(polygon_area(polygon) > options.min_area_fraction * polygon_area(slave_polygon)))
    return std::nullopt;

  SegmentCoupling segment;
  for_each_fan_point(polygon, rule, [&](const Eigen::Vector2d& point, double weight) {
    const std::optional<Eigen::Vector2d> xi_slave = inverse_bilinear(slave_corners, point);
    const std::optional<Eigen::Vector2d> xi_master = inverse_bilinear(master_corners, point);
    FETICON_CHECK(xi_slave && xi_master,
                  "mortar: inverse bilinear map failed at plane point " << point.transpose() << "; check the mesh");
    const double planar_jacobian =
        std::abs((slave_corners.transpose() * bilinear_derivatives(*xi_slave)).determinant());
    const double area = weight * surface_jacobian(slave, *xi_slave) / planar_jacobian;
    segment.coupling += area * dual_shape_functions(dual, *xi_slave) * quad_shape_functions(*xi_master).transpose();
    segment.area += area;
  });
  return segment;
}
} // namespace feticon::contact
