/// Ties (issue 63, item 3): non-matching meshes glued by dual mortar tying rows, through the
/// FETI solver, in 3D (hex8 stacks) and on the edges of every 2D cell type.
///
/// References. A stack of bodies under a uniform traction on its top, on rollers (symmetry
/// planes and the bottom held normal to themselves): the exact solution is uniaxial stress
/// sigma = +-p along the stack, a linear displacement every cell type represents. Dual mortar
/// tying rows transfer it exactly across non-matching meshes (a uniform traction gives both
/// sides their consistent nodal forces: ALGORITHMS.md section 10, "Mortar tying"), so the
/// computed displacement is the exact one to the QP's tolerance: u_z = s z / E, u_x = -nu s x /
/// E, u_y = -nu s y / E in 3D (s = sigma_zz); u_y = s (1 - nu^2) (y - y_0) / E, u_x = -nu (1 +
/// nu) s x / E in plane strain; u_z = s (y - y_0) / E, u_r = -nu s r / E in axisymmetry. A tie
/// carries tension, which contact cannot: both signs are tested.

#include "linear_solve.hpp"
#include "stacked_bodies.hpp"

#include "contact/tie_rows.hpp"
#include "nonlinear/contact_pressure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace feticon;

namespace ties
{
constexpr double young = test::stack_young, poisson = test::stack_poisson;

/// test::stacked_cubes with the interfaces `tied` made ties, the top pulled (s > 0) or pressed.
fem::Problem stacked_cubes(const std::vector<int>& cells, const std::vector<size_t>& tied, double s)
{
  fem::Problem p = test::stacked_cubes(cells, s);
  test::tie_pairs(p, tied);
  return p;
}

/// max |u - u_exact| over all nodes and components, relative to max |u_exact|.
template <class Exact>
double displacement_error(const fem::Problem& p, const la::Vector& u, Exact exact)
{
  double error = 0, scale = 0;
  for (int32_t n = 0; n < p.mesh.n_nodes(); ++n)
  {
    const Eigen::Vector3d expected = exact(p.mesh.nodes.row(n).transpose());
    error = std::max(error, (u.segment<3>(3 * n) - expected).cwiseAbs().maxCoeff());
    scale = std::max(scale, expected.cwiseAbs().maxCoeff());
  }
  return error / scale;
}

Eigen::Vector3d uniaxial_3d(const Eigen::Vector3d& x, double s)
{
  return Eigen::Vector3d(-poisson * s * x(0), -poisson * s * x(1), s * x(2)) / young;
}
} // namespace ties

// Issue 63's acceptance: the three-body stack of test_assemblies.cpp (3 / 4 / 2 cells a side)
// with its upper pair replaced by a tie, pressed: exact to 1e-8 (measured 1e-12); the
// contact pair below carries p A. Then both interfaces tied and the stack pulled: tension
// across both ties, exact alike. 1 and 6 subdomains.
TEST(Ties, NonMatchingStackPassesThePatchTest)
{
  using namespace ties;
  const double p = 1e8;
  for (const int subdomains : {1, 6})
  {
    const fem::Problem pressed = stacked_cubes({3, 4, 2}, {1}, -p);
    ASSERT_EQ(pressed.ties.size(), 1u);
    // 5 x 5 slave nodes of the 2 x 2 bottom face of body 2... 3 x 3, each tied in the components
    // its rollers leave free: 9 x 3 - 3 (x = 0) - 3 (y = 0) = 21 rows.
    EXPECT_EQ(pressed.tie_equations.size(), 21u);
    const nonlinear::ContactSolution squeezed = test::solve_linear(pressed, subdomains, 1e-12);
    ASSERT_TRUE(squeezed.converged) << squeezed.reason;
    const double error =
        displacement_error(pressed, squeezed.u, [&](const Eigen::Vector3d& x) { return uniaxial_3d(x, -p); });
    std::printf("tie + pair, pressed, %d subdomains: max |u - u_exact| / max |u_exact| = %.2e\n", subdomains, error);
    EXPECT_LT(error, 1e-8);
    EXPECT_NEAR(nonlinear::total_normal_force(squeezed, 0), p, 1e-8 * p);

    const fem::Problem pulled = stacked_cubes({3, 4, 2}, {0, 1}, p);
    const nonlinear::ContactSolution stretched = test::solve_linear(pulled, subdomains, 1e-12);
    ASSERT_TRUE(stretched.converged) << stretched.reason;
    const double tension_error =
        displacement_error(pulled, stretched.u, [&](const Eigen::Vector3d& x) { return uniaxial_3d(x, p); });
    std::printf("two ties, pulled, %d subdomains: max |u - u_exact| / max |u_exact| = %.2e\n", subdomains,
                tension_error);
    EXPECT_LT(tension_error, 1e-8);
  }
}

