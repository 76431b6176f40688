/// Dual mortar contact on the edges of 2D cells (issue 64, item 3): the contact patch test on
/// non-matching meshes in plane strain and axisymmetry for every 2D cell type, and the
/// axisymmetric shrink fit of test_planar_solids.cpp on non-matching rings.
///
/// References. Two stacked blocks under a uniform pressure p on the top, on rollers (u_x = 0 at
/// x = 0, u_y = 0 at the bottom): the exact solution is a uniform uniaxial stress sigma_yy = -p,
/// which every cell type represents, so the contact pressure is p at every slave node and the
/// top settles by p H (1 - nu^2) / E in plane strain (eps_zz = 0) and p H / E in axisymmetry
/// (a column r <= R with a free mantle). The dual mortar rows pass this test on non-matching
/// meshes (consistent master loads; Wohlmuth 2000); node-to-segment rows do not (measured on
/// these meshes: 5 % to 34 % off p at a slave node). Lame's
/// interference pressure as in test_planar_solids.cpp.

#include "linear_solve.hpp"
#include "mesh/rectangle.hpp"
#include "nonlinear/contact_pressure.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>

using namespace feticon;

namespace planar_mortar
{
constexpr double young = 2e11, poisson = 0.3, pressure = 1e7, width = 0.5, height = 0.4; ///< SI

/// Block [0, width] x [-height, 0] of n x n cells under block [0, width] x [0, height] of
/// (n + 2) x (n + 1): non-matching at y = 0, the upper block's bottom the slave surface.
fem::Problem stacked_blocks(mesh::CellKind kind, mesh::PlanarKind planar, int n)
{
  fem::Problem p;
  p.name = "planar patch";
  p.eliminated = {false, false, true};
  const mesh::Planar formulation{planar, 0.1};
  p.mesh = mesh::generate_rectangle({.origin = {0, -height},
                                     .lengths = {width, height},
                                     .nx = n,
                                     .ny = n,
                                     .kind = kind,
                                     .planar = formulation,
                                     .body_name = "lower"});
  mesh::append_mesh(p.mesh,
                    mesh::generate_rectangle({.origin = {0, 0},
                                              .lengths = {width, height},
                                              .nx = n + 2,
                                              .ny = n + 1,
                                              .kind = kind,
                                              .planar = formulation,
                                              .body_name = "upper"}),
                    "upper_");
  p.materials = {fem::Material{young, poisson}, fem::Material{young, poisson}};
  fem::Step step;
  step.dirichlet.push_back({"ymin", {std::nullopt, 0.0, std::nullopt}});
  if (planar != mesh::PlanarKind::axisymmetric) // on the axis u_r = 0 by itself
  {
    step.dirichlet.push_back({"xmin", {0.0, std::nullopt, std::nullopt}});
    step.dirichlet.push_back({"upper_xmin", {0.0, std::nullopt, std::nullopt}});
  }
  step.pressures.push_back({"upper_ymax", pressure});
  p.steps = {step};
  p.contacts.push_back({"upper_ymin", "ymax"});
  p.contacts[0].interaction.formulation = fem::ContactFormulation::mortar;
  p.validate();
  return p;
}

} // namespace planar_mortar

// Every cell type, plane strain and axisymmetry, 1 and 3 subdomains: the pressure of every
// slave row within 1e-7 of p (measured: round-off of the QP's 1e-11, a few 1e-9), the total
// force p times the area (thickness w, or pi w^2), the top's settlement within 1e-7.
TEST(PlanarMortar, NonMatchingBlocksPassTheContactPatchTest)
{
  using namespace planar_mortar;
  for (const mesh::PlanarKind planar : {mesh::PlanarKind::plane_strain, mesh::PlanarKind::axisymmetric})
    for (const mesh::CellKind kind : mesh::planar_cell_kinds)
      for (const int subdomains : {1, 3})
      {
        const fem::Problem problem = stacked_blocks(kind, planar, 3);
        const nonlinear::ContactSolution s = test::solve_linear(problem, subdomains, 1e-11);
        ASSERT_TRUE(s.converged) << s.reason;
        ASSERT_EQ(s.constraints.formulation, contact::ContactFormulation::mortar);
        const bool axisymmetric = planar == mesh::PlanarKind::axisymmetric;
        const std::vector<double> nodal = nonlinear::row_pressure_per_node(s, problem.mesh.n_nodes());
        double worst = 0;
        for (const int32_t node : problem.mesh.face_set_nodes("upper_ymin"))
          worst = std::max(worst, std::abs(nodal[node] / pressure - 1));
        const double area = axisymmetric ? std::numbers::pi * width * width : 0.1 * width;
        const double force_error = nonlinear::total_normal_force(s) / (pressure * area) - 1;
        const double strain = pressure / young * (axisymmetric ? 1 : 1 - poisson * poisson);
        double settlement_error = 0;
        for (const int32_t node : problem.mesh.face_set_nodes("upper_ymax"))
          settlement_error = std::max(settlement_error, std::abs(s.u(3 * node + 1) / (-2 * height * strain) - 1));
        std::printf("%s %s, %d subdomains: %zu rows, pressure error %.1e, force %.1e, settlement %.1e\n",
                    std::string(mesh::planar_name(planar)).c_str(), std::string(mesh::cell_type(kind).name).c_str(),
                    subdomains, s.constraints.slave_node.size(), worst, force_error, settlement_error);
        EXPECT_EQ(s.constraints.slave_node.size(), problem.mesh.face_set_nodes("upper_ymin").size());
        EXPECT_LT(worst, 1e-7);
        EXPECT_LT(std::abs(force_error), 1e-7);
        EXPECT_LT(settlement_error, 1e-7);
      }
}
