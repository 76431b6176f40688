/// Inexact outer iterations (SolverSettings::forcing): the large-displacement Hertz problem
/// solved with forcing QP tolerances reaches the answer of the same loop with every QP solved
/// to qp.rtol, in fewer MPRGP steps. Reference: that exact-QP run (an independent check of
/// the large-displacement answer against the TL primal penalty is in docs/contact.md).
/// Tolerance: both loops stop at |du|/|u| <= 1e-6 and converge linearly at a rate of about
/// 0.04, so each is within about 1e-7 of the limit; QP errors of the last forced QP are
/// below 0.001 |du_(k-1)|. 1e-5 on the displacement and the peak pressure is a margin of 10
/// over the stopping tolerance.

#include "problems/hertz.hpp"
#include "tests/support/feti_contact_run.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace feticon;

namespace
{
test::FetiContactRun run(const fem::Problem& problem, double forcing)
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = 2;
  s.dual.preconditioner = dual::DualPreconditioner::none;
  s.forcing = forcing;
  return test::run_feti_contact(problem, s);
}
} // namespace

TEST(InexactOuterIterations, ReachTheExactQpAnswerInFewerMprgpSteps)
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 0.75;
  const fem::Problem problem = problems::hertz_problem(parameters);
  const test::FetiContactRun exact = run(problem, 0.0);
  const test::FetiContactRun forced = run(problem, 0.001);
  std::printf("MPRGP steps: exact QPs %d, forcing 0.001 %d; p_peak %.6e / %.6e Pa\n", exact.mprgp, forced.mprgp,
              exact.peak, forced.peak);
  EXPECT_LE((forced.solution.u - exact.solution.u).norm(), 1e-5 * exact.solution.u.norm());
  EXPECT_NEAR(forced.peak, exact.peak, 1e-5 * exact.peak);
  EXPECT_LT(forced.mprgp, exact.mprgp);
}
