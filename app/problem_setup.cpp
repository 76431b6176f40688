#include "app/problem_setup.hpp"

#include "common/log.hpp"

#include <algorithm>
#include <string>

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

fem::Problem build_problem(const io::ProblemFile& file, io::DeckInfo* deck)
{
  if (!file.deck.empty())
  {
    io::Deck read = io::read_deck(file.deck, file.deck_outline);
    if (deck)
      *deck = std::move(read.info);
    return std::move(read.problem);
  }
  if (const auto built_in = problems::make_built_in_problem(file.settings))
    return built_in->build();
  return io::build_custom_problem(file);
}

nonlinear::SolverSettings solver_settings(const io::Settings& s, const fem::Problem& problem, const FetiChoice& feti)
{
  nonlinear::SolverSettings out(s);
  out.subdomains = feti.subdomains;
  out.dual.preconditioner = feti.preconditioner;
  // Friction with mortar rows on tri6 / quad8 faces: the tangential rows of the symmetry
  // planes' nodes are not recognised as held (the transformed dual basis spreads their weight
  // beyond the plane), (B B')_CC is nearly singular (2.8e-5 on hertz3d hex20's half model) and
  // the solve stalls (docs/elements.md); node-to-segment rows converge there.
  const bool friction = out.friction.model != nonlinear::FrictionModel::none;
  if (friction && out.formulation == contact::ContactFormulation::mortar && !s.given("contact.formulation"))
    for (const fem::ContactPairNames& pair : problem.contacts)
      if (std::ranges::any_of(problem.mesh.face_set(pair.slave), [](const mesh::Face& f) {
            return f.kind == mesh::FaceKind::tri6 || f.kind == mesh::FaceKind::quad8;
          }))
      {
        log::info("contact: friction on the quadratic faces of '" + pair.slave +
                  "': node_to_segment rows (mortar rows with friction are not ready on them)");
        out.formulation = contact::ContactFormulation::node_to_segment;
      }
  return out;
}

} // namespace feticon::app
