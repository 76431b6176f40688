/// J2 plasticity at one material point: the radial return against the closed forms of
/// uniaxial stress, and the consistent tangent against finite differences (issue 66, item 3).

#include "common/error.hpp"
#include "fem/j2_plasticity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace feticon;

namespace j2_test
{
constexpr double young = 2.0e11, poisson = 0.3, yield = 2.5e8;

/// Steel with linear hardening H (a two-point table; constant beyond its last point, which
/// lies far beyond the strains here) or the table given.
fem::Material hardening_steel(double hardening)
{
  fem::Material m{young, poisson};
  m.plastic.stress = {yield, yield + hardening * 1.0};
  m.plastic.plastic_strain = {0, 1.0};
  return m;
}

/// One state of uniaxial stress sigma along x with axial plastic strain ep and equivalent
/// plastic strain eqps: the total strain is (sigma / E + ep) axially and (-nu sigma / E - ep / 2)
/// laterally (plastic flow is isochoric).
struct UniaxialState
{
  double sigma, ep, eqps;
  fem::Voigt strain() const
  {
    fem::Voigt e = fem::Voigt::Zero();
    e(0) = sigma / young + ep;
    e(1) = e(2) = -poisson * sigma / young - ep / 2;
    return e;
  }
};

/// Returns from `state` along `path`, checking each increment's stress and plastic strains.
void follow(const fem::Material& m, const std::vector<UniaxialState>& path)
{
  fem::PlasticPointState state;
  for (const UniaxialState& expected : path)
  {
    const fem::J2Update update = fem::j2_return(m, expected.strain(), 0, state);
    state = update.state;
    fem::Voigt stress = fem::Voigt::Zero();
    stress(0) = expected.sigma;
    // Tolerance: round-off of the return (strains of 1e-3 carry stresses of 1e8 Pa).
    EXPECT_LE((update.stress - stress).norm(), 1e-8 * yield) << "sigma = " << expected.sigma;
    EXPECT_NEAR(state.equivalent_plastic_strain, expected.eqps, 1e-12) << "sigma = " << expected.sigma;
    EXPECT_NEAR(state.plastic_strain(0), expected.ep, 1e-12);
    EXPECT_NEAR(state.plastic_strain(1), -expected.ep / 2, 1e-12);
    EXPECT_NEAR(state.plastic_strain(2), -expected.ep / 2, 1e-12);
  }
}
} // namespace j2_test

/// Reference: uniaxial stress with linear isotropic hardening, closed form. Loading past yield,
/// sigma = sigma_y + H eqps; unloading is elastic (eqps constant) until the reversed stress reaches
/// -(sigma_y + H eqps_1) (isotropic hardening: the yield surface grew, it did not move); further
/// compression yields again with eqps = eqps_1 + (|sigma| - sigma_1) / H, the axial plastic strain
/// falling by the same amount. Radial return is exact on this path (the deviator keeps its
/// direction within each increment), so every increment matches to round-off whatever its size.
TEST(J2Plasticity, UniaxialTensionUnloadingAndReversedYieldMatchTheClosedForm)
{
  const double H = j2_test::young / 20;
  const fem::Material m = j2_test::hardening_steel(H);
  std::vector<j2_test::UniaxialState> path;
  const double sigma_1 = 1.6 * j2_test::yield, eqps_1 = (sigma_1 - j2_test::yield) / H;
  for (int i = 1; i <= 8; ++i) // loading, the first increments elastic
  {
    const double sigma = sigma_1 * i / 8;
    const double eqps = std::max(0.0, (sigma - j2_test::yield) / H);
    path.push_back({sigma, eqps, eqps});
  }
  for (int i = 1; i <= 12; ++i) // unloading to -1.9 sigma_y: elastic down to -sigma_1, then yield
  {
    const double sigma = sigma_1 - (sigma_1 + 1.9 * j2_test::yield) * i / 12;
    const double reversed = std::max(0.0, (-sigma - sigma_1) / H);
    path.push_back({sigma, eqps_1 - reversed, eqps_1 + reversed});
  }
  j2_test::follow(m, path);
}

/// Reference: uniaxial stress with linear kinematic hardening, closed form (Simo and Hughes 1.4;
/// the Bauschinger effect). Loading past yield, sigma = sigma_y + H eqps as with isotropic
/// hardening; but the yield surface moves with the back stress alpha = H eqps and keeps its
/// radius sigma_y, so the reversed yield comes at sigma_1 - 2 sigma_y (not at -sigma_1), and
/// further compression follows sigma = alpha - sigma_y with alpha = H (eqps_1 - reversed plastic
/// strain) while eqps grows. The back stress is a deviator: alpha_xx = 2/3 H ep.
TEST(J2Plasticity, KinematicHardeningMovesTheYieldSurface)
{
  const double H = j2_test::young / 20;
  fem::Material m = j2_test::hardening_steel(H);
  m.plastic.kinematic = true;
  std::vector<j2_test::UniaxialState> path;
  const double sigma_1 = 1.6 * j2_test::yield, eqps_1 = (sigma_1 - j2_test::yield) / H;
  for (int i = 1; i <= 8; ++i)
  {
    const double sigma = sigma_1 * i / 8;
    const double eqps = std::max(0.0, (sigma - j2_test::yield) / H);
    path.push_back({sigma, eqps, eqps});
  }
  const double reversed_yield = sigma_1 - 2 * j2_test::yield; // -0.4 sigma_y
  for (int i = 1; i <= 12; ++i) // down to -1.0 sigma_y: elastic to sigma_1 - 2 sigma_y, then yield
  {
    const double sigma = sigma_1 - (sigma_1 + 1.0 * j2_test::yield) * i / 12;
    const double reversed = std::max(0.0, (reversed_yield - sigma) / H);
    path.push_back({sigma, eqps_1 - reversed, eqps_1 + reversed});
  }
  j2_test::follow(m, path);
  fem::PlasticPointState state;
  for (const j2_test::UniaxialState& s : path)
    state = fem::j2_return(m, s.strain(), 0, state).state;
  // alpha_xx = 2/3 H ep (deviatoric, its trace zero).
  EXPECT_NEAR(state.back_stress(0), 2.0 / 3 * H * state.plastic_strain(0), 1e-8 * j2_test::yield);
  EXPECT_NEAR(state.back_stress.head<3>().sum(), 0, 1e-8 * j2_test::yield);
}

