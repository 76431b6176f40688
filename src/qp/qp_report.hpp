#pragma once
/// @file The result of an iterative QP or linear solve (MFEM GetConverged(), PETSc
/// KSPConvergedReason, PERMON QPSViewConvergence).
///
/// Non-convergence is a result, not an exception: solvers fill `converged = false` and say
/// why in `reason`; only invalid input throws feticon::Error.

#include <string>

namespace feticon::qp
{
/// Extreme Ritz values of the operator (times the preconditioner, if any) on the face of
/// the longest run of consecutive CG steps, from that run's CG coefficients (the Lanczos
/// tridiagonal, as PETSc's -ksp_monitor_singular_value). They bound the spectrum from
/// inside and approach its ends as the run grows; max / min estimates the condition number
/// that governs the CG phase. All 0 when no run had two steps.
struct RitzValues
{
  double min = 0.0;
  double max = 0.0;
  /// CG steps of that run.
  int cg_steps = 0;
};

/// Counters and final state of one solve; the meaning of each counter is fixed by the
/// solver that fills it (see Mprgp and conjugate_gradient).
struct QpReport
{
  /// True when the stopping test was met.
  bool converged = false;
  /// Human-readable why: the test that was met, or what stopped the solve.
  std::string reason;
  /// Steps taken (for MPRGP: CG + expansion + proportioning steps).
  int iterations = 0;
  /// MPRGP conjugate gradient steps (for plain CG: all iterations).
  int cg_steps = 0;
  /// MPRGP expansion steps (feasible half step + gradient projection).
  int expansion_steps = 0;
  /// MPRGP proportioning steps (release of active components along the chopped gradient).
  int proportioning_steps = 0;
  /// MPRGP projected-CG expansions that increased f and were replaced by a standard one.
  int expansion_fallbacks = 0;
  /// All applications of the operator, including start-up and periodic gradient refreshes.
  int hessian_multiplications = 0;
  /// ||g_P|| for MPRGP, ||P r|| for CG, at the returned iterate.
  double projected_gradient_norm = 0.0;
  /// 1/2 x'Ax - b'x at the returned iterate.
  double cost = 0.0;
  /// Wall-clock time of the solve.
  double seconds = 0.0;
  /// Spectrum estimate from the longest run of CG steps.
  RitzValues ritz;
};
} // namespace feticon::qp
