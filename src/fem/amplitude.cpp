#include "fem/amplitude.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::fem
{
double Amplitude::value(double t) const
{
  const double s = t - shift_x;
  if (s <= points.front().first)
    return points.front().second + shift_y;
  if (s >= points.back().first)
    return points.back().second + shift_y;
  // The first point beyond s; the one before it is at or before s.
  const auto after = std::upper_bound(points.begin(), points.end(), s,
                                      [](double x, const std::pair<double, double>& p) { return x < p.first; });
  const auto before = after - 1;
  const double w = (s - before->first) / (after->first - before->first);
  return (1 - w) * before->second + w * after->second + shift_y;
}

void Amplitude::check() const
{
  FETICON_CHECK(points.size() >= 2,
                where << ": an amplitude needs at least two (time, value) points, it has " << points.size());
  FETICON_CHECK(std::isfinite(shift_x) && std::isfinite(shift_y), where << ": the shifts must be finite");
  for (size_t k = 0; k < points.size(); ++k)
  {
    FETICON_CHECK(std::isfinite(points[k].first) && std::isfinite(points[k].second),
                  where << ": point " << k + 1 << " of the amplitude is not finite");
    FETICON_CHECK(k == 0 || points[k].first >= points[k - 1].first,
                  where << ": the amplitude's times decrease at point " << k + 1 << " (" << points[k].first << " after "
                        << points[k - 1].first << ")");
  }
}
} // namespace feticon::fem
