#include "problems/pressure_profile.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::problems
{
double peak_pressure(const std::vector<ProfilePoint>& samples)
{
  double peak = 0;
  for (const ProfilePoint& s : samples)
    peak = std::max(peak, s.pressure);
  return peak;
}

double fitted_half_width(const std::vector<ProfilePoint>& samples)
{
  // p^2 = A + B r^2 over the loaded samples; a = sqrt(-A / B).
  const double threshold = loaded_fraction * peak_pressure(samples);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ProfilePoint& s : samples)
    if (s.pressure > threshold)
    {
      const double X = s.r * s.r, Y = s.pressure * s.pressure;
      n += 1, sx += X, sy += Y, sxx += X * X, sxy += X * Y;
    }
  if (n < 2)
    return 0;
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / n;
  return slope < 0 && intercept > 0 ? std::sqrt(-intercept / slope) : 0;
}
} // namespace feticon::problems
