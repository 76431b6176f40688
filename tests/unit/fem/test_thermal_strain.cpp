/// Thermal strain in the elements and the temperatures of a problem's history (issue 65, item 4).

#include "common/error.hpp"
#include "fem/cell_element.hpp"
#include "fem/hex8_element.hpp"
#include "fem/temperature_history.hpp"
#include "fem_test_meshes.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace feticon;

namespace
{
fem::Material steel()
{
  fem::Material m{2.1e11, 0.3};
  m.expansion = 1.2e-5;
  return m;
}
} // namespace

/// Reference: a body heated uniformly by dT and free to expand is unstrained mechanically: u =
/// alpha dT X with small strains, and with Green-Lagrange strains E = alpha dT I, i.e. the
/// stretch sqrt(1 + 2 alpha dT) (CalculiX's additive split on E). Its internal force is zero;
/// held at u = 0 it carries sigma = -alpha E dT / (1 - 2 nu) on the normals and no shear.
TEST(ThermalStrain, FreeExpansionIsStressFreeAndHeldExpansionCarriesTheThermalStress)
{
  const mesh::Mesh cube = test::distorted_patch();
  const fem::Material m = steel();
  const double dT = 150, scale = m.thermal_stress() * dT;
  for (const fem::Kinematics kinematics : {fem::Kinematics::linear, fem::Kinematics::total_lagrangian})
  {
    const double stretch =
        kinematics == fem::Kinematics::linear ? m.expansion * dT : std::sqrt(1 + 2 * m.expansion * dT) - 1;
    for (int32_t c = 0; c < cube.n_cells(); ++c)
    {
      fem::NodeCoords X;
      for (int a = 0; a < 8; ++a)
        X.row(a) = cube.nodes.row(cube.cells[c][a]);
      const fem::NodeTemperatures temperature = fem::NodeTemperatures::Constant(dT);
      fem::ElementVector f;
      fem::hex8_element(X, stretch * X, m, kinematics, fem::StiffnessKind::none, f, nullptr, c, &temperature);
      // f is a sum of terms of size sigma_th * area: zero to round-off of that scale.
      EXPECT_LT(f.norm(), 1e-9 * scale * X.squaredNorm()) << "cell " << c;
      const fem::Hex8PointResults held =
          fem::hex8_point_results(X, fem::NodeCoords::Zero(), m, kinematics, c, &temperature);
      for (const auto& s : held.stress)
      {
        EXPECT_NEAR(s(0), -scale, 1e-12 * scale);
        EXPECT_NEAR(s(2), -scale, 1e-12 * scale);
        EXPECT_NEAR(s(3), 0, 1e-12 * scale);
      }
      const auto free = fem::hex8_cauchy_stress(X, stretch * X, m, kinematics, c, &temperature);
      EXPECT_LT(free.norm(), 1e-9 * scale);
    }
  }
}

// Reference: hex8_element, an independent implementation of the same formulation. The element
// of any cell type interpolates a temperature varying in space by its shape functions as
// hex8_element does: the same force and tangent on a hex8 cell.
TEST(ThermalStrain, AnyCellTypeAgreesWithHex8)
{
  const mesh::Mesh hex = test::unit_cube();
  const fem::Material m = steel();
  Eigen::Matrix<double, 8, 3> X8;
  for (int a = 0; a < 8; ++a)
    X8.row(a) = hex.nodes.row(hex.cells[0][a]);
  fem::NodeTemperatures t8;
  for (int a = 0; a < 8; ++a)
    t8(a) = 20 + 30 * X8(a, 0) - 10 * X8(a, 2);
  Eigen::MatrixX3d X = X8, u = 1e-4 * X8;
  Eigen::VectorXd t = t8;
  for (const fem::Kinematics kinematics : {fem::Kinematics::linear, fem::Kinematics::total_lagrangian})
  {
    fem::ElementVector f8;
    fem::ElementMatrix K8;
    fem::hex8_element(X8, 1e-4 * X8, m, kinematics, fem::StiffnessKind::tangent, f8, &K8, 0, &t8);
    Eigen::VectorXd f;
    Eigen::MatrixXd K;
    fem::cell_element(mesh::CellKind::hex8, X, u, m, kinematics, fem::StiffnessKind::tangent, fem::Integration::full, f,
                      &K, 0, &t);
    EXPECT_LT((f - f8).norm(), 1e-12 * f8.norm());
    EXPECT_LT((K - K8).norm(), 1e-12 * K8.norm());
  }
}

