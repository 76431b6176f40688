/// Body loads against closed forms (issue 65, item 5): a rotating disc (CENTRIF) against the
/// rotating annulus in plane strain, through the FETI solver without any contact pair, and a
/// column of two blocks under its own weight (GRAV) with a contact pair between them.

#include "annulus_mesh.hpp"
#include "fem/stress.hpp"
#include "mesh/box.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace feticon;

namespace disc
{
constexpr double young = 2.1e11, poisson = 0.3, density = 7800, omega = 1000;
constexpr double a = 0.02, c = 0.1; ///< bore and rim radii (m)

/// The annulus a < r < c spinning at omega about z, plane strain (u_z = 0 on both faces),
/// symmetry planes x = 0 and y = 0.
fem::Problem spinning_annulus(int n_r, int n_theta)
{
  fem::Problem p;
  p.name = "rotating disc";
  p.mesh = test::quarter_annulus(a, c, 0.005, n_r, n_theta, mesh::CellKind::hex8, "disc");
  p.materials = {fem::Material{young, poisson, density}};
  fem::Step& step = p.steps.front();
  step.dirichlet = {{"ymin", {std::nullopt, 0.0, std::nullopt}},
                    {"ymax", {0.0, std::nullopt, std::nullopt}},
                    {"zmin", {std::nullopt, std::nullopt, 0.0}},
                    {"zmax", {std::nullopt, std::nullopt, 0.0}}};
  fem::BodyLoad spin;
  spin.kind = fem::BodyLoad::Kind::centrifugal;
  spin.omega2 = omega * omega;
  step.body_loads = {spin};
  p.validate();
  return p;
}

/// Radial and hoop stress of the rotating annulus in plane strain: the plane-stress disc's
/// (Timoshenko and Goodier, Theory of Elasticity, 32) with nu / (1 - nu) for nu,
///   sigma_r = (3 - 2 nu) / (8 (1 - nu)) rho omega^2 (a^2 + c^2 - a^2 c^2 / r^2 - r^2),
///   sigma_t = rho omega^2 / (8 (1 - nu)) ((3 - 2 nu) (a^2 + c^2 + a^2 c^2 / r^2) - (1 + 2 nu) r^2).
Eigen::Vector2d closed_form(double r)
{
  const double k = density * omega * omega / (8 * (1 - poisson));
  const double s = a * a + c * c, q = a * a * c * c / (r * r);
  return {k * (3 - 2 * poisson) * (s - q - r * r), k * ((3 - 2 * poisson) * (s + q) - (1 + 2 * poisson) * r * r)};
}

/// The largest error of the cell-averaged radial and hoop stresses against the closed form at
/// the cell centres, over the peak hoop stress (at the bore).
double stress_error(int n_r, int n_theta)
{
  const fem::Problem problem = spinning_annulus(n_r, n_theta);
  nonlinear::SolverSettings settings;
  settings.kinematics = fem::Kinematics::linear;
  settings.dual.rtol = 1e-10;
  settings.subdomains = 4;
  TimerTable timers;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, settings, timers);
  EXPECT_TRUE(solution.converged) << solution.reason;
  const auto stresses = fem::cell_cauchy_stresses(problem.mesh, solution.u, problem.materials, fem::Kinematics::linear);
  double error = 0;
  for (int32_t cell = 0; cell < problem.mesh.n_cells(); ++cell)
  {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const int32_t n : problem.mesh.cells[cell])
      centre += problem.mesh.nodes.row(n).transpose() / 8;
    const double r = centre.head<2>().norm();
    const Eigen::Vector2d e_r = centre.head<2>() / r, e_t(-e_r.y(), e_r.x());
    Eigen::Matrix2d sigma;
    sigma << stresses[cell](0), stresses[cell](3), stresses[cell](3), stresses[cell](1);
    const Eigen::Vector2d expected = closed_form(r);
    error =
        std::max({error, std::abs(e_r.dot(sigma * e_r) - expected(0)), std::abs(e_t.dot(sigma * e_t) - expected(1))});
  }
  return error / closed_form(a)(1);
}
} // namespace disc

