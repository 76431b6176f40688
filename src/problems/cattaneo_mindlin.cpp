#include "problems/cattaneo_mindlin.hpp"

#include "common/error.hpp"
#include "problems/pressure_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace feticon::problems
{
double CattaneoMindlin::shear(double x) const
{
  const double r = x / half_width;
  if (std::abs(r) >= 1)
    return 0;
  double q = coefficient * peak_pressure * std::sqrt(1 - r * r);
  if (std::abs(x) < stick_half_width)
    q -= coefficient * peak_pressure * (stick_half_width / half_width) *
        std::sqrt(1 - std::pow(x / stick_half_width, 2));
  return -q;
}

CattaneoMindlin cattaneo_mindlin(double coefficient, double peak_pressure, double half_width, double line_load,
                                 double tangential_load)
{
  FETICON_CHECK(coefficient > 0 && line_load > 0 && tangential_load >= 0,
                "Cattaneo-Mindlin: need mu > 0, P > 0 and Q >= 0");
  const double ratio = std::min(tangential_load / (coefficient * line_load), 1.0);
  return {coefficient, peak_pressure, half_width, half_width * std::sqrt(1 - ratio)};
}

namespace
{
/// c from the samples: the midpoints between the outermost sticking loaded samples and their
/// sliding neighbours, on either side (0 if none sticks).
double computed_stick_half_width(const std::vector<SurfaceSample>& samples, const std::vector<double>& x,
                                 const std::vector<char>& loaded)
{
  std::vector<size_t> order(samples.size());
  for (size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::ranges::sort(order, [&](size_t a, size_t b) { return x[a] < x[b]; });
  std::vector<size_t> contact; // loaded samples by x
  for (size_t i : order)
    if (loaded[i])
      contact.push_back(i);
  size_t first = contact.size(), last = 0;
  for (size_t k = 0; k < contact.size(); ++k)
    if (!samples[contact[k]].slipping)
    {
      first = std::min(first, k);
      last = k;
    }
  if (first == contact.size())
    return 0;
  const double left = first > 0 ? 0.5 * (x[contact[first - 1]] + x[contact[first]]) : x[contact[first]];
  const double right = last + 1 < contact.size() ? 0.5 * (x[contact[last]] + x[contact[last + 1]]) : x[contact[last]];
  return 0.5 * (right - left);
}

/// The computed shear along x at -at, linear between the samples (0 outside them).
double mirrored_shear(const std::vector<SurfaceSample>& samples, const std::vector<double>& x, double at)
{
  double below = -std::numeric_limits<double>::infinity(), above = std::numeric_limits<double>::infinity();
  double q_below = 0, q_above = 0;
  for (size_t i = 0; i < samples.size(); ++i)
  {
    if (x[i] <= -at && x[i] > below)
      below = x[i], q_below = samples[i].shear_x;
    if (x[i] >= -at && x[i] < above)
      above = x[i], q_above = samples[i].shear_x;
  }
  if (!std::isfinite(below) || !std::isfinite(above))
    return 0;
  return above > below ? q_below + (q_above - q_below) * (-at - below) / (above - below) : q_below;
}
} // namespace

nlohmann::ordered_json cattaneo_mindlin_figures(const CattaneoMindlin& theory,
                                                const std::vector<SurfaceSample>& samples, const std::vector<double>& x,
                                                double applied_tangential_force)
{
  double peak = 0;
  for (const SurfaceSample& s : samples)
    peak = std::max(peak, s.pressure);
  std::vector<char> loaded(samples.size());
  double force = 0, sum_sq = 0, symmetric_sq = 0, antisymmetric_sq = 0;
  int within = 0, sliding = 0, sticking = 0;
  for (size_t i = 0; i < samples.size(); ++i)
  {
    const SurfaceSample& s = samples[i];
    loaded[i] = s.pressure > loaded_fraction * peak;
    force += s.friction_force_x;
    if (loaded[i])
      (s.slipping ? sliding : sticking) += 1;
    if (std::abs(x[i]) <= theory.half_width)
    {
      const double mirrored = mirrored_shear(samples, x, x[i]);
      sum_sq += std::pow(s.shear_x - theory.shear(x[i]), 2);
      symmetric_sq += std::pow(0.5 * (s.shear_x + mirrored) - theory.shear(x[i]), 2);
      antisymmetric_sq += std::pow(0.5 * (s.shear_x - mirrored), 2);
      ++within;
    }
  }
  const double mu_p0 = theory.coefficient * theory.peak_pressure;
  auto rms = [&](double sum) { return within > 0 ? std::sqrt(sum / within) / mu_p0 : 0.0; };
  return {{"coefficient", theory.coefficient},
          {"tangential_force", force},
          {"applied_tangential_force", applied_tangential_force},
          {"tangential_force_error", std::abs(force + applied_tangential_force) / applied_tangential_force},
          {"stick_half_width_computed", computed_stick_half_width(samples, x, loaded)},
          {"stick_half_width_analytic", theory.stick_half_width},
          {"shear_rms_error_over_mu_p0", rms(sum_sq)},
          {"shear_symmetric_rms_error_over_mu_p0", rms(symmetric_sq)},
          {"shear_antisymmetric_rms_over_mu_p0", rms(antisymmetric_sq)},
          {"slipping_nodes", sliding},
          {"sticking_nodes", sticking}};
}
} // namespace feticon::problems
