#include "problems/cattaneo_mindlin.hpp"

#include "common/error.hpp"
#include "problems/pressure_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace feticon::problems
{
namespace
{
/// Cattaneo's traction magnitude at x with stick half-width c (Pa).
double cattaneo_traction(const CattaneoMindlin& t, double x, double c)
{
  const double r = x / t.half_width;
  if (std::abs(r) >= 1)
    return 0;
  double q = t.coefficient * t.peak_pressure * std::sqrt(1 - r * r);
  if (std::abs(x) < c)
    q -= t.coefficient * t.peak_pressure * (c / t.half_width) * std::sqrt(1 - std::pow(x / c, 2));
  return q;
}
} // namespace

double CattaneoMindlin::shear(double x) const
{
  if (peak_stick_half_width)
    return -(cattaneo_traction(*this, x, *peak_stick_half_width) - 2 * cattaneo_traction(*this, x, stick_half_width));
  return -cattaneo_traction(*this, x, stick_half_width);
}

CattaneoMindlin cattaneo_mindlin(double coefficient, double peak_pressure, double half_width, double line_load,
                                 double tangential_load, HertzContact contact)
{
  FETICON_CHECK(coefficient > 0 && line_load > 0 && tangential_load >= 0,
                "Cattaneo-Mindlin: need mu > 0, P > 0 and Q >= 0");
  const double ratio = std::min(tangential_load / (coefficient * line_load), 1.0);
  const double c = contact == HertzContact::cylinder ? std::sqrt(1 - ratio) : std::cbrt(1 - ratio);
  return {coefficient, peak_pressure, half_width, half_width * c, std::nullopt};
}

CattaneoMindlin mindlin_deresiewicz(double coefficient, double peak_pressure, double half_width, double line_load,
                                    double peak_load, double tangential_load)
{
  FETICON_CHECK(coefficient > 0 && line_load > 0 && peak_load < coefficient * line_load && tangential_load > 0 &&
                    tangential_load < peak_load,
                "Mindlin-Deresiewicz: need mu > 0, P > 0 and 0 < Q < Q* < mu P");
  CattaneoMindlin out = cattaneo_mindlin(coefficient, peak_pressure, half_width, line_load, peak_load);
  out.peak_stick_half_width = out.stick_half_width;
  out.stick_half_width = half_width * std::sqrt(1 - (peak_load - tangential_load) / (2 * coefficient * line_load));
  return out;
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

/// The shear's squared errors over the samples within [-a, a] (or r <= a): against the theory,
/// of the part symmetric across x = 0 against it, and the antisymmetric part.
struct ShearErrors
{
  double sum_sq = 0, symmetric_sq = 0, antisymmetric_sq = 0;
  int within = 0;
  void add(double shear, double mirrored, double theory)
  {
    sum_sq += std::pow(shear - theory, 2);
    symmetric_sq += std::pow(0.5 * (shear + mirrored) - theory, 2);
    antisymmetric_sq += std::pow(0.5 * (shear - mirrored), 2);
    ++within;
  }
  double rms(double sum, const CattaneoMindlin& theory) const
  {
    return within > 0 ? std::sqrt(sum / within) / (theory.coefficient * theory.peak_pressure) : 0.0;
  }
};

/// The `friction` block's keys both geometries share.
nlohmann::ordered_json figures(const CattaneoMindlin& theory, double force, double reaction, double applied,
                               double stick_computed, const ShearErrors& e, int sliding, int sticking)
{
  return {{"coefficient", theory.coefficient},
          {"tangential_force", force},
          {"applied_tangential_force", applied},
          {"tangential_force_error", std::abs(force + applied) / applied},
          {"tangential_reaction", reaction},
          {"tangential_reaction_error", std::abs(reaction + applied) / applied},
          {"stick_half_width_computed", stick_computed},
          {"stick_half_width_analytic", theory.stick_half_width},
          {"shear_rms_error_over_mu_p0", e.rms(e.sum_sq, theory)},
          {"shear_symmetric_rms_error_over_mu_p0", e.rms(e.symmetric_sq, theory)},
          {"shear_antisymmetric_rms_over_mu_p0", e.rms(e.antisymmetric_sq, theory)},
          {"slipping_nodes", sliding},
          {"sticking_nodes", sticking}};
}
} // namespace

double tangential_reaction(const std::vector<SurfaceSample>& samples)
{
  double reaction = 0;
  for (const SurfaceSample& s : samples)
    reaction += s.friction_force_x + s.normal_force_x;
  return reaction;
}

nlohmann::ordered_json cattaneo_mindlin_figures(const CattaneoMindlin& theory,
                                                const std::vector<SurfaceSample>& samples, const std::vector<double>& x,
                                                double applied_tangential_force)
{
  double peak = 0;
  for (const SurfaceSample& s : samples)
    peak = std::max(peak, s.pressure);
  std::vector<char> loaded(samples.size());
  double force = 0;
  const double reaction = tangential_reaction(samples);
  ShearErrors errors;
  int sliding = 0, sticking = 0;
  for (size_t i = 0; i < samples.size(); ++i)
  {
    const SurfaceSample& s = samples[i];
    loaded[i] = s.pressure > loaded_fraction * peak;
    force += s.friction_force_x;
    if (loaded[i])
      (s.slipping ? sliding : sticking) += 1;
    if (std::abs(x[i]) <= theory.half_width)
      errors.add(s.shear_x, mirrored_shear(samples, x, x[i]), theory.shear(x[i]));
  }
  return figures(theory, force, reaction, applied_tangential_force, computed_stick_half_width(samples, x, loaded),
                 errors, sliding, sticking);
}

nlohmann::ordered_json cattaneo_mindlin_sphere_figures(const CattaneoMindlin& theory,
                                                       const std::vector<SurfaceSample>& samples, bool deformed,
                                                       double applied_tangential_force)
{
  double peak = 0;
  for (const SurfaceSample& s : samples)
    peak = std::max(peak, s.pressure);
  // The mirror node of (x, y) is (-x, y) exactly (mesh::mirrored_across_x).
  const auto key = [](double x, double y) { return std::make_pair(std::llround(x * 1e12), std::llround(y * 1e12)); };
  std::map<std::pair<long long, long long>, size_t> by_position;
  for (size_t i = 0; i < samples.size(); ++i)
    by_position[key(samples[i].x, samples[i].y)] = i;
  double force = 0, stick_area = 0, across_sq = 0;
  const double reaction = tangential_reaction(samples);
  ShearErrors errors;
  int sliding = 0, sticking = 0;
  for (const SurfaceSample& s : samples)
  {
    force += s.friction_force_x;
    if (s.pressure > loaded_fraction * peak)
    {
      (s.slipping ? sliding : sticking) += 1;
      stick_area += s.slipping ? 0.0 : s.area;
    }
    const double r = deformed ? std::hypot(s.deformed_x, s.deformed_y) : std::hypot(s.x, s.y);
    if (r > theory.half_width)
      continue;
    const auto mirror = by_position.find(key(-s.x, s.y));
    FETICON_CHECK(mirror != by_position.end(),
                  "Cattaneo-Mindlin: the slave node at (" << s.x << ", " << s.y
                                                          << ") m has no mirror node across x = 0");
    errors.add(s.shear_x, samples[mirror->second].shear_x, theory.shear(r));
    across_sq += s.shear_y * s.shear_y;
  }
  nlohmann::ordered_json out = figures(theory, force, reaction, applied_tangential_force,
                                       std::sqrt(2 * stick_area / M_PI), errors, sliding, sticking);
  out["shear_y_rms_over_mu_p0"] = errors.rms(across_sq, theory);
  return out;
}

std::string cattaneo_mindlin_line(const nlohmann::ordered_json& f, const CattaneoMindlin& theory, double applied,
                                  const std::string& zone)
{
  const double c = f["stick_half_width_computed"].get<double>();
  char line[320];
  if (theory.stick_half_width == 0) // Q >= mu P: nothing to compare c with
  {
    const int sliding = f["slipping_nodes"].get<int>();
    std::snprintf(line, sizeof line,
                  "\nCattaneo-Mindlin, full slide: %d of %d loaded nodes slide, shear RMS error %.2f%% of mu p0, "
                  "friction force %.6g N (mu P %.6g N)",
                  sliding, sliding + f["sticking_nodes"].get<int>(),
                  100 * f["shear_rms_error_over_mu_p0"].get<double>(), f["tangential_force"].get<double>(), applied);
    return line;
  }
  std::snprintf(line, sizeof line,
                "\n%s: stick %s c %.3f mm (analytic %.3f mm, %+.2f%%), shear RMS error %.2f%% of mu p0, "
                "friction force %.6g N, tangential reaction %.9g N (applied %.6g N)",
                theory.peak_stick_half_width ? "Mindlin-Deresiewicz, unloaded" : "Cattaneo-Mindlin", zone.c_str(),
                1e3 * c, 1e3 * theory.stick_half_width, 100 * (c / theory.stick_half_width - 1),
                100 * f["shear_rms_error_over_mu_p0"].get<double>(), f["tangential_force"].get<double>(),
                f["tangential_reaction"].get<double>(), applied);
  return line;
}
} // namespace feticon::problems
