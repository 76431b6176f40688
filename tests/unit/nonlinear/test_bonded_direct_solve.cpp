/// The bonded direct solve (the benchmarks' lower bound) on a coarse Hertz mesh. Independent
/// references: the primal penalty solver, whose converged linear solve is the same system with
/// its own active set, and the equilibrium of the cylinder, which is held vertically by the
/// bonded springs alone. Tolerances: both solves are one CHOLMOD factorization of a system with
/// condition number about eps_n / lambda_min(K); 1e-8 leaves several digits above round-off.

#include "common/error.hpp"
#include "nonlinear/bonded_direct_solve.hpp"
#include "nonlinear/primal_penalty_solver.hpp"
#include "problems/hertz.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
fem::Problem coarse_hertz()
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 0.5;
  return problems::hertz_problem(parameters);
}

/// The settings these tests were written for: small displacements, no dual preconditioner.
nonlinear::SolverSettings small_displacements()
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.dual.preconditioner = dual::DualPreconditioner::none;
  return s;
}

/// Vertical force of the bonded springs on the cylinder (N): lambda_i / |b_i| along the
/// row's normal, summed over the slave nodes.
double spring_force_y(const nonlinear::BondedSolve& solve)
{
  const la::Vector force = contact::slave_normal_forces(solve.constraints, solve.contact_lambda);
  double sum = 0;
  for (la::Index i = 0; i < force.size(); ++i)
    sum += force(i) * solve.constraints.normal[i].y();
  return sum;
}
} // namespace

TEST(BondedDirectSolve, EqualsPrimalPenaltyWithItsActiveSetAndCarriesTheLoad)
{
  const fem::Problem problem = coarse_hertz();
  nonlinear::SolverSettings settings = small_displacements();
  settings.method = nonlinear::ContactMethod::primal_penalty;
  TimerTable timers;
  const nonlinear::ContactSolution penalty = nonlinear::solve_primal_penalty(problem, settings, timers);
  ASSERT_TRUE(penalty.converged) << penalty.reason;
  const std::vector<int32_t> active = nonlinear::active_slave_nodes(penalty);
  // A proper subset: the test is about bonding some rows and not the others.
  ASSERT_GT(active.size(), 2u);
  ASSERT_LT(static_cast<int64_t>(active.size()), penalty.constraints.n_rows());

  const nonlinear::BondedSolve bonded = nonlinear::bonded_direct_solve(problem, settings, active);
  EXPECT_EQ(bonded.n_bonded, static_cast<int64_t>(active.size()));
  EXPECT_DOUBLE_EQ(bonded.penalty, penalty.penalty);
  EXPECT_GT(bonded.factor_nonzeros, 0);
  EXPECT_LE((bonded.u - penalty.u).norm(), 1e-8 * penalty.u.norm());
  EXPECT_LE((bonded.contact_lambda - penalty.contact_lambda).norm(), 1e-8 * penalty.contact_lambda.norm());

  const double applied = -problem.external_force()(Eigen::seqN(1, problem.mesh.n_nodes(), 3)).sum();
  ASSERT_GT(applied, 0);
  EXPECT_NEAR(spring_force_y(bonded), applied, 1e-8 * applied);
}

TEST(BondedDirectSolve, BondingEverySlaveNodeStillCarriesTheLoad)
{
  // Also the rows with an open gap: a system no penalty iterate solves, checked by
  // equilibrium alone.
  const fem::Problem problem = coarse_hertz();
  const nonlinear::SolverSettings settings = small_displacements();
  contact::ContactOptions options;
  options.formulation = settings.interaction(problem.contacts[0]).formulation;
  const contact::ContactConstraints rows = contact::build_contact_constraints(
      problem.mesh, {}, {problem.contacts[0].slave, problem.contacts[0].master}, options);
  const nonlinear::BondedSolve bonded = nonlinear::bonded_direct_solve(problem, settings, rows.slave_node);
  EXPECT_EQ(bonded.n_bonded, rows.n_rows());
  const double applied = -problem.external_force()(Eigen::seqN(1, problem.mesh.n_nodes(), 3)).sum();
  // Bonded open gaps pull and push: the spring forces sum to about 50 times the load and
  // cancel, so the round-off of the sum scales with the sum of their magnitudes.
  const la::Vector force = contact::slave_normal_forces(bonded.constraints, bonded.contact_lambda);
  EXPECT_NEAR(spring_force_y(bonded), applied, 1e-8 * force.cwiseAbs().sum());
}

TEST(BondedDirectSolve, RejectsAFloatingCylinderAndANodeWithoutARow)
{
  const fem::Problem problem = coarse_hertz();
  const nonlinear::SolverSettings settings = small_displacements();
  EXPECT_THROW(nonlinear::bonded_direct_solve(problem, settings, {}), feticon::Error);
  // A node of the loaded top face of the cylinder, far from the contact zone.
  const int32_t far_node = problem.mesh.node_set("load").front();
  EXPECT_THROW(nonlinear::bonded_direct_solve(problem, settings, {far_node}), feticon::Error);
}
