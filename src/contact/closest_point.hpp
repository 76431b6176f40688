#pragma once
/// @file Closest-point projection of a point onto a bilinear quadrilateral (ALGORITHMS.md
/// section 4).
///
/// The quad is x(xi) = sum_a N_a(xi) x_a with xi = (xi, eta) in [-1, 1]^2,
/// N_a = 1/4 (1 + xi_a xi)(1 + eta_a eta), and the corners in the order of a mesh::Face:
///   a = 0 (-1,-1), 1 (+1,-1), 2 (+1,+1), 3 (-1,+1).
/// Because a boundary face is ordered counter-clockwise seen from outside its body, the normal
/// n = x_,xi x x_,eta / |x_,xi x x_,eta| points out of the body that owns the face (the master
/// body). The gap of the point x_s is g = n . (x_s - x(xi_bar)): g >= 0 open, g < 0 penetration.
///
/// Newton solves r_alpha = x_,alpha . (x(xi) - x_s) = 0 with the Jacobian
/// J_ab = x_,a . x_,b + x_,ab . (x - x_s); for a bilinear quad only x_,xi eta is nonzero. When J
/// is not positive definite (a point far on the concave side of a warped quad) the curvature
/// term is dropped (Gauss-Newton), which is a descent direction for the squared distance.
/// Newton stops when |dxi| < step_tolerance, or one step earlier when two consecutive full Newton
/// steps predict by quadratic convergence that the next step would be below it
/// (|dxi_k+1| ~ |dxi_k|^3 / |dxi_k-1|^2, used only once |dxi_k| < sqrt(step_tolerance)).
///
/// Usage:
///   const QuadCoordinates quad = ...;  // rows = corner coordinates (m)
///   const QuadProjection p = project_to_quad(quad, point);
///   if (p.accepted()) use(p.xi, p.normal, p.gap);

#include <array>

#include <Eigen/Dense>

namespace feticon::contact
{
/// Corner coordinates of a quad, one row per corner in mesh::Face order (m).
using QuadCoordinates = Eigen::Matrix<double, 4, 3>;

/// Reference coordinates (xi_a, eta_a) of the quad corners.
inline constexpr std::array<std::array<double, 2>, 4> quad_corners = {{
    {-1, -1},
    {1, -1},
    {1, 1},
    {-1, 1},
}};

/// A Newton step of a projection is capped at the width of the reference face so that a point far
/// outside the face cannot throw the iterate to infinity; accepted projections never reach the cap.
inline constexpr double max_projection_step = 2.0;

/// Reference coordinates of corner a as a vector.
inline Eigen::Vector2d quad_corner(int a) { return {quad_corners[a][0], quad_corners[a][1]}; }

/// Bilinear shape functions N_a(xi), a = 0..3; they sum to 1.
Eigen::Vector4d quad_shape_functions(const Eigen::Vector2d& xi);

/// Point x(xi) of the quad (m).
Eigen::Vector3d quad_point(const QuadCoordinates& quad, const Eigen::Vector2d& xi);

/// Unit normal x_,xi x x_,eta / |.| at xi; zero vector if the quad is degenerate there.
Eigen::Vector3d quad_normal(const QuadCoordinates& quad, const Eigen::Vector2d& xi);

/// Stopping and acceptance parameters of project_to_quad.
struct ProjectionOptions
{
  /// Maximum number of Newton (or Gauss-Newton) steps.
  int max_iterations = 20;
  /// Stop when the step |dxi| (reference coordinates, dimensionless) is below this, or is
  /// predicted to be at the next step (see file comment).
  double step_tolerance = 1e-12;
  /// The projection is inside when |xi|, |eta| <= 1 + inside_tolerance.
  double inside_tolerance = 1e-6;
};

/// Result of project_to_quad. Non-convergence is a result, not an exception.
struct QuadProjection
{
  /// Reference coordinates of the closest point (may lie outside [-1, 1]^2).
  Eigen::Vector2d xi{0, 0};
  /// Closest point x(xi) (m).
  Eigen::Vector3d point{0, 0, 0};
  /// Unit normal at xi, outward of the body owning the quad (see file comment).
  Eigen::Vector3d normal{0, 0, 0};
  /// Signed normal gap n . (x_s - x(xi)) (m).
  double gap = 0;
  /// Newton steps taken, of which gauss_newton_steps dropped the curvature term.
  int iterations = 0;
  int gauss_newton_steps = 0;
  /// Whether the step tolerance was met (false also for a degenerate quad).
  bool converged = false;
  /// Whether |xi|, |eta| <= 1 + inside_tolerance.
  bool inside = false;

  /// A converged projection inside the quad: the only kind build_contact_constraints uses as is.
  bool accepted() const { return converged && inside; }
};

/// @brief Closest point on the bilinear quad `quad` to `point`, Newton from xi = (0, 0).
/// @param[in] quad    corner coordinates (m), mesh::Face order
/// @param[in] point   the point x_s (m), e.g. a slave node in the current configuration
/// @param[in] options stopping and acceptance parameters
QuadProjection project_to_quad(const QuadCoordinates& quad, const Eigen::Vector3d& point,
                               const ProjectionOptions& options = {});

/// Closest point on the straight segment [a, b]: the parameter t in [0, 1] of a + t (b - a).
double closest_on_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& point);
} // namespace feticon::contact
