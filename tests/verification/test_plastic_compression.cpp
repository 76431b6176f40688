/// J2 plasticity through contact (issue 66, items 2, 3 and 5): a plastic block compressed by a
/// stiff elastic platen under a prescribed displacement, loaded past yield, unloaded, reloaded
/// and released, against the closed form of the uniaxial series model at every load step.

#include "block_under_platen.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace feticon;

namespace platen
{
constexpr double young = 2e11, platen_young = 2e13, poisson = 0.3;
constexpr double yield = 2.5e8, hardening = 1e9; ///< sigma_y = yield + hardening eqps
constexpr double block_height = 0.5, platen_height = 0.2, area = 0.25;

/// The block [0, 0.5]^3 (3 x 3 x 3 cells, J2 with linear hardening) held at z = 0, the platen
/// [0, 0.5]^2 x [0.5, 0.7] (4 x 4 x 2 cells, 100 times stiffer) on it through a frictionless
/// mortar pair (non-matching faces), both on the symmetry planes x = 0 and y = 0, the platen's
/// top moved down by each step's entry of `press` (m) in that step's increments.
fem::Problem compressed_block(const std::vector<std::pair<double, int>>& press)
{
  mesh::BoxParameters block, top;
  block.lengths = Eigen::Vector3d(0.5, 0.5, block_height);
  block.nx = block.ny = block.nz = 3;
  top.lengths = Eigen::Vector3d(0.5, 0.5, platen_height);
  top.nx = top.ny = 4;
  top.nz = 2;
  fem::Material steel{young, poisson};
  steel.plastic.stress = {yield, yield + hardening};
  steel.plastic.plastic_strain = {0, 1};
  return block_under_platen::pressed_block("plastic block", block, top, {steel, fem::Material{platen_young, poisson}},
                                           press, true);
}

/// The closed form: frictionless contact and free lateral faces leave both bodies in uniaxial
/// stress sigma (compression positive). The press d = sigma C_e + L_b eps_p with the elastic
/// compliance C_e = L_p / E_p + L_b / E; on yielding, sigma = sigma_y(eqps) and eqps grows with
/// eps_p (compression only: a release opens the contact before the block could yield back).
struct SeriesModel
{
  double plastic_strain = 0; ///< eps_p = eqps

  double stress_at(double d)
  {
    const double compliance = platen_height / platen_young + block_height / young;
    const double trial = (d - block_height * plastic_strain) / compliance;
    const double limit = yield + hardening * plastic_strain;
    if (trial <= limit)
      return std::max(trial, 0.0);
    plastic_strain +=
        (d - block_height * plastic_strain - compliance * limit) / (compliance * hardening + block_height);
    return yield + hardening * plastic_strain;
  }
};
} // namespace platen

// Reference: the series model above at every load step (press 2, 1.5, 3 and 0 mm; yield starts at
// 0.6275 mm). Tolerance 1e-5 of the peak force: the outer loop stops at |du|/|u| < 1e-6
// (newton.tolerance) and the QP solves to 1e-10 (measured: 1.4e-10 with the tangent refreshed
// at every outer iteration, newton.stiffness = auto; 1.2e-7 with K_0); the equivalent plastic
// strain of every point to 1e-5 of the strain. Released, the block keeps its plastic
// shortening: the contact opens and its top sits at -eps_p L_b.
TEST(PlasticCompression, ContactForceFollowsTheUniaxialClosedFormThroughLoadUnloadReload)
{
  const std::vector<std::pair<double, int>> press = {{0.002, 3}, {0.0015, 1}, {0.003, 2}, {0.0, 1}};
  const fem::Problem problem = platen::compressed_block(press);
  nonlinear::SolverSettings settings;
  settings.kinematics = fem::Kinematics::linear;
  settings.dual.rtol = 1e-10;
  settings.dual.force_rtol = 0;
  settings.subdomains = 4;
  std::vector<double> forces;
  std::vector<double> mean_eqps, eqps_spread; // over the block's quadrature points
  TimerTable timers;
  const nonlinear::ContactSolution solution =
      nonlinear::solve_feti_contact(problem, settings, timers, [&](int, const nonlinear::ContactSolution& s) {
        forces.push_back(nonlinear::total_normal_force(s));
        double sum = 0, low = INFINITY, high = 0;
        int64_t n = 0;
        for (int32_t c = 0; c < problem.mesh.n_cells(); ++c)
          for (const fem::PlasticPointState& point : s.plastic.of(c))
          {
            sum += point.equivalent_plastic_strain;
            low = std::min(low, point.equivalent_plastic_strain);
            high = std::max(high, point.equivalent_plastic_strain);
            ++n;
          }
        mean_eqps.push_back(sum / static_cast<double>(n));
        eqps_spread.push_back(high - low);
      });
  ASSERT_TRUE(solution.converged) << solution.reason;
  platen::SeriesModel model;
  std::vector<double> depths;
  double previous = 0;
  for (const auto& [depth, increments] : press)
  {
    for (int i = 1; i <= increments; ++i)
      depths.push_back(previous + (depth - previous) * i / increments);
    previous = depth;
  }
  ASSERT_EQ(forces.size(), depths.size());
  const double peak = (platen::yield + platen::hardening * 0.01) * platen::area;
  for (size_t k = 0; k < depths.size(); ++k)
  {
    const double expected = model.stress_at(depths[k]) * platen::area;
    std::printf("press %.4f mm: contact force %.8e N, closed form %.8e N (%+.2e of the peak); eqps %.6e, closed form "
                "%.6e\n",
                depths[k] * 1e3, forces[k], expected, (forces[k] - expected) / peak, mean_eqps[k],
                model.plastic_strain);
    EXPECT_NEAR(forces[k], expected, 1e-5 * peak) << "load step " << k + 1;
    // eqps is off by at most the strain's error, 1e-5 of the strain d / L_b likewise.
    const double strain_tolerance = 1e-5 * std::max(depths[k], 0.001) / platen::block_height;
    EXPECT_NEAR(mean_eqps[k], model.plastic_strain, strain_tolerance) << "load step " << k + 1;
    EXPECT_LE(eqps_spread[k], strain_tolerance) << "load step " << k + 1; // a uniform stress
  }
  // Released: the block's top (its corner at x = y = 0 in its top face's node set) keeps its
  // plastic shortening.
  for (const int32_t n : problem.mesh.node_set("zmax"))
  {
    if (problem.mesh.nodes.row(n).head<2>().isZero(0.0))
    {
      EXPECT_NEAR(solution.u(3 * n + 2), -model.plastic_strain * platen::block_height,
                  1e-5 * model.plastic_strain * platen::block_height);
    }
  }
}