// The same stack tied by node-to-segment rows (CalculiX's tie, the closest point's shape
// functions): a linear displacement satisfies them, but the forces across the tie are not the
// consistent ones, so the answer is off the exact one on non-matching meshes (measured 2.8 %),
// and exact where the meshes match (3 / 3 cells).
TEST(Ties, NodeToSegmentTieIsExactOnMatchingMeshesOnly)
{
  using namespace ties;
  const double p = 1e8;
  const auto error_of = [&](const std::vector<int>& cells) {
    fem::Problem problem = stacked_cubes(cells, {0}, p);
    problem.ties[0].formulation = fem::ContactFormulation::node_to_segment;
    contact::tie_surfaces(problem);
    const nonlinear::ContactSolution solution = test::solve_linear(problem, 2, 1e-12);
    EXPECT_TRUE(solution.converged) << solution.reason;
    return displacement_error(problem, solution.u, [&](const Eigen::Vector3d& x) { return uniaxial_3d(x, p); });
  };
  const double matching = error_of({3, 3});
  const double non_matching = error_of({3, 4});
  std::printf("node-to-segment tie: matching %.2e, non-matching %.2e of max |u_exact|\n", matching, non_matching);
  EXPECT_LT(matching, 1e-8);
  EXPECT_GT(non_matching, 1e-4);
}

// Large displacements: the two-tie stack pulled by s = 4e9 Pa (2 % strain), a dead traction on
// the reference top. The tie rows hold in every configuration (u_s = sum w u_a is linear in u),
// so the state stays uniaxial: SVK gives P = E (l^3 - l) / 2 = s and the top rises by 3 (l - 1).
// To 1e-7 (the outer loop's tolerance 1e-9; measured 8e-11).
TEST(Ties, TiedStackUnderLargeDisplacementsIsSvkUniaxial)
{
  using namespace ties;
  const double s = 4e9;
  const fem::Problem problem = stacked_cubes({3, 4, 2}, {0, 1}, s);
  nonlinear::SolverSettings settings;
  settings.kinematics = fem::Kinematics::total_lagrangian;
  settings.dual.rtol = 1e-10;
  settings.dual.force_rtol = 0;
  settings.displacement_tolerance = 1e-9;
  settings.residual_tolerance = 1e-9;
  settings.subdomains = 6;
  TimerTable timers;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, settings, timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  double l = 1.02; // Newton on E (l^3 - l) / 2 = s
  for (int k = 0; k < 50; ++k)
    l -= (young * (l * l * l - l) / 2 - s) / (young * (3 * l * l - 1) / 2);
  double top = 0;
  for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
    top = std::max(top, solution.u(3 * n + 2));
  const double error = std::abs(top - 3 * (l - 1)) / (3 * (l - 1));
  std::printf("tied stack, large displacements: top %.10e m, SVK uniaxial %.10e m, relative error %.2e\n", top,
              3 * (l - 1), error);
  EXPECT_LT(error, 1e-7);
}

// Every 2D cell type (line2 and line3 edges, Popp's transformed basis on the quadratic ones),
// plane strain and axisymmetry, pulled: exact to 1e-8 (module comment).
TEST(Ties, PlanarNonMatchingBlocksPassThePatchTest)
{
  using namespace ties;
  const double s = 1e7;
  for (const mesh::CellKind kind :
       {mesh::CellKind::tri3, mesh::CellKind::quad4, mesh::CellKind::tri6, mesh::CellKind::quad8})
    for (const mesh::PlanarKind planar : {mesh::PlanarKind::plane_strain, mesh::PlanarKind::axisymmetric})
    {
      fem::Problem problem = test::stacked_blocks(kind, planar, 3, -s);
      test::tie_pairs(problem, {0});
      const nonlinear::ContactSolution solution = test::solve_linear(problem, 3, 1e-12);
      ASSERT_TRUE(solution.converged) << solution.reason;
      const bool axi = planar == mesh::PlanarKind::axisymmetric;
      const double error = displacement_error(problem, solution.u, [&](const Eigen::Vector3d& x) -> Eigen::Vector3d {
        if (axi)
          return Eigen::Vector3d(-poisson * s * x(0), s * (x(1) + 0.4), 0) / young;
        return Eigen::Vector3d(-poisson * (1 + poisson) * s * x(0), (1 - poisson * poisson) * s * (x(1) + 0.4), 0) /
            young;
      });
      std::printf("%s %s: %zu tie rows, max |u - u_exact| / max |u_exact| = %.2e\n",
                  std::string(mesh::cell_type(kind).name).c_str(), axi ? "axisymmetric" : "plane strain",
                  problem.tie_equations.size(), error);
      EXPECT_LT(error, 1e-8) << std::string(mesh::cell_type(kind).name) << (axi ? " axisymmetric" : " plane strain");
    }
}
