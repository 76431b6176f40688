#pragma once
/// @file The result of an iterative QP or linear solve (MFEM GetConverged(), PETSc
/// KSPConvergedReason, PERMON QPSViewConvergence).
///
/// Non-convergence is a result, not an exception: solvers fill `converged = false` and say
/// why in `reason`; only invalid input throws feticon::Error.

#include <cstdint>
#include <string>
#include <vector>

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
  /// All its Ritz values (at most 500 steps' worth), ascending, copies merged (a value within
  /// a relative 1e-3 of the last one kept: finite-precision Lanczos repeats a converged
  /// eigenvalue, a "ghost"). The extremes converge first; a value inside the spectrum need
  /// not be an eigenvalue. The outliers above the bulk are what a richer coarse space or
  /// preconditioner would have to take out.
  std::vector<double> distinct;
};

/// The work of QP solves: of one solve, or summed (+=) over SMALBE-M's inner solves, over
/// the QPs of an outer loop, or over a run. The one type every layer reports and sums, so a
/// counter added here reaches summary.json through one writer (app/qp_counters_json.hpp).
struct QpCounters
{
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
  /// SMALBE-M outer iterations (updates of its multiplier; 1 for a dual penalty solve).
  int outer_iterations = 0;
  /// SMALBE-M's raises of rho.
  int rho_updates = 0;
  /// SMALBE-M's feasibility corrections on the face that ended the solve (Smalbe::solve).
  int feasibility_corrections = 0;
  /// Applications of the (dual) operator and of the preconditioner, as counted and timed by
  /// their callers (0 where nobody times them), and their wall time (s).
  int64_t operator_applications = 0;
  double operator_seconds = 0;
  int64_t preconditioner_applications = 0;
  double preconditioner_seconds = 0;
  /// Wall-clock time of the solve(s).
  double seconds = 0.0;
  /// Spectrum estimate from the longest run of CG steps (of all those summed).
  RitzValues ritz;
  /// The same from a long CG run on the face of a QP's solution (dual::DualPenaltyOptions::
  /// spectrum_steps), of the last QP that measured it; all 0 when none did.
  RitzValues solution_face;
  /// Steps of that run until ||r|| <= (the QP's rtol) ||r_0|| first held: what preconditioned
  /// CG needs on the solution's face, the active set known in advance (0 when not measured).
  int solution_face_steps_to_rtol = 0;

  /// Sums the counters and times; keeps the Ritz values of the longer CG run.
  QpCounters& operator+=(const QpCounters& other)
  {
    iterations += other.iterations;
    cg_steps += other.cg_steps;
    expansion_steps += other.expansion_steps;
    proportioning_steps += other.proportioning_steps;
    expansion_fallbacks += other.expansion_fallbacks;
    hessian_multiplications += other.hessian_multiplications;
    outer_iterations += other.outer_iterations;
    rho_updates += other.rho_updates;
    feasibility_corrections += other.feasibility_corrections;
    operator_applications += other.operator_applications;
    operator_seconds += other.operator_seconds;
    preconditioner_applications += other.preconditioner_applications;
    preconditioner_seconds += other.preconditioner_seconds;
    seconds += other.seconds;
    if (other.ritz.cg_steps > ritz.cg_steps)
      ritz = other.ritz;
    if (other.solution_face.cg_steps > 0)
    {
      solution_face = other.solution_face;
      solution_face_steps_to_rtol = other.solution_face_steps_to_rtol;
    }
    return *this;
  }
};

/// Counters and final state of one solve; the meaning of each counter is fixed by the
/// solver that fills it (see Mprgp and conjugate_gradient).
struct QpReport : QpCounters
{
  /// True when the stopping test was met.
  bool converged = false;
  /// Human-readable why: the test that was met, or what stopped the solve.
  std::string reason;
  /// ||g_P|| for MPRGP, ||P r|| for CG, at the returned iterate.
  double projected_gradient_norm = 0.0;
  /// 1/2 x'Ax - b'x at the returned iterate.
  double cost = 0.0;
};
} // namespace feticon::qp
