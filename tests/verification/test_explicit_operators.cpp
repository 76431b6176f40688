/// Explicit dual operators (decomposition/explicit_boundary_operators.hpp) against the implicit
/// ones on Hertz. Reference: the implicit solve of the same problem. The two apply the same
/// linear operators (F and B S B' restricted to the rows' boundary DOFs), so the iterates differ
/// by round-off only: the same MPRGP steps (issue 19: within 1 %) and the same peak pressure
/// and displacements to 1e-8 relative.

#include "common/error.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "problems/hertz.hpp"
#include "tests/support/feti_contact_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace feticon;

namespace
{
test::FetiContactRun run(fem::Kinematics kinematics, nonlinear::DualOperatorMode mode)
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 1;
  const fem::Problem problem = problems::hertz_problem(parameters);
  nonlinear::SolverSettings s;
  s.kinematics = kinematics;
  s.load_steps = kinematics == fem::Kinematics::linear ? 1 : 2;
  s.dual.preconditioner = dual::DualPreconditioner::dirichlet;
  s.dual_operator = mode;
  return test::run_feti_contact(problem, s);
}

/// Hertz at refinement 0.5 with large displacements in 2 load steps.
fem::Problem coarse_hertz()
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 0.5;
  return problems::hertz_problem(parameters);
}

/// Explicit operators with a search distance (1 mm) below the contact zone's growth, so that
/// contact rows leave the boundary the Dirichlet preconditioner started with.
nonlinear::SolverSettings growing_boundary_settings()
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::total_lagrangian;
  s.load_steps = 2;
  s.search_distance = 1e-3;
  s.dual_operator = nonlinear::DualOperatorMode::explicit_;
  return s;
}
} // namespace

TEST(ExplicitDualOperators, SameSolutionAsImplicit)
{
  for (auto kinematics : {fem::Kinematics::linear, fem::Kinematics::total_lagrangian})
  {
    const test::FetiContactRun implicit = run(kinematics, nonlinear::DualOperatorMode::implicit);
    const test::FetiContactRun explicit_ = run(kinematics, nonlinear::DualOperatorMode::explicit_);
    EXPECT_EQ(implicit.solution.dual_operator, "implicit");
    EXPECT_EQ(explicit_.solution.dual_operator, "explicit");
    const double du = (explicit_.solution.u - implicit.solution.u).norm() / implicit.solution.u.norm();
    std::printf("%s: MPRGP %d implicit, %d explicit; |du|/|u| = %.1e, peak %.10g / %.10g\n",
                kinematics == fem::Kinematics::linear ? "small" : "large", implicit.mprgp, explicit_.mprgp, du,
                implicit.peak, explicit_.peak);
    EXPECT_LE(std::abs(explicit_.mprgp - implicit.mprgp), 0.01 * implicit.mprgp);
    EXPECT_LT(du, 1e-8);
    EXPECT_NEAR(explicit_.peak, implicit.peak, 1e-8 * implicit.peak);
  }
}

TEST(ExplicitDualOperators, NeedTheDirichletPreconditioner)
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 0.5;
  const fem::Problem problem = problems::hertz_problem(parameters);
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.dual.preconditioner = dual::DualPreconditioner::none;
  s.dual_operator = nonlinear::DualOperatorMode::explicit_;
  TimerTable timers;
  EXPECT_THROW(nonlinear::solve_feti_contact(problem, s, timers), feticon::Error);
  s.dual_operator = nonlinear::DualOperatorMode::automatic; // falls back to implicit
  EXPECT_EQ(nonlinear::solve_feti_contact(problem, s, timers).dual_operator, "implicit");
}