// Reference: the closed form above. The cell averages carry the discretization error of the
// hex8 mesh (measured 3.0e-3 and 1.24e-3 of the peak hoop stress; 5.9e-3 at 6 x 12 cells, so
// still short of the asymptotic rate): halving the cells must at least halve it (first order),
// and the finer mesh be within 0.2 %.
TEST(RotatingDisc, CentrifugalLoadMatchesTheClosedFormAndConverges)
{
  const double coarse = disc::stress_error(12, 24), fine = disc::stress_error(24, 48);
  std::printf("rotating disc: max stress error / peak hoop stress %.3e (12 x 24 cells), %.3e (24 x 48), ratio %.2f\n",
              coarse, fine, coarse / fine);
  EXPECT_LT(fine, 2e-3);
  EXPECT_GT(coarse / fine, 2.0);
}

namespace
{
constexpr double column_height = 2.5; ///< base [-1, 0], block [0, 1.5]

/// A base [0, 0.5]^2 x [-1, 0] of 4 x 4 x 4 cells and a block [0, 0.5]^2 x [0, 1.5] of 3 x 3 x 5
/// cells on it (mortar pair, non-matching faces), both under gravity -g e_z; the base held at
/// z = -1 in z, both on the symmetry planes x = 0 and y = 0; nu = 0.
fem::Problem gravity_column(double rho, double g)
{
  fem::Problem p;
  p.name = "column";
  mesh::BoxParameters base, block;
  base.origin = Eigen::Vector3d(0, 0, -1);
  base.lengths = Eigen::Vector3d(0.5, 0.5, 1);
  base.nx = base.ny = base.nz = 4;
  base.body_name = "base";
  block.lengths = Eigen::Vector3d(0.5, 0.5, 1.5);
  block.nx = block.ny = 3;
  block.nz = 5;
  block.body_name = "block";
  p.mesh = mesh::generate_box(base);
  mesh::append_mesh(p.mesh, mesh::generate_box(block), "block_");
  p.materials.assign(2, fem::Material{2e11, 0.0, rho});
  fem::Step& step = p.steps.front();
  for (const std::string prefix : {"", "block_"})
  {
    step.dirichlet.push_back({prefix + "xmin", {0.0, std::nullopt, std::nullopt}});
    step.dirichlet.push_back({prefix + "ymin", {std::nullopt, 0.0, std::nullopt}});
  }
  step.dirichlet.push_back({"zmin", {std::nullopt, std::nullopt, 0.0}});
  fem::BodyLoad weight;
  weight.gravity = Eigen::Vector3d(0, 0, -g);
  step.body_loads = {weight};
  p.contacts.push_back({"block_zmin", "zmax"});
  p.validate();
  return p;
}
} // namespace

// Reference: with nu = 0 and one cross-section the column is a bar under its weight,
// sigma_zz(z) = -rho g (1.5 - z), so u_z(z) = -rho g / E ((1.5) (z + 1) - (z^2 - 1) / 2) and the
// top settles by rho g H^2 / (2 E), H = 2.5; hex8's nodal values of a bar are exact (linear
// elements on a 1D second-order problem with consistent loads), and mortar rows carry the
// uniform pressure across the non-matching faces. The contact force is the block's weight
// rho g V. Tolerances 1e-6 (issue 65's), far above qp.rtol = 1e-10.
TEST(GravityColumn, ContactForceIsTheWeightAndTheSettlementTheBarFormula)
{
  const double rho = 7800, g = 9.81, E = 2e11;
  const fem::Problem problem = gravity_column(rho, g);
  nonlinear::SolverSettings settings;
  settings.kinematics = fem::Kinematics::linear;
  settings.dual.rtol = 1e-10;
  settings.dual.force_rtol = 0;
  settings.subdomains = 4;
  TimerTable timers;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(problem, settings, timers);
  ASSERT_TRUE(solution.converged) << solution.reason;
  const double weight = rho * g * 0.5 * 0.5 * 1.5, force = nonlinear::total_normal_force(solution);
  const double settlement = rho * g * column_height * column_height / (2 * E);
  double error = 0;
  for (int32_t n = 0; n < problem.mesh.n_nodes(); ++n)
  {
    const double z = problem.mesh.nodes(n, 2);
    error = std::max(error, std::abs(solution.u(3 * n + 2) + rho * g / E * (1.5 * (z + 1) - (z * z - 1) / 2)));
  }
  std::printf("gravity column: contact force %.10g N (weight %.10g N), max |u_z - bar| %.2e of the settlement "
              "%.4e m\n",
              force, weight, error / settlement, settlement);
  EXPECT_NEAR(force, weight, 1e-6 * weight);
  EXPECT_LT(error, 1e-6 * settlement);
}
