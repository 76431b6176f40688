/// Contact of two blocks of every cell type (issue 38): the contact patch test. A block
/// [0,1]^2 x [0,0.5] pressed by a uniform pressure p onto a block [0,1]^2 x [-0.5,0] on a
/// frictionless support, both on the symmetry planes x = 0 and y = 0, node-to-segment and dual
/// mortar rows. References: equilibrium (the contact force equals p A, the upper block being
/// held along z by contact alone) and the exact solution, a uniform stress sigma_zz = -p in both
/// blocks with every other component zero. Mortar rows must reproduce it to round-off on
/// matching and non-matching meshes of every type: a uniform pressure is a dual traction with
/// z_j = p (sum_j Phi_j = 1), whose forces are the consistent nodal loads on both faces
/// (contact/mortar_constraints.hpp, and for quadratic faces the transformed basis of
/// contact/mortar_face_integration.hpp). Node-to-segment rows only on matching meshes (the slave
/// nodes lie on the master nodes, and the consistent loads of the slave faces, zero at a tri6's
/// corners, are a solution of the QP), and not for hex20, whose quad8 faces' consistent loads
/// are negative at the corners (see the test).

#include "fem/stress.hpp"
#include "mesh/box.hpp"
#include "mesh/cell_conversion.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "tests/support/feti_contact_run.hpp"

#include <gtest/gtest.h>

using namespace feticon;
using mesh::CellKind;

namespace
{
constexpr double pressure = 1e7; // Pa on the 1 m^2 top face

struct PatchCase
{
  CellKind kind;
  int upper_cells; ///< along x and y; the lower block has 2 x 2
  contact::ContactFormulation formulation = contact::ContactFormulation::node_to_segment;
};

fem::Problem pressed_blocks(const PatchCase& c)
{
  mesh::BoxParameters lower{
      .origin = {0, 0, -0.5}, .lengths = {1, 1, 0.5}, .nx = 2, .ny = 2, .nz = 1, .body_name = "lower"};
  mesh::BoxParameters upper{.origin = {0, 0, 0},
                            .lengths = {1, 1, 0.5},
                            .nx = c.upper_cells,
                            .ny = c.upper_cells,
                            .nz = 1,
                            .body_name = "upper"};
  mesh::Mesh hex = mesh::generate_box(lower);
  mesh::append_mesh(hex, mesh::generate_box(upper), "upper_");
  fem::Problem p;
  p.name = "pressed blocks";
  p.mesh = c.kind == CellKind::hex8 ? hex : mesh::convert_hex8_mesh(hex, c.kind);
  p.materials.assign(2, fem::Material{2e11, 0.3});
  p.steps.front().dirichlet = {{"zmin", {std::nullopt, std::nullopt, 0.0}},
                               {"xmin", {0.0, std::nullopt, std::nullopt}},
                               {"ymin", {std::nullopt, 0.0, std::nullopt}},
                               {"upper_xmin", {0.0, std::nullopt, std::nullopt}},
                               {"upper_ymin", {std::nullopt, 0.0, std::nullopt}}};
  p.steps.front().tractions = {{"upper_zmax", Eigen::Vector3d(0, 0, -pressure)}};
  p.contacts = {{"upper_zmin", "zmax"}};
  p.validate();
  return p;
}

nonlinear::SolverSettings patch_settings(contact::ContactFormulation formulation)
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.dual.rtol = 1e-12;
  s.dual.force_rtol = 0; // qp.rtol alone: the patch test holds to round-off
  s.subdomains = 2;
  s.formulation = formulation;
  return s;
}

class ContactPatch : public ::testing::TestWithParam<PatchCase>
{
};

TEST_P(ContactPatch, TransmitsAUniformPressure)
{
  const PatchCase c = GetParam();
  const fem::Problem problem = pressed_blocks(c);
  const test::FetiContactRun run = test::run_feti_contact(problem, patch_settings(c.formulation));
  EXPECT_NEAR(nonlinear::total_normal_force(run.solution), pressure, 1e-6 * pressure);
  // Non-matching node-to-segment rows pass no patch test (only the force balance). Nor do quad8
  // faces: a uniform pressure's consistent loads pull at their corners (-A/12 each), which a
  // node-to-segment row cannot (measured: 2.3 % of p in the cells at the corners).
  if (c.formulation == contact::ContactFormulation::node_to_segment &&
      (c.upper_cells != 2 || c.kind == CellKind::hex20))
    return;
  const auto stresses =
      fem::cell_cauchy_stresses(problem.mesh, run.solution.u, problem.materials, fem::Kinematics::linear);
  double worst = 0;
  for (const auto& sigma : stresses)
  {
    Eigen::Matrix<double, 6, 1> exact = Eigen::Matrix<double, 6, 1>::Zero();
    exact(2) = -pressure;
    worst = std::max(worst, (sigma - exact).lpNorm<Eigen::Infinity>());
  }
  EXPECT_LT(worst, 1e-6 * pressure) << "largest stress error over all cells (Pa)";
}

constexpr auto mortar = contact::ContactFormulation::mortar;
INSTANTIATE_TEST_SUITE_P(EveryCellType, ContactPatch,
                         ::testing::Values(PatchCase{CellKind::hex8, 2}, PatchCase{CellKind::tet4, 2},
                                           PatchCase{CellKind::tet10, 2}, PatchCase{CellKind::hex20, 2},
                                           PatchCase{CellKind::wedge6, 2}, PatchCase{CellKind::tet4, 3},
                                           PatchCase{CellKind::tet10, 3}, PatchCase{CellKind::hex20, 3},
                                           PatchCase{CellKind::wedge6, 3}, PatchCase{CellKind::hex8, 3, mortar},
                                           PatchCase{CellKind::tet4, 2, mortar}, PatchCase{CellKind::tet4, 3, mortar},
                                           PatchCase{CellKind::tet10, 2, mortar}, PatchCase{CellKind::tet10, 3, mortar},
                                           PatchCase{CellKind::hex20, 2, mortar}, PatchCase{CellKind::hex20, 3, mortar},
                                           PatchCase{CellKind::wedge6, 3, mortar}),
                         [](const ::testing::TestParamInfo<PatchCase>& info) {
  return std::string(mesh::cell_type(info.param.kind).name) +
      (info.param.upper_cells == 2 ? "_matching" : "_nonmatching") +
      (info.param.formulation == mortar ? "_mortar" : "");
});
} // namespace
