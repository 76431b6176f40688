/// The (B B')^{-1} scaling of the FETI preconditioner on contact rows (dual/constraint_scaling.hpp).

#include "contact_test_problems.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace feticon;

namespace
{
nonlinear::ContactSolution solve_blocks(bool constraint_scaling, int& mprgp_steps)
{
  // Non-matching meshes: each mortar row shares master nodes with its neighbours.
  const fem::Problem problem = test::pressed_blocks(6, 5, 0.0, 1e8);
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.subdomains = 8;
  s.dual.preconditioner = dual::DualPreconditioner::dirichlet;
  s.dual.constraint_scaling = constraint_scaling;
  TimerTable timers;
  nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, s, timers);
  EXPECT_TRUE(solution.converged) << solution.reason;
  mprgp_steps = 0;
  for (const auto& it : solution.history)
    mprgp_steps += it.qp.iterations;
  return solution;
}
} // namespace

// Reference: the solve without the scaling. A preconditioner changes MPRGP's path, not the
// QP's solution: displacements agree to the QP tolerance (1e-8 on the dual gradient, 1e-6
// asserted on u). With Y = (B B')^{-1} the preconditioned operator's smallest eigenvalue on
// the contact rows returns to 1 (docs/distributed.md), so MPRGP needs fewer steps.
TEST(ConstraintScaling, SameContactSolutionInFewerStepsOnNonMatchingMeshes)
{
  int plain_steps = 0, scaled_steps = 0;
  const nonlinear::ContactSolution plain = solve_blocks(false, plain_steps);
  const nonlinear::ContactSolution scaled = solve_blocks(true, scaled_steps);
  const double difference = (scaled.u - plain.u).norm() / plain.u.norm();
  std::printf("MPRGP steps: B S B' %d, (BB')^-1 B S B' (BB')^-1 %d; |u_Y - u|/|u| = %.1e\n", plain_steps, scaled_steps,
              difference);
  EXPECT_LT(difference, 1e-6);
  EXPECT_LT(scaled_steps, plain_steps);
}