namespace
{
fem::Problem two_cells()
{
  fem::Problem p;
  mesh::BoxParameters box;
  box.nx = 2;
  p.mesh = mesh::generate_box(box);
  p.materials = {steel()};
  p.amplitudes["up"] = fem::Amplitude{{{0, 0}, {1, 2}}};
  p.initial_temperatures.assign(p.mesh.n_nodes(), 20);
  return p;
}
} // namespace

// Reference: CalculiX's rule (tempload.f), evaluated by hand for node 0 and node 1 over three
// steps: ramp 20 -> 120, amplitude 60 a(t) with a = 2t, then not named: back to T_0 = 20.
TEST(TemperatureHistory, RampAmplitudeAndReturnToTheInitialTemperature)
{
  fem::Problem p = two_cells();
  p.steps.resize(3);
  p.steps[0].temperatures = {{0, 120}, {1, 70}};
  p.steps[1].temperatures = {{0, 60, "up"}, {1, 70}};
  p.steps[2].ramp = false;
  p.validate();
  const fem::TemperatureHistory history(p);
  ASSERT_FALSE(history.empty());
  const auto at = [&](int stage, double fraction) {
    return history.change({stage, fraction, stage - 1 + fraction, stage - 1 + fraction});
  };
  EXPECT_DOUBLE_EQ(at(1, 0.25)(0), 25);     // 20 + 0.25 (120 - 20) - 20
  EXPECT_DOUBLE_EQ(at(1, 0.25)(1), 12.5);   // 20 + 0.25 (70 - 20) - 20
  EXPECT_DOUBLE_EQ(at(1, 0.25)(2), 0);      // not named: stays at T_0
  EXPECT_DOUBLE_EQ(at(2, 0.5)(0), 60 - 20); // 60 a(0.5) = 60, step time 0.5
  EXPECT_DOUBLE_EQ(at(2, 0.5)(1), 50);      // held at 70
  EXPECT_DOUBLE_EQ(at(3, 0.5)(0), 0);       // ramp = false: T_0 at once
  EXPECT_DOUBLE_EQ(at(3, 0.5)(1), 0);
  p.steps[2].ramp = true;
  const fem::TemperatureHistory ramped(p);
  // From 60 a(1) = 120 at the end of step 2 back to 20.
  EXPECT_DOUBLE_EQ(ramped.change({3, 0.5, 2.5, 2.5})(0), 70 - 20);
  EXPECT_TRUE(fem::TemperatureHistory(two_cells()).empty());
}

TEST(TemperatureHistory, BadTemperaturesAreRefused)
{
  fem::Problem p = two_cells();
  p.steps[0].temperatures = {{0, std::nan("")}};
  EXPECT_THROW(p.validate(), Error);
  p.steps[0].temperatures = {{0, -300}};
  EXPECT_THROW(p.validate(), Error);
  p.steps[0].temperatures = {{p.mesh.n_nodes(), 20}};
  EXPECT_THROW(p.validate(), Error);
  p.steps[0].temperatures = {{0, 20, "nowhere"}};
  EXPECT_THROW(p.validate(), Error);
  p.steps[0].temperatures = {{0, 20}};
  p.initial_temperatures.pop_back();
  EXPECT_THROW(p.validate(), Error);
}
