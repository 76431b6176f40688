/// Tests of the fit of Hertz's elliptic profile (pressure_profile.hpp).
/// References: samples of p(r) = p0 sqrt(1 - r^2/a^2) with a and p0 chosen here, so the fit
/// must return a to round-off; the threshold and the degenerate cases by construction.

#include "problems/pressure_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace feticon::problems
{
namespace
{
std::vector<ProfilePoint> ellipse(double a, double p0, int n, double r_max)
{
  std::vector<ProfilePoint> samples;
  for (int i = 0; i < n; ++i)
  {
    const double r = r_max * i / (n - 1);
    samples.push_back({r, r < a ? p0 * std::sqrt(1 - r * r / (a * a)) : 0.0});
  }
  return samples;
}
} // namespace

TEST(PressureProfile, FitRecoversTheHalfWidthOfAnEllipse)
{
  // Unloaded samples beyond a must not enter the fit: half of them lie there.
  const auto samples = ellipse(0.068, 3.7e9, 41, 0.136);
  EXPECT_DOUBLE_EQ(peak_pressure(samples), 3.7e9);
  EXPECT_NEAR(fitted_half_width(samples), 0.068, 1e-12);
}

TEST(PressureProfile, SamplesBelowTheThresholdAreNotLoaded)
{
  // A node with 1e-4 p0 far outside (below loaded_fraction = 1e-3) leaves a unchanged; one
  // with 1e-2 p0 enters the fit and moves a outward.
  auto samples = ellipse(1.0, 1.0, 21, 0.95);
  samples.push_back({1.5, 1e-4});
  EXPECT_NEAR(fitted_half_width(samples), 1.0, 1e-12);
  samples.back().pressure = 1e-2;
  EXPECT_GT(fitted_half_width(samples), 1.01);
}

TEST(PressureProfile, NoEllipseGivesZero)
{
  EXPECT_EQ(fitted_half_width({}), 0.0);
  EXPECT_EQ(fitted_half_width({{0.1, 5.0}}), 0.0);
  // Pressure growing with r: p^2 has a positive slope, no ellipse.
  EXPECT_EQ(fitted_half_width({{0.0, 1.0}, {0.1, 2.0}, {0.2, 3.0}}), 0.0);
  // Two samples at one r: the fit's normal equations are singular.
  EXPECT_EQ(fitted_half_width({{0.1, 1.0}, {0.1, 2.0}}), 0.0);
}
} // namespace feticon::problems
