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
  // Mortar rows integrate quad4 faces: contact surfaces of other face types (tetrahedra,
  // wedges, quadratic cells) get node-to-segment rows unless the user asked for mortar.
  if (out.formulation == contact::ContactFormulation::mortar && !s.given("contact.formulation"))
    for (const fem::ContactPairNames& pair : problem.contacts)
      for (const std::string& set : {pair.slave, pair.master})
        if (std::ranges::any_of(problem.mesh.face_set(set),
                                [](const mesh::Face& f) { return f.kind != mesh::FaceKind::quad4; }) &&
            out.formulation == contact::ContactFormulation::mortar)
        {
          log::info("contact: face set '" + set +
                    "' has faces other than quad4; its rows are node_to_segment (mortar integrates quad4 faces)");
          out.formulation = contact::ContactFormulation::node_to_segment;
        }
  return out;
}

} // namespace feticon::app
