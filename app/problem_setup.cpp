#include "app/problem_setup.hpp"

#include "common/log.hpp"

#include "problems/cantilever_obstacle.hpp"
#include "problems/hertz3d.hpp"

#include <algorithm>
#include <optional>
#include <string>

namespace feticon::app
{
namespace
{
problems::CantileverObstacleParameters cantilever_parameters(const io::Settings& s)
{
  problems::CantileverObstacleParameters p;
  p.gap = s.number("cantilever.gap");
  p.linear_deflection_ratio = s.number("cantilever.load");
  p.cells_along = s.integer("cantilever.cells");
  p.material = {s.number("material.young"), s.number("material.poisson")};
  return p;
}

/// The block's material of a built-in Hertz problem, if `prefix`.block_young or
/// `prefix`.block_poisson is given (the other one from `material`).
std::optional<fem::Material> block_material(const io::Settings& s, const std::string& prefix,
                                            const fem::Material& material)
{
  const std::optional<double> young = s.optional_number(prefix + ".block_young");
  const std::optional<double> poisson = s.optional_number(prefix + ".block_poisson");
  if (!young && !poisson)
    return std::nullopt;
  return fem::Material{young.value_or(material.young), poisson.value_or(material.poisson)};
}
} // namespace

problems::HertzParameters hertz_parameters(const io::Settings& s)
{
  problems::HertzParameters p;
  p.line_load = s.number("hertz.line_load");
  p.mesh.kind = s.text("hertz.mesh") == "tensor" ? problems::HertzMeshKind::tensor : problems::HertzMeshKind::graded;
  p.mesh.refinement = s.number("hertz.refinement");
  p.mesh.element_size = s.number("hertz.element_size");
  p.mesh.master_ratio = s.number("hertz.master_ratio");
  p.mesh.block_width = s.number("hertz.block_width");
  p.mesh.block_depth = s.number("hertz.block_depth");
  p.mesh.growth_ratio = s.number("hertz.growth_ratio");
  p.mesh.cylinder_width = s.number("hertz.cylinder_width");
  p.material = {s.number("material.young"), s.number("material.poisson")};
  p.block_material = block_material(s, "hertz", p.material);
  return p;
}

problems::Hertz3dParameters hertz3d_parameters(const io::Settings& s)
{
  problems::Hertz3dParameters p;
  p.radius = s.number("hertz3d.radius");
  p.load = s.number("hertz3d.load");
  p.material = {s.number("material.young"), s.number("material.poisson")};
  p.block_material = block_material(s, "hertz3d", p.material);
  p.element_size = s.number("hertz3d.element_size");
  p.refinement = s.number("hertz3d.refinement");
  p.master_ratio = s.number("hertz3d.master_ratio");
  p.block_radius = s.number("hertz3d.block_radius");
  p.cap_radius = s.number("hertz3d.cap_radius");
  p.radial_aspect = s.number("hertz3d.radial_aspect");
  return p;
}

MeshPrediction predict_mesh(const io::ProblemFile& file)
{
  const std::string& kind = file.settings.text("problem");
  if (kind == "hertz")
    return {problems::hertz_node_estimate(hertz_parameters(file.settings).mesh), true};
  if (kind == "hertz3d")
    return {problems::hertz3d_node_count(hertz3d_parameters(file.settings)), false};
  if (kind == "cantilever_obstacle")
    return {problems::cantilever_obstacle_node_count(cantilever_parameters(file.settings)), true};
  const io::CustomMeshSize size = io::custom_mesh_size(file);
  return {size.nodes, size.plane_strain};
}

fem::Problem build_problem(const io::ProblemFile& file, io::DeckInfo* deck)
{
  if (!file.deck.empty())
  {
    io::Deck read = io::read_deck(file.deck, file.deck_outline);
    if (deck)
      *deck = std::move(read.info);
    return std::move(read.problem);
  }
  const std::string& kind = file.settings.text("problem");
  if (kind == "hertz")
    return problems::hertz_problem(hertz_parameters(file.settings));
  if (kind == "hertz3d")
    return problems::hertz3d_problem(hertz3d_parameters(file.settings));
  if (kind == "cantilever_obstacle")
    return problems::cantilever_obstacle_problem(cantilever_parameters(file.settings));
  return io::build_custom_problem(file);
}

nonlinear::SolverSettings solver_settings(const io::Settings& s, const fem::Problem& problem)
{
  nonlinear::SolverSettings out(s);
  const int cells = s.integer("subdomain_cells");
  if (cells > 0)
    out.subdomains = std::max<int>(problem.mesh.n_bodies(),
                                   static_cast<int>((problem.mesh.n_cells() + cells - 1) / cells));
  // A small model (a user's deck of a few elements) gets at most a subdomain per cell rather
  // than an error for the default count; a count the user gives is checked by the partition.
  if (!s.given("subdomains") && out.subdomains > problem.mesh.n_cells())
  {
    log::info("subdomains: " + std::to_string(out.subdomains) + " asked for, the mesh has " +
              std::to_string(problem.mesh.n_cells()) + " cells: one subdomain per cell");
    out.subdomains = problem.mesh.n_cells();
  }
  return out;
}

} // namespace feticon::app
