#include "app/problem_setup.hpp"

#include "common/log.hpp"
#include "contact/adjust.hpp"
#include "contact/coupling_rows.hpp"
#include "contact/tie_rows.hpp"

#include <chrono>
#include <string>
#include <vector>

namespace feticon::app
{
io::ProblemFile load_problem(const std::filesystem::path& path, const std::vector<std::string>& overrides)
{
  return io::load_problem_file(path, overrides, problems::setting_specs());
}

problems::MeshPrediction predict_mesh(const io::ProblemFile& file)
{
  if (const auto built_in = problems::make_built_in_problem(file.settings))
    return built_in->predict_mesh();
  const io::CustomMeshSize size = io::custom_mesh_size(file);
  return {size.nodes, size.plane_strain};
}

namespace
{
/// The pairs' ADJUST applied (contact/adjust.hpp), the ties' rows made (contact/tie_rows.hpp,
/// their ADJUST included) and the kinematic couplings' (contact/coupling_rows.hpp): the model
/// CalculiX starts its first increment from.
fem::Problem adjusted(fem::Problem problem)
{
  if (const int64_t moved = contact::adjust_slave_nodes(problem))
    log::info("contact ADJUST: " + std::to_string(moved) + " slave nodes moved onto their master surfaces");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<contact::TieReport> ties = contact::tie_surfaces(problem);
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  for (const contact::TieReport& report : ties)
    log::info(contact::describe(report));
  if (!ties.empty())
    log::info("ties: " + std::to_string(problem.tie_equations.size()) + " rows made in " +
              std::to_string(took.count()) + " s");
  for (const contact::CouplingReport& report : contact::couple_surfaces(problem))
    log::info(contact::describe(report));
  return problem;
}

/// hyperelastic.fbar: F-bar on the linear cells of every hyperelastic body; without it, a
/// warning where such a body's linear cells lock (K_0 / mu_0 >= 100: +0.6 % of a seal's force at
/// 50, +5 % at 500, +29 % at 5000 on quad4, docs/materials.md). plasticity.fbar: F-bar on those
/// of every plastic body (with large displacements: fem::Material::fbar).
void volumetric_locking(fem::Problem& problem, bool fbar, bool plastic_fbar)
{
  std::vector<char> linear_cells(problem.materials.size(), 0);
  for (int32_t c = 0; c < problem.mesh.n_cells(); ++c)
    if (const mesh::CellKind kind = problem.mesh.cells.kind(c);
        kind == mesh::CellKind::hex8 || kind == mesh::CellKind::quad4)
      linear_cells[static_cast<size_t>(problem.mesh.cell_body[c])] = 1;
  for (size_t b = 0; b < problem.materials.size(); ++b)
  {
    fem::Material& material = problem.materials[b];
    if (material.is_plastic())
      material.fbar = plastic_fbar;
    if (!material.is_hyperelastic())
      continue;
    material.fbar = fbar;
    const double ratio = material.hyperelastic.initial_bulk_modulus() / material.hyperelastic.initial_shear_modulus();
    if (!fbar && linear_cells[b] && ratio >= 100)
      log::warning("body '" + problem.mesh.body_names[b] +
                   "': K_0 / mu_0 = " + std::to_string(static_cast<int>(ratio)) +
                   " on hex8 / quad4 cells, which lock where the law is nearly incompressible (docs/materials.md); "
                   "hyperelastic.fbar=true gives them F-bar, quadratic cells do not lock");
  }
}
} // namespace

fem::Problem build_problem(const io::ProblemFile& file, io::DeckInfo* deck)
{
  fem::Problem problem;
  if (!file.deck.empty())
  {
    io::Deck read = io::read_deck(file.deck, file.deck_outline);
    if (deck)
      *deck = std::move(read.info);
    problem = adjusted(std::move(read.problem));
  }
  else if (const auto built_in = problems::make_built_in_problem(file.settings))
    problem = built_in->build();
  else
    problem = adjusted(io::build_custom_problem(file));
  volumetric_locking(problem, file.settings.flag("hyperelastic.fbar"), file.settings.flag("plasticity.fbar"));
  return problem;
}

nonlinear::SolverSettings solver_settings(const io::Settings& s, const FetiChoice& feti)
{
  nonlinear::SolverSettings out(s);
  out.subdomains = feti.subdomains;
  out.dual.preconditioner = feti.preconditioner;
  out.dual.expansion = feti.expansion;
  out.dirichlet_layers = feti.dirichlet_layers;
  out.factor_precision =
      feti.single_precision_factors ? la::FactorPrecision::single_precision : la::FactorPrecision::double_precision;
  return out;
}

} // namespace feticon::app