/// Reference: the same closed form with a three-segment table walked in one increment (the
/// return finds the segment its answer lies on), and perfect plasticity beyond the last point:
/// sigma stays at the last yield stress however far the strain goes.
TEST(J2Plasticity, PiecewiseLinearTableIsWalkedAndPerfectlyPlasticBeyondItsEnd)
{
  fem::Material m{j2_test::young, j2_test::poisson};
  m.plastic.stress = {2.5e8, 3.0e8, 3.2e8};
  m.plastic.plastic_strain = {0, 0.01, 0.05};
  // sigma = 3.1e8 lies on the second segment: eqps = 0.01 + (0.1e8 / 0.2e8) 0.04 = 0.03.
  j2_test::follow(m, {{3.1e8, 0.03, 0.03}});
  // Strain of eqps 0.2 at the last stress, reached from rest in one increment.
  j2_test::follow(m, {{3.2e8, 0.2, 0.2}});
}

/// Reference: central differences of the stress of j2_return (from a yielded committed state,
/// at a general strain that yields again). The consistent tangent is the exact derivative of
/// the return, so the two agree to the differences' truncation and round-off (step 1e-9 on
/// strains of 1e-3: about 1e-6 relative).
TEST(J2Plasticity, ConsistentTangentIsTheDerivativeOfTheReturn)
{
  const fem::Material m = j2_test::hardening_steel(j2_test::young / 50);
  fem::PlasticPointState committed;
  committed.plastic_strain << 1e-3, -4e-4, -6e-4, 2e-4, -1e-4, 3e-4;
  committed.equivalent_plastic_strain = 1.2e-3;
  fem::Voigt strain;
  strain << 4.1e-3, -1.3e-3, -1.1e-3, 1.5e-3, -0.6e-3, 0.9e-3;
  const double thermal = 1e7;
  Eigen::Matrix<double, 6, 6> C;
  const fem::J2Update update = fem::j2_return(m, strain, thermal, committed, &C);
  ASSERT_TRUE(update.plastic);
  Eigen::Matrix<double, 6, 6> numeric;
  const double h = 1e-9;
  for (int j = 0; j < 6; ++j)
  {
    fem::Voigt plus = strain, minus = strain;
    plus(j) += h;
    minus(j) -= h;
    numeric.col(j) =
        (fem::j2_return(m, plus, thermal, committed).stress - fem::j2_return(m, minus, thermal, committed).stress) /
        (2 * h);
  }
  EXPECT_LE((C - numeric).norm(), 1e-6 * C.norm());
  // The tangent of associative J2 flow is symmetric, and softer than the elastic matrix.
  EXPECT_LE((C - C.transpose()).norm(), 1e-12 * C.norm());
  EXPECT_LT(C.norm(), m.elasticity_matrix().norm());
}

/// Reference: below yield the return is Hooke's law with the thermal stress, and the state
/// is unchanged.
TEST(J2Plasticity, BelowYieldTheReturnIsElastic)
{
  const fem::Material m = j2_test::hardening_steel(j2_test::young / 20);
  fem::Voigt strain;
  strain << 3e-4, -1e-4, 0.5e-4, 2e-4, 0, -1e-4;
  const fem::J2Update update = fem::j2_return(m, strain, 5e6, {});
  fem::Voigt expected = m.elasticity_matrix() * strain;
  expected.head<3>().array() -= 5e6;
  EXPECT_FALSE(update.plastic);
  EXPECT_LE((update.stress - expected).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(update.state.equivalent_plastic_strain, 0);
}

/// Malformed tables are refused by Material::check with the place named.
TEST(J2Plasticity, MalformedTablesAreRefused)
{
  fem::Material m = j2_test::hardening_steel(1e9);
  m.plastic.plastic_strain = {0.01, 0.2};
  EXPECT_THROW(m.check("body 'block'"), Error);
  m.plastic.plastic_strain = {0, 0.2, 0.1};
  m.plastic.stress = {2.5e8, 2.6e8, 2.7e8};
  EXPECT_THROW(m.check("body 'block'"), Error);
  m.plastic.plastic_strain = {0, 1e-6};
  m.plastic.stress = {2.5e8, 1e3}; // softening far faster than 3 G
  EXPECT_THROW(m.check("body 'block'"), Error);
}
