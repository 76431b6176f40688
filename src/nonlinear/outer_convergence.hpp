#pragma once
/// @file The stopping test of the outer (modified Newton) loop, ALGORITHMS.md section 8: a
/// load step has converged when, after an outer iteration, all three clauses hold:
///
///   the displacement: ||du|| <= eps_u ||u||, or ||du||_inf <= 1e-9 L (L the diagonal of the
///                     model's bounding box: a correction at round-off; for an answer near
///                     u = 0 the relative test compares noise with noise);
///   the residual:     ||t f_ext - f_int(u) - B'lambda|| <= eps_r max(||t f_ext||, ||f_int(u)||)
///                     (the internal force is the scale where the load is a prescribed
///                     displacement);
///   the contact set:  the set of active contact rows did not change.
///
/// The displacement test alone stops a loop that still changes its contact set, or one whose
/// correction is small only because the QP was inexact; the residual test alone cannot tell a
/// converged loop from a stalled one. There is no shortcut past the residual: when the
/// correction is round-off and the contact set stays, another iteration repeats this one, and
/// a residual still above eps_r is a floor (the QP's accuracy, round-off of the forces) that
/// the loop cannot go below. The step then ends at that floor, and the run says so, unless the
/// residual still at least halved since the outer iteration before: a modified Newton loop on
/// K_0 contracts linearly, and its corrections fall below 1e-9 L while the residual still falls
/// (a plastic bar pulled to 1.5 times its length with newton.stiffness = initial: the residual
/// 2.1e-5, 5.3e-6, 1.5e-6 at corrections of 2e-9 L, which the floor ended above 1e-6; a floor
/// left by the QP's accuracy does not halve from one iteration to the next).

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

namespace feticon::nonlinear
{
enum class OuterVerdict
{
  iterate,   ///< another outer iteration
  converged, ///< all three clauses hold
  floor      ///< nothing left to change (round-off correction, same contact set), residual > eps_r
};

struct OuterConvergence
{
  double displacement_tolerance = 0; ///< eps_u
  double residual_tolerance = 0;     ///< eps_r
  double length_scale = 1.0;         ///< L (m)

  /// A displacement correction this small (infinity norm) is round-off: 1e-9 L.
  double roundoff_displacement() const { return 1e-9 * length_scale; }

  /// @param du_norm, u_norm   ||du||, ||u|| (2-norms of the same distributed vectors)
  /// @param du_max            ||du||_inf
  /// @param residual          the relative residual above
  /// @param previous_residual the residual of the outer iteration before in the load step
  ///                          (infinity at its first: no trend to read)
  OuterVerdict verdict(double du_norm, double u_norm, double du_max, double residual, const std::set<int64_t>& active,
                       const std::set<int64_t>& previous_active,
                       double previous_residual = std::numeric_limits<double>::infinity()) const
  {
    const bool roundoff = du_max <= roundoff_displacement();
    const bool small_change = du_norm <= displacement_tolerance * u_norm || roundoff;
    const bool same_set = active == previous_active;
    if (small_change && same_set && residual <= residual_tolerance)
      return OuterVerdict::converged;
    const bool still_falling = std::isfinite(previous_residual) && residual <= 0.5 * previous_residual;
    if (roundoff && same_set && !still_falling)
      return OuterVerdict::floor;
    return OuterVerdict::iterate;
  }
};
} // namespace feticon::nonlinear