// The Dirichlet preconditioner's boundary starts with the contact DOFs of the rows near contact
// at set-up. With a search distance of 1 mm on Hertz (large displacements, the cylinder
// approaches by more than that), later rows reach nodes beyond those: the boundary grows by
// the rows near contact at the current u, which the explicit blocks need (a row touching a
// DOF off their boundary is an error, FetiOperators::use_explicit), and the blocks of the
// subdomains whose boundary changed are formed again. Reference: the lumped
// preconditioner, which has no boundary, on the same rows: the same QP solutions, so the same
// peak pressure to the QP tolerance.
TEST(ExplicitDualOperators, ContactBeyondTheInitialReachWidensTheBoundary)
{
  const fem::Problem problem = coarse_hertz();
  nonlinear::SolverSettings s = growing_boundary_settings();
  double peak[2] = {0, 0};
  bool widened[2] = {false, false};
  const dual::DualPreconditioner kinds[2] = {dual::DualPreconditioner::dirichlet, dual::DualPreconditioner::lumped};
  for (int k = 0; k < 2; ++k)
  {
    s.dual.preconditioner = kinds[k];
    if (kinds[k] == dual::DualPreconditioner::lumped)
      s.dual_operator = nonlinear::DualOperatorMode::implicit;
    const test::FetiContactRun run = test::run_feti_contact(problem, s);
    ASSERT_TRUE(run.solution.converged);
    widened[k] = run.solution.schur_boundary_widened;
    peak[k] = run.peak;
  }
  std::printf("peak %.10g (Dirichlet, explicit) / %.10g (lumped)\n", peak[0], peak[1]);
  EXPECT_TRUE(widened[0]);
  EXPECT_FALSE(widened[1]);
  EXPECT_NEAR(peak[0], peak[1], 1e-6 * peak[1]);
}

// Reference: the uninterrupted run. The run of the test above whose Schur boundary grows in
// its first load step, restarted from the state after that step (the checkpoint's
// RestartState, in memory here), forms its operators on the grown boundary and repeats the
// uninterrupted run's second step: the same outer and MPRGP iteration counts, the same answer
// to round-off. Before the checkpoint carried the boundary, the restart formed the initial
// boundary's operators and grew it again within step 2 (here to the same counters, since it
// grows before the first QP of the step, but with one growth more than the uninterrupted run).
TEST(ExplicitDualOperators, RestartKeepsTheGrownBoundary)
{
  const fem::Problem problem = coarse_hertz();
  nonlinear::SolverSettings s = growing_boundary_settings();
  s.dual.preconditioner = dual::DualPreconditioner::dirichlet;
  nonlinear::ContactSolution after_step_1;
  TimerTable timers;
  const nonlinear::ContactSolution full =
      nonlinear::solve_feti_contact(problem, s, timers, [&](int step, const nonlinear::ContactSolution& so_far) {
        if (step == 1)
          after_step_1 = so_far;
      });
  ASSERT_TRUE(full.converged) << full.reason;
  ASSERT_EQ(after_step_1.restart.completed_steps, 1);
  ASSERT_FALSE(after_step_1.restart.schur_boundary.empty()) << "the boundary did not grow in step 1";

  const nonlinear::ContactSolution restarted = nonlinear::solve_feti_contact(problem, s, timers, {}, &after_step_1);
  ASSERT_TRUE(restarted.converged) << restarted.reason;
  ASSERT_EQ(restarted.history.size(), full.history.size());
  for (size_t k = 0; k < full.history.size(); ++k)
  {
    EXPECT_EQ(restarted.history[k].load_step, full.history[k].load_step);
    EXPECT_EQ(restarted.history[k].qp.iterations, full.history[k].qp.iterations) << "outer iteration " << k;
  }
  EXPECT_EQ(restarted.restart.schur_boundary, full.restart.schur_boundary);
  // It grows in step 2 only where the uninterrupted run's grew there too.
  EXPECT_EQ(restarted.schur_boundary_growths, full.schur_boundary_growths - after_step_1.schur_boundary_growths);
  EXPECT_LT((restarted.u - full.u).norm(), 1e-10 * full.u.norm());
}
