/// The stopping test of the outer loop (nonlinear/outer_convergence.hpp, ALGORITHMS.md
/// section 8) on problems whose answer is known exactly.
///
/// Reference of the first: two unloaded blocks touching with no gap, the upper one held at its
/// top face, stay where they are (u = 0). The outer loop's corrections are round-off, as large
/// relative to u as u itself, so a test on ||du|| / ||u|| alone never passes; the round-off
/// floor of the test (||du||_inf <= 1e-9 L) must end each load step at once.

#include "contact_test_problems.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
nonlinear::SolverSettings large_displacements()
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = 2;
  s.dual.preconditioner = dual::DualPreconditioner::none;
  s.subdomains = 4;
  s.max_outer_iterations = 8;
  return s;
}
} // namespace

TEST(OuterConvergence, UnloadedBodiesStayPutAndConverge)
{
  fem::Problem problem = test::pressed_blocks(2, 3, 0.0, 0.0);
  problem.tractions.clear();
  problem.dirichlet.push_back({"upper_zmax", {std::nullopt, std::nullopt, 0.0}});
  TimerTable timers;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, large_displacements(), timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  EXPECT_LT(solution.u.cwiseAbs().maxCoeff(), 1e-12);
  for (const auto& step : solution.steps)
    EXPECT_LE(step.outer_iterations, 2);
}

// Reference: uniaxial stress, contact pressure p on the whole interface (contact_test_problems.hpp);
// with large displacements the total force still equals the load p * 1 m^2. The loop must not
// stop before the residual test holds: the last residual is at most eps_r.
TEST(OuterConvergence, StopsOnlyWhenTheResidualIsSmall)
{
  const double p = 2e8; // 0.1 % strain: a few outer iterations
  const fem::Problem problem = test::pressed_blocks(2, 3, 0.0, p);
  nonlinear::SolverSettings s = large_displacements();
  s.displacement_tolerance = 1e-2; // loose: the residual test decides
  s.residual_tolerance = 1e-8;
  TimerTable timers;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, s, timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  EXPECT_LE(solution.history.back().residual_norm, s.residual_tolerance);
  double force = 0;
  for (la::Index i = 0; i < solution.contact_lambda.size(); ++i)
    force += solution.contact_lambda(i) / solution.constraints.row_norm[i];
  EXPECT_NEAR(force, p, 1e-5 * p);
}
