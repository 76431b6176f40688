#include "problems/hertz.hpp"

#include "common/error.hpp"
#include "fem/assembler.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace feticon::problems
{
namespace
{
/// Cattaneo and Mindlin's tangential load acts in the contact plane; ours, Q on the load face
/// y = R1, has the moment Q R1 about the contact, which the contact would take as a tilted
/// pressure (measured: the contact zone shifted by one element, 8 % of p0 at its edges). A
/// normal traction t_y = k x on the load face, k = 3 Q R1 / (2 Xc^3) per unit thickness,
/// cancels it: its moment int x t_y dx over [-Xc, Xc] is Q R1 and its resultant 0. As
/// consistent nodal forces of the load faces (exact for a linear traction: sum x_i f_i =
/// int x t_y). `force` = Q times the thickness (N).
std::vector<fem::NodalForce> moment_free_couple(const mesh::Mesh& mesh, double force, double radius)
{
  double half_width = 0;
  for (const mesh::Face& face : mesh.face_set("load"))
    for (int32_t node : face)
      half_width = std::max(half_width, std::abs(mesh.nodes(node, 0)));
  std::map<int32_t, double> nodal;
  for (const mesh::Face& face : mesh.face_set("load"))
  {
    // An edge of a 2D cell (one node at each of two abscissae) or a face of the hex8 layer
    // (two at each): its area, over the nodes at an abscissa, times the linear traction's
    // consistent weights.
    double x_min = 1e300, x_max = -1e300, z_min = 1e300, z_max = -1e300;
    for (int32_t node : face)
    {
      x_min = std::min(x_min, mesh.nodes(node, 0)), x_max = std::max(x_max, mesh.nodes(node, 0));
      z_min = std::min(z_min, mesh.nodes(node, 2)), z_max = std::max(z_max, mesh.nodes(node, 2));
    }
    const bool edge = mesh::is_line(face.kind);
    const double thickness = edge ? mesh.planar.thickness : z_max - z_min, length = x_max - x_min;
    const double k = 3 * force * radius / (2 * std::pow(half_width, 3) * thickness); // Pa/m
    const double per_abscissa = edge ? 1.0 : 0.5;
    for (int32_t node : face)
    {
      const bool left = mesh.nodes(node, 0) == x_min;
      const double t_here = k * (left ? x_min : x_max), t_other = k * (left ? x_max : x_min);
      nodal[node] += per_abscissa * thickness * length / 6 * (2 * t_here + t_other);
    }
  }
  std::vector<fem::NodalForce> out;
  for (const auto& [node, value] : nodal)
    out.push_back({node, 1, value});
  return out;
}
} // namespace

fem::Problem hertz_problem(const HertzParameters& parameters)
{
  FETICON_CHECK(std::isfinite(parameters.line_load) && parameters.line_load > 0,
                "hertz: line_load = " << parameters.line_load << " N/m must be positive");
  FETICON_CHECK(std::isfinite(parameters.tangential_load) && parameters.tangential_load >= 0,
                "hertz: tangential_load = " << parameters.tangential_load << " N/m must be >= 0");
  FETICON_CHECK(std::isfinite(parameters.tangential_displacement) && parameters.tangential_displacement >= 0,
                "hertz: tangential_displacement = " << parameters.tangential_displacement << " m must be >= 0");
  const bool pulled = parameters.tangential_load > 0, slid = parameters.tangential_displacement > 0;
  FETICON_CHECK(!(pulled && slid), "hertz: give a tangential load or a tangential displacement, not both");
  FETICON_CHECK(std::isfinite(parameters.tangential_couple) && parameters.tangential_couple >= 0,
                "hertz: tangential_couple = " << parameters.tangential_couple << " N/m must be >= 0");
  FETICON_CHECK(parameters.tangential_couple == 0 || slid,
                "hertz: tangential_couple balances a tangential displacement's force; give tangential_displacement");
  FETICON_CHECK(parameters.tangential_couple <= parameters.friction_coefficient * parameters.line_load,
                "hertz: tangential_couple = " << parameters.tangential_couple
                                              << " N/m exceeds what friction can carry, mu line_load = "
                                              << parameters.friction_coefficient * parameters.line_load << " N/m");
  if (const std::optional<double> unloaded = parameters.unloaded_tangential_load)
  {
    FETICON_CHECK(pulled && *unloaded > 0 && *unloaded < parameters.tangential_load,
                  "hertz: tangential_unload = " << *unloaded << " N/m must lie in (0, tangential_load = "
                                                << parameters.tangential_load << " N/m)");
    FETICON_CHECK(parameters.tangential_load < parameters.friction_coefficient * parameters.line_load,
                  "hertz: tangential_unload needs partial slip at the peak: tangential_load = "
                      << parameters.tangential_load << " N/m must be below mu line_load = "
                      << parameters.friction_coefficient * parameters.line_load << " N/m");
  }
  FETICON_CHECK(!slid || parameters.friction_coefficient > 0,
                "hertz: a tangential displacement needs Coulomb friction (its couple balances the full "
                "slide's force mu P)");
  fem::Problem p;
  p.name = "hertz";
  const HertzMeshParameters& mesh = parameters.mesh;
  FETICON_CHECK(mesh.full || !(pulled || slid),
                "hertz: a tangential load or displacement needs the full model (HertzMeshParameters::full)");
  p.mesh = generate_hertz(mesh, &p.mesh_from_cache);
  p.materials = {parameters.material, parameters.block()}; // bodies "cylinder", "block"
  p.eliminated = {false, false, true};
  fem::Step& pressed = p.steps.front();
  pressed.dirichlet = {{"support", {0.0, 0.0, std::nullopt}}};
  if (!mesh.full)
    pressed.dirichlet.insert(pressed.dirichlet.begin(), {"symmetry", {0.0, std::nullopt, std::nullopt}});
  if (slid) // held along x while pressed, then moved
    pressed.dirichlet.push_back({"load", {0.0, std::nullopt, std::nullopt}});
  // The load face spans x in [0, Xc] (half model, which carries Q/2) or [-Xc, Xc].
  const double width = (mesh.full ? 2 : 1) * parameters.mesh.cylinder_width;
  const double modelled = mesh.full ? 1.0 : 0.5;
  const Eigen::Vector3d normal(0, -modelled * parameters.line_load / width, 0);
  pressed.tractions = {{"load", normal}};
  const double thickness = parameters.mesh.thickness, radius = parameters.mesh.cylinder_radius;
  if (pulled) // a second step: the normal load held, the tangential one added
  {
    fem::Step pulling;
    pulling.dirichlet = pressed.dirichlet;
    pulling.tractions = {{"load", normal + Eigen::Vector3d(parameters.tangential_load / width, 0, 0)}};
    pulling.nodal_forces = moment_free_couple(p.mesh, parameters.tangential_load * thickness, radius);
    pulling.increments = 1;
    p.steps.push_back(std::move(pulling));
  }
  if (const std::optional<double> unloaded = parameters.unloaded_tangential_load) // a third step
  {
    fem::Step unloading = p.steps.back();
    unloading.tractions = {{"load", normal + Eigen::Vector3d(*unloaded / width, 0, 0)}};
    unloading.nodal_forces = moment_free_couple(p.mesh, *unloaded * thickness, radius);
    p.steps.push_back(std::move(unloading));
  }
  if (slid)
  {
    fem::Step sliding;
    sliding.dirichlet = pressed.dirichlet;
    sliding.dirichlet.back() = {"load", {parameters.tangential_displacement, std::nullopt, std::nullopt}};
    sliding.tractions = {{"load", normal}};
    sliding.nodal_forces = moment_free_couple(p.mesh, parameters.compared_tangential_load() * thickness, radius);
    sliding.increments = 1;
    p.steps.push_back(std::move(sliding));
  }
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

namespace
{
/// The mean of u's component `component` over the load face's nodes.
double load_face_mean(const fem::Problem& problem, const la::Vector& u, int component)
{
  const auto& nodes = problem.mesh.node_set("load");
  double sum = 0;
  for (int32_t n : nodes)
    sum += u(3 * n + component);
  return sum / static_cast<double>(nodes.size());
}
} // namespace

double hertz_axis_approach(const fem::Problem& problem, const la::Vector& u) { return -load_face_mean(problem, u, 1); }

double hertz_load_face_shift(const fem::Problem& problem, const la::Vector& u) { return load_face_mean(problem, u, 0); }

double hertz_load_face_support_force(const fem::Problem& problem, const la::Vector& u, fem::Kinematics kinematics)
{
  const fem::Assembler assembler(problem.mesh, fem::whole_mesh_domain(problem.mesh), problem.materials, kinematics);
  const la::Vector f_int = assembler.internal_force(u);
  double force = 0;
  for (int32_t n : problem.mesh.node_set("load"))
    force += f_int(3 * n);
  return force;
}

HertzComparison compare_with_hertz(const HertzParameters& parameters, std::vector<ProfilePoint> samples)
{
  const HertzAnalytic analytic = hertz_analytic(parameters);
  HertzComparison h;
  h.a_analytic = analytic.half_width;
  h.p0_analytic = analytic.peak_pressure;
  h.applied_load = (parameters.mesh.full ? 1.0 : 0.5) * parameters.line_load * parameters.mesh.thickness;
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
