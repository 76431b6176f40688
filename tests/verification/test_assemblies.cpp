/// Assemblies (issue 63): several contact pairs with a body slave in one and master in another,
/// and models without any contact pair, through the FETI contact solver.

#include "stacked_bodies.hpp"

#include "fem/stress.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

using namespace feticon;

namespace
{
constexpr double young = test::stack_young;

nonlinear::SolverSettings exact_settings(fem::Kinematics kinematics)
{
  nonlinear::SolverSettings s;
  s.kinematics = kinematics;
  s.dual.rtol = 1e-10;
  s.dual.force_rtol = 0; // qp.rtol alone: the uniform state to round-off
  // Modified Newton contracts about 15-fold an iteration on the 2 % strain of the large
  // displacement case: 1e-8 ends it with the answer far inside the tests' 1e-6.
  s.displacement_tolerance = 1e-8;
  s.residual_tolerance = 1e-8;
  s.subdomains = 6;
  return s;
}

/// The largest |u_z(node) - expected(z)| over the mesh, relative to the largest |expected|.
double settlement_error(const fem::Problem& p, const la::Vector& u, const std::function<double(double)>& expected)
{
  double error = 0, scale = 0;
  for (int32_t n = 0; n < p.mesh.n_nodes(); ++n)
  {
    const double z = p.mesh.nodes(n, 2);
    error = std::max(error, std::abs(u(3 * n + 2) - expected(z)));
    scale = std::max(scale, std::abs(expected(z)));
  }
  return error / scale;
}
} // namespace

// Reference: the exact solution is uniaxial stress sigma_zz = -p in every body (it lies in the
// FE space, and dual mortar rows transfer it across non-matching faces: the contact patch
// test), so u_z = -p z / E and the top settles by p H / E with H = 3. Each pair carries the
// load p A = p. Tolerances 1e-6 (issue 63's acceptance), far above qp.rtol = 1e-10.
TEST(Assemblies, ThreeBodyStackWithTwoPairsIsUniaxialStress)
{
  const double p = 1e8;
  const fem::Problem problem = test::stacked_cubes({3, 4, 2}, -p);
  ASSERT_EQ(problem.contacts.size(), 2u);
  TimerTable timers;
  const nonlinear::ContactSolution solution =
      nonlinear::solve_feti_contact(problem, exact_settings(fem::Kinematics::linear), timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  const double error = settlement_error(problem, solution.u, [&](double z) { return -p * z / young; });
  double stress_error = 0;
  for (const auto& s : fem::cell_cauchy_stresses(problem.mesh, solution.u, problem.materials, fem::Kinematics::linear))
  {
    Eigen::Matrix<double, 6, 1> expected = Eigen::Matrix<double, 6, 1>::Zero();
    expected(2) = -p;
    stress_error = std::max(stress_error, (s - expected).cwiseAbs().maxCoeff() / p);
  }
  std::printf("three-body stack: |u_z - (-p z / E)|_max / (p H / E) = %.2e, max stress error / p = %.2e, "
              "%zu outer iterations\n",
              error, stress_error, solution.history.size());
  EXPECT_LT(error, 1e-6);
  EXPECT_LT(stress_error, 1e-6);
  for (int32_t pair = 0; pair < 2; ++pair)
  {
    EXPECT_NEAR(nonlinear::total_normal_force(solution, pair), p, 1e-6 * p) << "pair " << pair;
    for (const nonlinear::PressureSample& s :
         nonlinear::slave_pressure_by_x(problem, solution, fem::Kinematics::linear, {}, pair))
    {
      EXPECT_EQ(s.pair, pair);
      EXPECT_NEAR(s.pressure, p, 1e-6 * p) << "pair " << pair << " at (" << s.x << ", " << s.y << ")";
    }
  }
  // The middle body is master of pair 0 and slave of pair 1: its rows are told apart by pair.
  std::set<int64_t> keys;
  for (int64_t i = 0; i < solution.constraints.n_rows(); ++i)
    keys.insert(solution.constraints.key(i));
  EXPECT_EQ(static_cast<int64_t>(keys.size()), solution.constraints.n_rows());
}

// Reference: as above; the pairs' order and the pair ids of the rows do not change the answer.
// Pair 1 node-to-segment on matching faces (4 x 4 on 4 x 4) passes the patch test too.
TEST(Assemblies, PairsWithTheirOwnFormulationGiveTheSameStack)
{
  const double p = 1e8;
  fem::Problem problem = test::stacked_cubes({3, 4, 4}, -p);
  problem.contacts[1].interaction.formulation = fem::ContactFormulation::node_to_segment;
  TimerTable timers;
  const nonlinear::ContactSolution solution =
      nonlinear::solve_feti_contact(problem, exact_settings(fem::Kinematics::linear), timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  EXPECT_LT(settlement_error(problem, solution.u, [&](double z) { return -p * z / young; }), 1e-6);
  EXPECT_NEAR(nonlinear::total_normal_force(solution, 0), p, 1e-6 * p);
  EXPECT_NEAR(nonlinear::total_normal_force(solution, 1), p, 1e-6 * p);
}

// Reference: one body on supports, no contact pair. Linear: u_z = -p z / E exactly. Large
// displacements (total Lagrangian St Venant-Kirchhoff): the homogeneous uniaxial state is in
// the FE space; with the dead traction p on the reference top, P_zz = lambda S_zz = -p and
// S_zz = E E_zz = E (lambda^2 - 1) / 2 (SVK is linear in E, the lateral sides free), so the
// stretch solves E (lambda^3 - lambda) / 2 + p = 0 and u_z = (lambda - 1) z. Tolerance 1e-6
// relative, above the Newton tolerance 1e-8.
TEST(Assemblies, ModelWithoutContactRunsWithTheSameSolver)
{
  for (const auto kinematics : {fem::Kinematics::linear, fem::Kinematics::total_lagrangian})
  {
    const bool large = kinematics == fem::Kinematics::total_lagrangian;
    const double p = large ? 4e9 : 1e8; // 2 % strain with large displacements
    const fem::Problem problem = test::stacked_cubes({3}, -p);
    ASSERT_TRUE(problem.contacts.empty());
    TimerTable timers;
    const nonlinear::ContactSolution solution =
        nonlinear::solve_feti_contact(problem, exact_settings(kinematics), timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    double stretch = 1 - p / young;
    if (large)
      for (int k = 0; k < 50; ++k) // Newton on E (l^3 - l) / 2 + p = 0
        stretch -=
            (young * (stretch * stretch * stretch - stretch) / 2 + p) / (young * (3 * stretch * stretch - 1) / 2);
    const double error = settlement_error(problem, solution.u, [&](double z) { return (stretch - 1) * z; });
    std::printf("%s displacements without contact: stretch %.9f, |u_z - u_exact|_max / |u_top| = %.2e, %zu "
                "outer iterations\n",
                large ? "large" : "small", stretch, error, solution.history.size());
    EXPECT_LT(error, 1e-6);
    EXPECT_EQ(solution.constraints.n_rows(), 0);
    EXPECT_EQ(nonlinear::total_normal_force(solution), 0.0);
  }
}
