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
} // namespace

fem::Problem build_problem(const io::ProblemFile& file, io::DeckInfo* deck)
{
  if (!file.deck.empty())
  {
    io::Deck read = io::read_deck(file.deck, file.deck_outline);
    if (deck)
      *deck = std::move(read.info);
    return adjusted(std::move(read.problem));
  }
  if (const auto built_in = problems::make_built_in_problem(file.settings))
    return built_in->build();
  return adjusted(io::build_custom_problem(file));
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
