#include "problems/hertz.hpp"

#include "common/error.hpp"

#include <cmath>

namespace feticon::problems
{
fem::Problem hertz_problem(const HertzParameters& parameters)
{
  FETICON_CHECK(std::isfinite(parameters.line_load) && parameters.line_load > 0,
                "hertz: line_load = " << parameters.line_load << " N/m must be positive");
  fem::Problem p;
  p.name = "hertz";
  p.mesh = mesh::generate_hertz(parameters.mesh);
  p.materials.assign(p.mesh.n_bodies(), parameters.material);
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
  const fem::Material& m = parameters.material;
  HertzAnalytic h;
  h.effective_modulus = m.young / (2 * (1 - m.poisson * m.poisson));
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
} // namespace feticon::problems
