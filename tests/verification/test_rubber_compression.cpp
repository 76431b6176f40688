/// Hyperelasticity through contact with large displacements (issue 66, items 4 and 5): a rubber
/// block (Neo-Hooke, Mooney-Rivlin) compressed by 30 % by a stiff steel platen under a prescribed
/// displacement, against the closed form of the uniaxial series model at every load step.

#include "block_under_platen.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "rubber_closed_forms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace feticon;

namespace rubber_platen
{
constexpr double block_height = 0.5, block_width = 0.5, platen_height = 0.1, platen_width = 0.7;
constexpr double steel_young = 2e13, steel_poisson = 0.3; ///< a platen 3e6 times stiffer than the rubber

/// The block [0, 0.5]^3 (3 x 3 x 3 cells) held at z = 0, the steel platen [0, 0.7]^2 x [0.5, 0.6]
/// (2 x 2 x 1 cells, wide enough for the block's bulging top) on it through a frictionless
/// mortar pair, both on the symmetry planes x = 0 and y = 0, the platen's top moved down by
/// `depth` (m) in `increments` load steps.
fem::Problem compressed_block(const fem::Hyperelastic& law, double depth, int increments)
{
  mesh::BoxParameters block, top;
  block.lengths = Eigen::Vector3d(block_width, block_width, block_height);
  block.nx = block.ny = block.nz = 3;
  top.lengths = Eigen::Vector3d(platen_width, platen_width, platen_height);
  top.nx = top.ny = 2;
  top.nz = 1;
  fem::Material rubber;
  rubber.set_hyperelastic(law);
  return block_under_platen::pressed_block(
      "rubber block", block, top, {rubber, fem::Material{steel_young, steel_poisson}}, {{depth, increments}}, false);
}

/// The closed form: frictionless contact and free lateral faces leave both bodies in uniaxial
/// stress of one force F. The block's stretch l_b gives F = P_rubber(l_b) A_b
/// (rubber_closed_forms), the platen's stretch l_p the same F = -l_p E (l_p^2 - 1) / 2 A_p (St
/// Venant-Kirchhoff: S = E E_11, P = l S); the press is L_b (1 - l_b) + L_p (1 - l_p). Solved
/// for F by bisection (compression positive).
double series_force(const fem::Hyperelastic& law, double depth)
{
  const double area_b = block_width * block_width, area_p = platen_width * platen_width;
  const auto bisect = [](auto&& increasing, double low, double high) {
    for (int k = 0; k < 200; ++k)
    {
      const double mid = 0.5 * (low + high);
      (increasing(mid) > 0 ? high : low) = mid;
    }
    return 0.5 * (low + high);
  };
  const auto press_at = [&](double force) {
    const double l_b =
        bisect([&](double l) { return force + rubber_closed_forms::uniaxial_nominal_stress(law, l) * area_b; }, 0.3, 1);
    const double l_p = bisect([&](double l) { return force + l * steel_young * (l * l - 1) / 2 * area_p; }, 0.9, 1);
    return block_height * (1 - l_b) + platen_height * (1 - l_p);
  };
  return bisect([&](double force) { return press_at(force) - depth; }, 0, 1e8);
}
} // namespace rubber_platen

// Reference: the series model above at every load step (30 % of the block's height in 6
// increments). The deformation is homogeneous, which every trilinear cell represents exactly;
// the errors are the solver's (the outer loop stops at |du|/|u| < 1e-6 and the residual test,
// the QP at 1e-10) and the series model's platen term, uniaxial where the platen is pressed on
// the block's patch only (measured: -1.0e-6 of the force at E_p = 2e11 Pa, -1.0e-8 at 2e13 Pa).
// Tolerance 1e-7 of the final force.
TEST(RubberCompression, ContactForceFollowsTheUniaxialClosedForm)
{
  const double depth = 0.3 * rubber_platen::block_height;
  const int increments = 6;
  for (const fem::Hyperelastic& law : {fem::Hyperelastic{1.0e6, 0.0, 2.0e-8}, fem::Hyperelastic{0.8e6, 0.2e6, 2.0e-8}})
  {
    const fem::Problem problem = rubber_platen::compressed_block(law, depth, increments);
    nonlinear::SolverSettings settings;
    settings.kinematics = fem::Kinematics::total_lagrangian;
    settings.dual.rtol = 1e-10;
    settings.dual.force_rtol = 0;
    settings.subdomains = 2;
    std::vector<double> forces;
    TimerTable timers;
    const nonlinear::ContactSolution solution =
        nonlinear::solve_feti_contact(problem, settings, timers, [&](int, const nonlinear::ContactSolution& s) {
          forces.push_back(nonlinear::total_normal_force(s));
        });
    ASSERT_TRUE(solution.converged) << solution.reason;
    ASSERT_EQ(forces.size(), static_cast<size_t>(increments));
    const double last = rubber_platen::series_force(law, depth);
    for (int k = 0; k < increments; ++k)
    {
      const double expected = rubber_platen::series_force(law, depth * (k + 1) / increments);
      std::printf("C01 %.1e, press %.1f %%: contact force %.8e N, closed form %.8e N (%+.2e)\n", law.c01,
                  30.0 * (k + 1) / increments, forces[k], expected, (forces[k] - expected) / last);
      EXPECT_NEAR(forces[k], expected, 1e-7 * last) << "load step " << k + 1;
    }
  }
}
