#include "contact/closest_point.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::contact
{
namespace
{
/// Tangents x_,xi, x_,eta and the mixed derivative x_,xi eta of the quad at xi.
struct QuadDerivatives
{
  Eigen::Vector3d d_xi;
  Eigen::Vector3d d_eta;
  Eigen::Vector3d d_xi_eta;
};

QuadDerivatives quad_derivatives(const QuadCoordinates& quad, const Eigen::Vector2d& xi)
{
  QuadDerivatives d{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  for (int a = 0; a < 4; ++a)
  {
    const double xa = quad_corners[a][0];
    const double ea = quad_corners[a][1];
    const Eigen::Vector3d corner = quad.row(a).transpose();
    d.d_xi += 0.25 * xa * (1 + ea * xi(1)) * corner;
    d.d_eta += 0.25 * ea * (1 + xa * xi(0)) * corner;
    d.d_xi_eta += 0.25 * xa * ea * corner;
  }
  return d;
}

} // namespace

Eigen::Vector4d quad_shape_functions(const Eigen::Vector2d& xi)
{
  Eigen::Vector4d n;
  for (int a = 0; a < 4; ++a)
    n(a) = 0.25 * (1 + quad_corners[a][0] * xi(0)) * (1 + quad_corners[a][1] * xi(1));
  return n;
}

Eigen::Vector3d quad_point(const QuadCoordinates& quad, const Eigen::Vector2d& xi)
{
  return quad.transpose() * quad_shape_functions(xi);
}

Eigen::Vector3d quad_normal(const QuadCoordinates& quad, const Eigen::Vector2d& xi)
{
  const QuadDerivatives d = quad_derivatives(quad, xi);
  const Eigen::Vector3d cross = d.d_xi.cross(d.d_eta);
  const double length = cross.norm();
  return length > 0 ? Eigen::Vector3d(cross / length) : Eigen::Vector3d::Zero();
}

QuadProjection project_to_quad(const QuadCoordinates& quad, const Eigen::Vector3d& point,
                               const ProjectionOptions& options)
{
  QuadProjection result;
  Eigen::Vector2d xi = Eigen::Vector2d::Zero();
  double previous_step = 0; // size of the previous full Newton step, 0 if none
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration)
  {
    const QuadDerivatives d = quad_derivatives(quad, xi);
    const Eigen::Vector3d distance = quad_point(quad, xi) - point;
    const Eigen::Vector2d residual(d.d_xi.dot(distance), d.d_eta.dot(distance));
    Eigen::Matrix2d metric;
    metric << d.d_xi.squaredNorm(), d.d_xi.dot(d.d_eta), d.d_xi.dot(d.d_eta), d.d_eta.squaredNorm();
    if (!(metric(0, 0) > 0 && metric.determinant() > 0))
      break; // degenerate quad: tangents parallel or zero
    Eigen::Matrix2d jacobian = metric;
    jacobian(0, 1) += d.d_xi_eta.dot(distance);
    jacobian(1, 0) = jacobian(0, 1);
    // Full Newton only where the distance Hessian is positive definite; otherwise Gauss-Newton.
    bool full_newton = jacobian(0, 0) > 0 && jacobian.determinant() > 0;
    if (!full_newton)
    {
      jacobian = metric;
      ++result.gauss_newton_steps;
    }
    Eigen::Vector2d step = -jacobian.inverse() * residual;
    const double step_size = step.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(step_size))
      break;
    if (step_size > max_projection_step)
    {
      step *= max_projection_step / step_size;
      full_newton = false;
    }
    xi += step;
    result.iterations = iteration;
    const double step_norm = step.norm();
    // Converged when this step is below the tolerance, or when quadratic convergence predicts
    // that the next one would be: |dxi_k+1| ~ C |dxi_k|^2 with C = |dxi_k| / |dxi_k-1|^2. The
    // estimate is used only for two consecutive full Newton steps already below sqrt(tolerance);
    // it saves the last step, which would only confirm convergence.
    const bool predicted = full_newton && previous_step > 0 && step_norm < std::sqrt(options.step_tolerance) &&
        step_norm / (previous_step * previous_step) * step_norm * step_norm < options.step_tolerance;
    if (step_norm < options.step_tolerance || predicted)
    {
      result.converged = true;
      break;
    }
    previous_step = full_newton ? step_norm : 0;
  }
  result.xi = xi;
  result.point = quad_point(quad, xi);
  result.normal = quad_normal(quad, xi);
  if (result.normal.squaredNorm() == 0)
    result.converged = false;
  result.gap = result.normal.dot(point - result.point);
  result.inside = std::abs(xi(0)) <= 1 + options.inside_tolerance && std::abs(xi(1)) <= 1 + options.inside_tolerance;
  return result;
}

double closest_on_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& point)
{
  const Eigen::Vector3d edge = b - a;
  const double length2 = edge.squaredNorm();
  if (length2 == 0)
    return 0;
  return std::clamp(edge.dot(point - a) / length2, 0.0, 1.0);
}
} // namespace feticon::contact
