#pragma once
/// @file The stopping test of the outer (modified Newton) loop, ALGORITHMS.md section 8: a
/// load step has converged when, after an outer iteration,
///
///   ||du|| <= eps_u ||u||,
///   ||t f_ext - f_int(u) - B'lambda|| <= eps_r max(||t f_ext||, ||f_int(u)||)  (the internal
///                            force is the scale where the load is a prescribed displacement),
///   and the set of active contact rows did not change;
///
/// or when the correction is round-off, ||du||_inf <= 1e-9 L (L the diagonal of the model's
/// bounding box): then a problem whose answer is near u = 0 converges, where u, the residual
/// and the multipliers are all round-off and the relative tests above compare noise with
/// noise. The displacement test alone stops a loop that still changes its contact set, or
/// one whose correction is small only because the QP was inexact; the residual test alone
/// cannot tell a converged loop from a stalled one.

#include <cstdint>
#include <set>

namespace feticon::nonlinear
{
struct OuterConvergence
{
  double displacement_tolerance = 0; ///< eps_u
  double residual_tolerance = 0;     ///< eps_r
  double length_scale = 1.0;            ///< L (m)

  /// @param du_norm, u_norm   ||du||, ||u|| (2-norms of the same distributed vectors)
  /// @param du_max            ||du||_inf
  /// @param residual          the relative residual above
  bool converged(double du_norm, double u_norm, double du_max, double residual,
                 const std::set<int32_t>& active, const std::set<int32_t>& previous_active) const
  {
    if (du_max <= 1e-9 * length_scale)
      return true;
    return du_norm <= displacement_tolerance * u_norm && residual <= residual_tolerance && active == previous_active;
  }
};
} // namespace feticon::nonlinear
