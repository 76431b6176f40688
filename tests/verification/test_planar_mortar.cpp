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
#include "stacked_bodies.hpp"
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
/// SI; the blocks of test::stacked_blocks
constexpr double young = test::stack_young, poisson = test::stack_poisson, pressure = 1e7, width = 0.5, height = 0.4;

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
        const fem::Problem problem = test::stacked_blocks(kind, planar, 3, pressure);
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
