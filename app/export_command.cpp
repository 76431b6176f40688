/// `feticon export`: the model that `feticon run` with the same arguments solves, written for
/// another code (today CalculiX), so that both are measured on identical meshes
/// (bench/calculix.sh).
///
/// Sample run:
///   feticon export --set hertz.refinement=4.4 --format calculix --output deck
///       writes deck/feticon.inp; `cd deck && ccx feticon` solves it.

#include "app/commands.hpp"
#include "app/memory_guard.hpp"
#include "par/communicator.hpp"
#include "app/problem_setup.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/atomic_file.hpp"
#include "io/calculix_deck.hpp"

#include <filesystem>
#include <memory>
#include <sstream>

namespace feticon::app
{
namespace
{
struct ExportOptions
{
  std::string problem_file;
  std::vector<std::string> overrides;
  std::string format;
  std::string output;
  double contact_stiffness_factor = 5.0;
  double overclosure = -1.0;
};

void export_model(const ExportOptions& options)
{
  FETICON_CHECK(options.format == "calculix",
                "export: --format " << options.format << " is not known; the one format is calculix");
  const io::ProblemFile file = load_problem(options.problem_file, options.overrides);
  // The mesh and the deck only: no solve, so the guard counts the mesh alone.
  const problems::MeshPrediction predicted = predict_mesh(file);
  check_fits(estimate_mesh_memory(predicted.nodes), memory_budget(file.settings),
             "exporting problem " + file.settings.text("problem"));
  const fem::Problem problem = build_problem(file);
  // Kinematics and load steps exactly as `feticon run` takes them.
  const nonlinear::SolverSettings solver = solver_settings(
      file.settings,
      choose_feti(file.settings, model_size(problem), memory_budget(file.settings), par::Communicator::world().size()));
  io::CalculixOptions deck;
  deck.nlgeom = solver.kinematics == fem::Kinematics::total_lagrangian;
  deck.increments = solver.steps_of(problem);
  deck.contact_stiffness_factor = options.contact_stiffness_factor;
  deck.overclosure = options.overclosure;
  deck.friction.assign(problem.steps.size(), std::vector<double>(problem.contacts.size(), 0.0));
  for (int32_t p = 0; p < std::ssize(problem.contacts); ++p)
  {
    deck.node_to_segment.push_back(solver.interaction(problem.contacts[p]).formulation ==
                                   fem::ContactFormulation::node_to_segment);
    // CalculiX's *FRICTION is Coulomb's law; a slip bound independent of the pressure has no
    // keyword there, and writing Coulomb instead would compare two different models.
    for (size_t k = 0; k < problem.steps.size(); ++k)
    {
      const nonlinear::Friction friction = solver.interaction(problem, p, k).friction;
      FETICON_CHECK(friction.model != nonlinear::FrictionModel::tresca,
                    "export: Tresca friction (contact pair " << p
                                                             << ") has no CalculiX equivalent: ccx's *FRICTION is "
                                                                "Coulomb's law (mu times the pressure); export with "
                                                                "coulomb or none");
      deck.friction[k][static_cast<size_t>(p)] =
          friction.model == nonlinear::FrictionModel::coulomb ? friction.coefficient : 0.0;
    }
  }

  std::ostringstream text;
  const io::CalculixDeckSummary s = io::write_calculix_deck(problem, deck, text);
  const std::filesystem::path dir(options.output);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  FETICON_CHECK(!ec, "cannot create the output folder " << dir.string() << ": " << ec.message());
  feticon::write_file_atomically(dir / "feticon.inp", text.str());

  std::ostringstream message;
  message << "export: " << (dir / "feticon.inp").string() << ": " << s.n_nodes << " nodes, " << s.n_elements
          << " elements, " << s.n_contact_pairs << " contact pair(s) (" << s.n_slave_faces << " slave, "
          << s.n_master_faces << " master faces, K = " << s.contact_stiffness << " Pa/m), " << s.n_cloads
          << " nodal loads, total (" << s.total_load[0] << ", " << s.total_load[1] << ", " << s.total_load[2] << ") N, "
          << deck.increments << " increment(s)" << (deck.nlgeom ? ", NLGEOM" : "");
  if (s.stick_slope > 0)
    message << ", Coulomb friction mu = " << s.friction_coefficient << " (stick slope " << s.stick_slope << " Pa/m)";
  if (s.overclosure > 0)
    message << ", floating slave body shifted " << s.overclosure << " m into its master";
  log::info(message.str());
}
} // namespace

void register_export_command(CLI::App& app)
{
  auto options = std::make_shared<ExportOptions>();
  CLI::App* cmd = app.add_subcommand("export",
                                     "Write the model `feticon run` would solve (same file and --set) "
                                     "as another code's input: --format calculix writes DIR/feticon.inp");
  cmd->add_option("problem", options->problem_file, "problem file (YAML); omit for the built-in Hertz problem");
  cmd->add_option("--set,-s", options->overrides, "override a setting, KEY=VALUE (repeatable)");
  cmd->add_option("--format", options->format, "target format: calculix")->required();
  cmd->add_option("--output,-o", options->output, "folder of the written deck")->required();
  cmd->add_option("--contact-stiffness", options->contact_stiffness_factor,
                  "penalty slope of CalculiX's pressure-overclosure law as a multiple of E / h (h the "
                  "shortest slave face edge; see src/io/calculix_deck.hpp)")
      ->capture_default_str();
  cmd->add_option("--overclosure", options->overclosure,
                  "shift (m) of a slave body held only by contact into its master; default 2 % of the "
                  "shortest slave face edge");
  cmd->callback([options] { export_model(*options); });
}
} // namespace feticon::app
