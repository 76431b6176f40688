/// A shrink fit by temperature (issue 65, item 4): a ring cooled onto a hub, frictionless, in
/// plane strain, against Lame's solution with the thermal interference.

#include "annulus_mesh.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace feticon;

namespace shrink_fit_model
{
constexpr double young = 2.1e11, poisson = 0.3, alpha = 1.2e-5;
constexpr double a = 0.01, b = 0.05, c = 0.1; ///< hub bore, interface and ring outer radii (m)
constexpr double thickness = 0.005;           ///< one cell through z (m)

/// Hub (a, b) and ring (b, c), touching at r = b with matching nodes; the ring's nodes at
/// T - T_0 = delta_T, the hub's at T_0; symmetry planes x = 0 and y = 0, u_z = 0 on both faces
/// (plane strain).
fem::Problem shrink_fit(mesh::CellKind kind, int n_r, int n_theta, double delta_T)
{
  fem::Problem p;
  p.name = "shrink fit";
  p.mesh = test::quarter_annulus(a, b, thickness, n_r, n_theta, kind, "hub");
  const int32_t hub_nodes = p.mesh.n_nodes();
  mesh::append_mesh(p.mesh, test::quarter_annulus(b, c, thickness, n_r, n_theta, kind, "ring"), "ring_");
  p.materials.assign(2, fem::Material{young, poisson});
  for (fem::Material& m : p.materials)
    m.expansion = alpha;
  fem::Step& step = p.steps.front();
  for (const std::string prefix : {"", "ring_"})
  {
    step.dirichlet.push_back({prefix + "ymin", {std::nullopt, 0.0, std::nullopt}});
    step.dirichlet.push_back({prefix + "ymax", {0.0, std::nullopt, std::nullopt}});
    step.dirichlet.push_back({prefix + "zmin", {std::nullopt, std::nullopt, 0.0}});
    step.dirichlet.push_back({prefix + "zmax", {std::nullopt, std::nullopt, 0.0}});
  }
  for (int32_t n = hub_nodes; n < p.mesh.n_nodes(); ++n)
    step.temperatures.push_back({n, delta_T});
  p.contacts.push_back({"ring_xmin", "xmax"});
  p.validate();
  return p;
}

/// Lame's interface pressure of the fit in plane strain: the ring's free thermal growth
/// (1 + nu) alpha delta_T b closed by u_ring(b) - u_hub(b) under the pressure p,
///   u_hub(b) = -(1 + nu) p b / E ((1 - 2 nu) b^2 + a^2) / (b^2 - a^2),
///   u_ring(b) = (1 + nu) p b / E ((1 - 2 nu) b^2 + c^2) / (c^2 - b^2) + (1 + nu) alpha delta_T b,
/// so p = -E alpha delta_T / (((1 - 2 nu) b^2 + c^2) / (c^2 - b^2) + ((1 - 2 nu) b^2 + a^2) / (b^2 - a^2)).
double lame_pressure(double delta_T)
{
  const double k = 1 - 2 * poisson;
  return -young * alpha * delta_T / ((k * b * b + c * c) / (c * c - b * b) + (k * b * b + a * a) / (b * b - a * a));
}

nonlinear::SolverSettings settings(fem::Kinematics kinematics)
{
  nonlinear::SolverSettings s;
  s.kinematics = kinematics;
  s.dual.rtol = 1e-10;
  s.dual.force_rtol = 0; // qp.rtol alone: the pressures to the solver's accuracy
  s.subdomains = 4;
  return s;
}
} // namespace shrink_fit_model

// Reference: Lame (thick cylinders in plane strain, above), p = 1.309e8 Pa for a ring cooled by
// 100 K. The interface pressure is the pair's normal force over the interface's area
// (pi / 2) b h; tolerance 1 % (issue 65's acceptance for a 3D hex8 sector). The nodal
// pressures (force over tributary area) scatter more and are printed, not held: on hex8 the
// row normal of a slave node on a master vertex is one adjacent facet's
// (contact/mortar_constraints.cpp, row_normal), 1.9 degrees off the radius here.
TEST(ShrinkFit, CooledRingOnHubMatchesLame)
{
  using namespace shrink_fit_model;
  const double delta_T = -100;
  const double expected = lame_pressure(delta_T);
  struct Case
  {
    mesh::CellKind kind;
    fem::Kinematics kinematics;
  };
  for (const Case& run : {Case{mesh::CellKind::hex8, fem::Kinematics::linear},
                          Case{mesh::CellKind::hex8, fem::Kinematics::total_lagrangian},
                          Case{mesh::CellKind::hex20, fem::Kinematics::linear}})
  {
    const fem::Problem problem = shrink_fit(run.kind, 8, 24, delta_T);
    TimerTable timers;
    const nonlinear::ContactSolution solution =
        nonlinear::solve_feti_contact(problem, settings(run.kinematics), timers);
    ASSERT_TRUE(solution.converged) << solution.reason;
    const double interface = std::numbers::pi / 2 * b * thickness;
    const double pressure = nonlinear::total_normal_force(solution) / interface;
    double lowest = pressure, highest = pressure;
    for (const nonlinear::PressureSample& s : nonlinear::slave_pressure_by_x(problem, solution, run.kinematics, {}, 0))
      if (std::abs(s.x) > 1e-9 && std::abs(s.y) > 1e-9) // off the symmetry planes
      {
        lowest = std::min(lowest, s.pressure);
        highest = std::max(highest, s.pressure);
      }
    std::printf("shrink fit (%s, %s): Lame p = %.6e Pa, force / area %.6e Pa (%+.3f %%), nodal pressures %+.2f to "
                "%+.2f %%, %zu outer iterations\n",
                std::string(mesh::cell_type(run.kind).name).c_str(),
                run.kinematics == fem::Kinematics::linear ? "small" : "large", expected, pressure,
                100 * (pressure - expected) / expected, 100 * (lowest - expected) / expected,
                100 * (highest - expected) / expected, solution.history.size());
    EXPECT_NEAR(pressure, expected, 0.01 * expected);
  }
}
