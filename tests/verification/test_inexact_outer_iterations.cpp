/// Inexact outer iterations (SolverSettings::forcing): the large-displacement Hertz problem
/// solved with forcing QP tolerances reaches the answer of the same loop with every QP solved
/// to qp.rtol, in fewer MPRGP steps. Reference: that exact-QP run (an independent check of
/// the large-displacement answer against the TL primal penalty is in docs/contact.md).
/// Tolerance: both loops stop at |du|/|u| <= 1e-6 and converge linearly at a rate of about
/// 0.04, so each is within about 1e-7 of the limit; QP errors of the last forced QP are
/// below 0.001 |du_(k-1)|. 1e-5 on the displacement and the peak pressure is a margin of 10
/// over the stopping tolerance.

#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "problems/hertz.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
struct LargeRun
{
  nonlinear::ContactSolution solution;
  double p_peak = 0;
  int mprgp = 0;
};

LargeRun run(const fem::Problem& problem, double forcing)
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = 2;
  s.dual.preconditioner = dual::DualPreconditioner::none;
  s.forcing = forcing;
  TimerTable timers;
  LargeRun out;
  out.solution = nonlinear::solve_feti_contact(problem, s, timers);
  EXPECT_TRUE(out.solution.converged) << out.solution.reason;
  double peak = 0;
  for (const auto& p : nonlinear::slave_pressure_by_x(problem, out.solution, s.kinematics))
    peak = std::max(peak, p.pressure);
  out.p_peak = peak;
  for (const auto& it : out.solution.history)
    out.mprgp += it.qp.iterations;
  return out;
}
} // namespace

TEST(InexactOuterIterations, ReachTheExactQpAnswerInFewerMprgpSteps)
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 0.75;
  const fem::Problem problem = problems::hertz_problem(parameters);
  const LargeRun exact = run(problem, 0.0);
  const LargeRun forced = run(problem, 0.001);
  std::printf("MPRGP steps: exact QPs %d, forcing 0.001 %d; p_peak %.6e / %.6e Pa\n", exact.mprgp,
              forced.mprgp, exact.p_peak, forced.p_peak);
  EXPECT_LE((forced.solution.u - exact.solution.u).norm(), 1e-5 * exact.solution.u.norm());
  EXPECT_NEAR(forced.p_peak, exact.p_peak, 1e-5 * exact.p_peak);
  EXPECT_LT(forced.mprgp, exact.mprgp);
}
