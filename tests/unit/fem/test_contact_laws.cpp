/// Tests of the pressure-overclosure laws (fem/contact_interaction.hpp). References: the laws'
/// formulas in CalculiX's manual (*SURFACE BEHAVIOR: p = p0 exp(beta d), beta = ln(100) / c0;
/// the linear law's asymptote K d - sigma_inf; a table interpolated linearly), worked by hand.

#include "fem/contact_interaction.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace feticon::fem
{
TEST(ContactLaws, LinearTangentIsTheLawShiftedBySigmaInf)
{
  const NormalLaw law{NormalLawKind::linear, 1e7, 3.0};
  for (const double d : {-1.0, 0.0, 1e-3})
  {
    const NormalLaw::Tangent line = law.tangent(d);
    EXPECT_EQ(line.stiffness, 1e7);
    EXPECT_DOUBLE_EQ(line.zero_overclosure, 3e-7);
  }
  EXPECT_DOUBLE_EQ(law.overclosure_at(97.0), 1e-5); // (p + sigma_inf) / K
}

TEST(ContactLaws, ExponentialTangentTouchesTheCurve)
{
  NormalLaw law;
  law.kind = NormalLawKind::exponential;
  law.c0 = 1e-3;
  law.p0 = 2e6;
  const double beta = std::log(100.0) / law.c0;
  // Node-to-face: p = p0 exp(beta d) from d = -c0 on; the line p0 e^(beta d) (1 + beta (x - d)).
  const NormalLaw::Tangent at = law.tangent(2e-4);
  EXPECT_NEAR(at.stiffness, beta * law.p0 * std::exp(beta * 2e-4), 1e-9 * at.stiffness);
  EXPECT_NEAR(at.zero_overclosure, 2e-4 - 1 / beta, 1e-15);
  EXPECT_NEAR(law.tangent(-5e-3).zero_overclosure, -law.c0 - 1 / beta, 1e-15); // springs start at -c0
  EXPECT_NEAR(law.tangent(-5e-3).stiffness, beta * law.p0 / 100, 1e-9 * beta * law.p0);
  EXPECT_NEAR(law.overclosure_at(law.p0 * 10), law.c0 / 2, 1e-15); // ln 10 / beta
  // Face-to-face: p = p0 (exp(beta d) - 1) from d = 0 on, so its line at d = 0 starts there.
  law.zero_at_contact = true;
  EXPECT_NEAR(law.tangent(-1.0).zero_overclosure, 0.0, 1e-18);
  EXPECT_NEAR(law.tangent(-1.0).stiffness, beta * law.p0, 1e-9 * beta * law.p0);
  EXPECT_NEAR(law.overclosure_at(law.p0 * 9), law.c0 / 2, 1e-15);
}

TEST(ContactLaws, TabularTangentIsTheSegmentsLine)
{
  NormalLaw law;
  law.kind = NormalLawKind::tabular;
  law.table = {{0, 0}, {5e-4, 5e7}, {1e-3, 2e8}};
  const NormalLaw::Tangent first = law.tangent(2e-4), second = law.tangent(7e-4);
  EXPECT_NEAR(first.stiffness, 1e11, 1e-3);
  EXPECT_NEAR(first.zero_overclosure, 0.0, 1e-18);
  EXPECT_NEAR(second.stiffness, 3e11, 1e-3);
  EXPECT_NEAR(second.zero_overclosure, 5e-4 - 5e7 / 3e11, 1e-18);
  // Beyond the table: its first and last segments.
  EXPECT_NEAR(law.tangent(-1.0).stiffness, 1e11, 1e-3);
  EXPECT_NEAR(law.tangent(1.0).stiffness, 3e11, 1e-3);
  EXPECT_NEAR(law.overclosure_at(1e8), 5e-4 + 5e7 / 3e11, 1e-18);
  EXPECT_NEAR(law.overclosure_at(2.5e7), 2.5e-4, 1e-18);
}
} // namespace feticon::fem
