#include "problems/hertz.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::problems
{
fem::Problem hertz_problem(const HertzParameters& parameters)
{
  FETICON_CHECK(std::isfinite(parameters.line_load) && parameters.line_load > 0,
                "hertz: line_load = " << parameters.line_load << " N/m must be positive");
  fem::Problem p;
  p.name = "hertz";
  p.mesh = generate_hertz(parameters.mesh, &p.mesh_from_cache);
  p.materials = {parameters.material, parameters.block()}; // bodies "cylinder", "block"
  p.eliminated = {false, false, true};
  p.dirichlet = {
      {"symmetry", {0.0, std::nullopt, std::nullopt}},
      {"support", {0.0, 0.0, std::nullopt}},
  };
  const double half_load = 0.5 * parameters.line_load;
  const double width = parameters.mesh.cylinder_width;
  p.tractions = {{"load", Eigen::Vector3d(0, -half_load / width, 0)}};
  p.contacts = {{"cylinder_contact", "block_contact"}};
  p.validate();
  return p;
}

HertzAnalytic hertz_analytic(const HertzParameters& parameters)
{
  HertzAnalytic h;
  h.effective_modulus = fem::contact_modulus(parameters.material, parameters.block());
  const double R = parameters.mesh.cylinder_radius; // 1/R = 1/R1 + 1/inf
  h.half_width = std::sqrt(4 * parameters.line_load * R / (M_PI * h.effective_modulus));
  h.peak_pressure = 2 * parameters.line_load / (M_PI * h.half_width);
  return h;
}

double HertzAnalytic::pressure(double x) const
{
  const double r = x / half_width;
  return std::abs(r) < 1 ? peak_pressure * std::sqrt(1 - r * r) : 0.0;
}

double hertz_axis_approach(const fem::Problem& problem, const la::Vector& u)
{
  const auto& nodes = problem.mesh.node_set("load");
  double sum = 0;
  for (int32_t n : nodes)
    sum += u(3 * n + 1);
  return -sum / static_cast<double>(nodes.size());
}

HertzComparison compare_with_hertz(const HertzParameters& parameters, std::vector<ProfilePoint> samples)
{
  const HertzAnalytic analytic = hertz_analytic(parameters);
  HertzComparison h;
  h.a_analytic = analytic.half_width;
  h.p0_analytic = analytic.peak_pressure;
  h.applied_load = 0.5 * parameters.line_load * parameters.mesh.thickness;
  if (samples.empty())
    return h;
  std::ranges::sort(samples, {}, &ProfilePoint::r);
  h.p_peak_computed = peak_pressure(samples);
  h.a_computed = fitted_half_width(samples);
  for (size_t i = 0; i + 1 < samples.size(); ++i)
    if (samples[i].r <= h.a_computed && h.a_computed <= samples[i + 1].r)
      h.element_size = samples[i + 1].r - samples[i].r;

  auto interpolate = [&](double x) {
    if (x <= samples.front().r)
      return samples.front().pressure;
    for (size_t i = 0; i + 1 < samples.size(); ++i)
      if (x <= samples[i + 1].r)
      {
        const ProfilePoint& s0 = samples[i];
        const ProfilePoint& s1 = samples[i + 1];
        return s1.r > s0.r ? s0.pressure + (s1.pressure - s0.pressure) * (x - s0.r) / (s1.r - s0.r) : s0.pressure;
      }
    return 0.0;
  };
  constexpr int points = 400;
  double sum_sq = 0;
  for (int k = 0; k < points; ++k)
  {
    const double x = analytic.half_width * (k + 0.5) / points;
    const double e = interpolate(x) - analytic.pressure(x);
    sum_sq += e * e;
  }
  h.rms_error_over_p0 = std::sqrt(sum_sq / points) / analytic.peak_pressure;
  return h;
}
} // namespace feticon::problems
