#include "fem/yield_curve.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::fem
{
size_t YieldCurve::segment(double eqps) const
{
  // The first point after eqps, less one: the segment that starts at or below it.
  const auto after = std::upper_bound(plastic_strain.begin(), plastic_strain.end(), eqps);
  return after == plastic_strain.begin() ? 0 : static_cast<size_t>(after - plastic_strain.begin()) - 1;
}

double YieldCurve::hardening(double eqps) const
{
  const size_t k = segment(eqps);
  if (k + 1 >= stress.size())
    return 0;
  return (stress[k + 1] - stress[k]) / (plastic_strain[k + 1] - plastic_strain[k]);
}

double YieldCurve::yield_stress(double eqps) const
{
  const size_t k = segment(eqps);
  return stress[k] + hardening(eqps) * (eqps - plastic_strain[k]);
}

void YieldCurve::check(const std::string& where) const
{
  FETICON_CHECK(!stress.empty() && stress.size() == plastic_strain.size(),
                where << ": the plastic table has no points");
  FETICON_CHECK(plastic_strain.front() == 0,
                where << ": the plastic table's first equivalent plastic strain is " << plastic_strain.front()
                      << ", not 0: its first point is the initial yield stress");
  for (size_t k = 0; k < stress.size(); ++k)
  {
    FETICON_CHECK(std::isfinite(stress[k]) && stress[k] > 0,
                  where << ": the plastic table's yield stress " << stress[k] << " (point " << k + 1
                        << ") must be positive");
    FETICON_CHECK(k == 0 || (std::isfinite(plastic_strain[k]) && plastic_strain[k] > plastic_strain[k - 1]),
                  where << ": the plastic table's equivalent plastic strains must increase (point " << k + 1 << ": "
                        << plastic_strain[k] << " after " << plastic_strain[k - 1] << ")");
  }
}
} // namespace feticon::fem
