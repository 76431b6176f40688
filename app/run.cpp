/// The run of one problem (app/run.hpp): set-up, solve, post-processing and the results folder.

#include "app/run.hpp"

#include "app/calculix_results.hpp"
#include "app/constraint_summary.hpp"
#include "app/checkpoint.hpp"
#include "app/memory_guard.hpp"
#include "app/model_picture.hpp"
#include "app/problem_setup.hpp"
#include "app/qp_counters_json.hpp"
#include "app/run_output.hpp"
#include "par/communicator.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/atomic_file.hpp"
#include "common/available_memory.hpp"
#include "io/problem_file.hpp"
#include "io/settings.hpp"
#include "la/blas_core.hpp"
#include "mesh/mesh_quality.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "nonlinear/primal_penalty_solver.hpp"
#include "problems/pressure_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

namespace feticon::app
{
namespace
{
/// The problem as run: every setting (defaults, file, overrides) and the structured sections,
/// in a form `feticon run` reads back.
std::string effective_problem(const io::ProblemFile& file)
{
  YAML::Emitter out;
  out << YAML::BeginMap;
  for (const auto& kv : file.root)
    if (io::is_structured_key(kv.first.as<std::string>()))
      out << YAML::Key << kv.first << YAML::Value << kv.second;
  out << YAML::EndMap;
  std::string structured = out.c_str();
  if (structured == "{}")
    structured.clear();
  return file.settings.to_yaml() + structured + "\n";
}

/// A step's VTU (one rank) or the .pvtu joining the ranks' pieces, and a piece's name.
std::string step_file_name(int step, bool serial)
{
  char name[64];
  std::snprintf(name, sizeof name, serial ? "step_%03d.vtu" : "step_%03d.pvtu", step);
  return name;
}

std::string piece_file_name(int step, int rank)
{
  char name[64];
  std::snprintf(name, sizeof name, "step_%03d_rank%03d.vtu", step, rank);
  return name;
}

/// What the phases of a run share: the problem and its settings, where the results go, and
/// the output writers that the load steps feed.
struct RunContext
{
  io::ProblemFile file;
  par::Communicator comm = par::Communicator::world();
  bool writer = false; ///< rank 0 of a run with files: writes the folder's shared files
  bool restart = false;
  std::filesystem::path out_dir;
  TimerTable timers;
  std::unique_ptr<problems::BuiltInProblem> built_in; ///< null for a custom problem or a deck
  std::shared_ptr<fem::Problem> problem;
  std::string theory_line; ///< the built-in problem's comparison with theory, for the table
  io::DeckInfo deck;       ///< the model's input deck, if it is one
  MemoryEstimate memory_estimate;
  FetiChoice feti; ///< the subdomain count and the preconditioner, with why
  nonlinear::SolverSettings solver;
  std::optional<CalculixResults> calculix; ///< a deck's results also in CalculiX's files
  std::optional<io::PvdWriter> pvd;
  std::vector<nonlinear::PressureSample> pressures; ///< of every pair, as in contact_pressure.csv

  const io::Settings& settings() const { return file.settings; }
  bool files() const { return !out_dir.empty(); } ///< a results folder is written
};

/// Set-up: the settings, the memory guard (before anything large is allocated and before an
/// earlier run's results are cleared by --overwrite, then again for the mesh as made), the
/// output folder, the problem and the solver's settings.
void set_up(const RunOptions& options, RunContext& run)
{
  // Set for every run: a library caller's quiet run must not silence its next one.
  log::set_level(options.verbose ? log::Level::iterations
                                 : (options.quiet ? log::Level::warning : log::Level::summary));
  run.restart = !options.restart.empty();
  if (run.restart)
    FETICON_CHECK(options.problem_file.empty() && options.overrides.empty(),
                  "--restart continues a run exactly as it was set up: give no problem file or --set");
  const std::filesystem::path restart_dir(options.restart);
  if (options.problem_text)
  {
    FETICON_CHECK(options.problem_file.empty() && !run.restart,
                  "a problem is given either as text or as a file (or --restart), not both");
    run.file = io::load_problem_text(*options.problem_text, "the problem given as text",
                                     std::filesystem::current_path(), options.overrides, problems::setting_specs());
  }
  else
    run.file = load_problem(run.restart ? restart_dir / "problem.yaml" : std::filesystem::path(options.problem_file),
                            options.overrides);
  const io::Settings& settings = run.settings();

  const std::string what = "problem " + settings.text("problem");
  run.built_in = problems::make_built_in_problem(settings);
  const problems::MeshPrediction predicted = predict_mesh(run.file);
  const int ranks = run.comm.size();
  guard_memory(settings,
               choose_feti(settings, {predicted.nodes, 0, 1, predicted.plane_strain}, memory_budget(settings), ranks),
               predicted.nodes, predicted.plane_strain, what);

  // Under MPI every rank runs this function; rank 0 writes the folder's shared files, every
  // rank its piece of each step's VTU.
  run.out_dir = run.restart ? options.restart : options.output;
  run.writer = run.files() && run.comm.rank() == 0;
  if (run.writer && !run.restart)
  {
    prepare_output_folder(run.out_dir, options.overwrite);
    feticon::write_file_atomically(run.out_dir / "problem.yaml", effective_problem(run.file));
  }
  run.comm.barrier();

  {
    ScopedTimer t(run.timers, "mesh");
    run.problem =
        std::make_shared<fem::Problem>(run.built_in ? run.built_in->build() : build_problem(run.file, &run.deck));
  }
  const fem::Problem& problem = *run.problem;
  // Again for the mesh as made, from what the ranks hold now (with or without Gmsh loaded).
  ModelSize size = model_size(problem);
  size.resident = run.comm.max(static_cast<double>(resident_memory_bytes()));
  run.feti = choose_feti(settings, size, memory_budget(settings), ranks);
  run.memory_estimate = guard_memory(settings, run.feti, size.nodes, size.plane_strain, what, size.resident);
  run.solver = solver_settings(settings, run.feti);
  // A restart must decompose and precondition as this run does, whatever memory the machine
  // has then: problem.yaml gets auto's choices.
  if (run.writer && !run.restart)
  {
    io::ProblemFile resolved = run.file;
    resolved.settings.set("subdomains", std::to_string(run.feti.subdomains), "the auto choice");
    resolved.settings.set("qp.preconditioner", run.feti.preconditioner_name, "the auto choice");
    resolved.settings.set("qp.dirichlet_layers", std::to_string(run.feti.dirichlet_layers), "the auto choice");
    resolved.settings.set("qp.expansion", run.feti.expansion_name, "the auto choice");
    resolved.settings.set("dual.factor_precision", run.feti.single_precision_factors ? "single" : "double",
                          "the auto choice");
    char rho[32];
    std::snprintf(rho, sizeof rho, "%.17g", run.solver.dual.rho); // the method's own where not given
    resolved.settings.set("rho", rho, "the method's default");
    feticon::write_file_atomically(run.out_dir / "problem.yaml", effective_problem(resolved));
  }
  run.solver.explicit_block_budget = run.memory_estimate.explicit_block_budget;
  log::info("feticon: problem " + problem.name + ", " + mesh::describe_cells(problem.mesh.cells) + ", " +
            std::to_string(problem.mesh.dofs_per_node() * static_cast<int64_t>(problem.mesh.n_nodes())) +
            " DOFs, method " + settings.text("method") + ", " + settings.text("displacements") + " displacements" +
            (problem.mesh_from_cache ? "; mesh from the mesh cache (FETICON_MESH_CACHE=off remeshes)" : ""));
  if (run.solver.method != nonlinear::ContactMethod::primal_penalty)
    log::info("subdomains: " + std::to_string(run.feti.subdomains) + " (" + run.feti.subdomains_reason +
              "); preconditioner: " + run.feti.preconditioner_label() + " (" + run.feti.preconditioner_reason +
              "); factors: " + (run.feti.single_precision_factors ? "single" : "double") + " precision");
  if (!run.deck.path.empty() && run.writer) // rank 0 holds the gathered solution
    run.calculix.emplace(run.out_dir, problem, run.deck, run.solver.kinematics);
  if (run.writer)
    run.pvd.emplace(run.out_dir / "solution.pvd");
}

/// The VTU of one accepted load step (one piece per rank under MPI) and its .pvd entry.
void write_step_vtu_files(RunContext& run, int step, const nonlinear::ContactSolution& solution)
{
  const par::Communicator& comm = run.comm;
  const std::string name = step_file_name(step, comm.serial());
  if (comm.serial())
    write_step_vtu(run.out_dir / name, *run.problem, solution, run.solver.kinematics);
  else
  {
    std::vector<std::string> pieces;
    for (int r = 0; r < comm.size(); ++r)
      pieces.push_back(piece_file_name(step, r));
    write_step_vtu(run.out_dir / pieces[comm.rank()], *run.problem, solution, run.solver.kinematics,
                   solution.owned_cells);
    comm.barrier();
    if (run.writer)
      write_step_pvtu(run.out_dir / name, *run.problem, pieces);
  }
  if (run.writer)
    run.pvd->add(solution.steps.back().load_factor, name);
}

/// The output of one accepted load step: CalculiX's files, the VTU, and after them the
/// checkpoint, also without VTU output (a restart needs it whatever was written beside it).
void write_step(RunContext& run, int step, const nonlinear::ContactSolution& solution)
{
  ScopedTimer t(run.timers, "output");
  if (run.calculix)
    run.calculix->add_step(solution);
  if (run.files() && run.settings().flag("output.vtu"))
    write_step_vtu_files(run, step, solution);
  // After the VTU: a checkpoint always names a step whose output is complete.
  if (run.writer && run.solver.method != nonlinear::ContactMethod::primal_penalty)
    write_checkpoint(run.out_dir / "checkpoint.bin", solution);
}

/// Solve: the primal penalty, or FETI from the start or from the folder's checkpoint.
nonlinear::ContactSolution solve(RunContext& run)
{
  const nonlinear::SolverSettings& solver = run.solver;
  const auto on_step = [&run](int step, const nonlinear::ContactSolution& solution) {
    write_step(run, step, solution);
  };
  FETICON_CHECK(run.comm.serial() || solver.method != nonlinear::ContactMethod::primal_penalty,
                "method primal_penalty solves the undecomposed problem on one rank; run it without mpirun");
  FETICON_CHECK(!run.restart || solver.method != nonlinear::ContactMethod::primal_penalty,
                "--restart is available for the FETI methods (smalbe, dual_penalty), not primal_penalty");
  if (solver.method == nonlinear::ContactMethod::primal_penalty)
    return nonlinear::solve_primal_penalty(*run.problem, solver, run.timers, on_step);
  if (!run.restart)
    return nonlinear::solve_feti_contact(*run.problem, solver, run.timers, on_step);
  nonlinear::ContactSolution previous;
  read_checkpoint(run.out_dir / "checkpoint.bin", previous);
  for (int step = 1; step <= previous.restart.completed_steps; ++step)
  {
    const std::string name = step_file_name(step, run.comm.serial());
    if (run.settings().flag("output.vtu"))
    {
      FETICON_CHECK(std::filesystem::exists(run.out_dir / name),
                    "restart: " << (run.out_dir / name).string() << " of a converged step is missing");
      if (run.writer)
        run.pvd->add(previous.steps[step - 1].load_factor, name);
    }
  }
  log::info("restart: continuing after load step " + std::to_string(previous.restart.completed_steps));
  return nonlinear::solve_feti_contact(*run.problem, solver, run.timers, on_step, &previous);
}

/// The run's size and set-up in summary.json.
void summarize_problem(const RunContext& run, const nonlinear::ContactSolution& solution,
                       nlohmann::ordered_json& summary)
{
  const fem::Problem& problem = *run.problem;
  const io::Settings& settings = run.settings();
  summary["problem"] = problem.name;
  summary["method"] = settings.text("method");
  summary["displacements"] = settings.text("displacements");
  summary["converged"] = solution.converged;
  summary["completed"] = solution.completed; // every load step ran; converged: and met the stopping test
  if (!solution.converged)
    summary["reason"] = solution.reason;
  summary["degrees_of_freedom"] = problem.mesh.dofs_per_node() * static_cast<int64_t>(problem.mesh.n_nodes());
  summary["nodes"] = problem.mesh.n_nodes();
  summary["elements"] = problem.mesh.n_cells();
  summary["mesh_from_cache"] = problem.mesh_from_cache;
  summary["subdomains"] = solution.n_subdomains;
  summary["subdomains_reason"] = run.feti.subdomains_reason;
  summary["expansion"] = {{"choice", run.feti.expansion_name}, {"reason", run.feti.expansion_reason}};
  summary["preconditioner"] = {{"choice", run.feti.preconditioner_name},
                               {"dirichlet_layers", run.feti.dirichlet_layers},
                               {"reason", run.feti.preconditioner_reason}};
  if (run.solver.method == nonlinear::ContactMethod::primal_penalty) // no subdomain factors
    summary["factor_precision"] = {{"choice", "double"},
                                   {"reason", "method primal_penalty: one direct factorization of the whole model"}};
  else
    summary["factor_precision"] = {{"choice", run.feti.single_precision_factors ? "single" : "double"},
                                   {"reason", run.feti.factor_precision_reason}};
  summary["dual_size"] = solution.n_dual;
  summary["coarse_size"] = solution.n_kernel;
  const mesh::MeshQuality quality = mesh::mesh_quality(problem.mesh, problem.eliminated[2]);
  summary["mesh_quality"] = {{"max_aspect_ratio", quality.max_aspect_ratio},
                             {"min_angle_deg", quality.min_angle_deg},
                             {"max_angle_deg", quality.max_angle_deg},
                             {"measured", problem.eliminated[2] ? "in plane" : "all cell faces"}};
  summary["rho"] = run.solver.dual.rho;
  summary["dual_operator"] = {{"mode", solution.dual_operator},
                              {"reason", solution.dual_operator_reason},
                              {"bytes", solution.explicit_operator_bytes},
                              {"boundary_widened", solution.schur_boundary_widened}};
  if (run.solver.method == nonlinear::ContactMethod::primal_penalty)
    summary["eps_n"] = solution.penalty;
}

/// A built-in problem's comparison with theory into summary, its line for the end-of-run
/// table and the analytic column of the pressure samples.
void compare_with_theory(RunContext& run, const nonlinear::ContactSolution& solution,
                         std::vector<nonlinear::PressureSample>& samples, nlohmann::ordered_json& summary)
{
  if (!run.built_in)
    return;
  std::vector<problems::SurfaceSample> surface;
  surface.reserve(samples.size());
  for (const nonlinear::PressureSample& s : samples)
    surface.push_back({s.x, s.y, s.deformed_x, s.deformed_y, s.pressure, s.shear.x(), s.friction_force.x(), s.slipping,
                       s.shear.y(), s.area, s.normal_force.x()});
  const bool large = run.solver.kinematics == fem::Kinematics::total_lagrangian;
  const std::optional<problems::TheoryComparison> theory =
      run.built_in->compare_with_theory(*run.problem, solution.u, surface, large);
  if (!theory)
    return;
  summary["contact"]["applied_load"] = theory->applied_load;
  summary[theory->name] = theory->figures;
  run.theory_line = theory->summary_line;
  for (size_t i = 0; i < samples.size(); ++i)
    samples[i].analytic = theory->analytic[i];
  for (size_t i = 0; i < theory->analytic_shear.size(); ++i)
    samples[i].shear_analytic = theory->analytic_shear[i];
}

/// A penalty law's constants and the largest overclosure it gives pair `pair`'s rows at their
/// pressures p = lambda_i / (|b_i| A_i) (contact_constraints.hpp).
nlohmann::ordered_json law_figures(const fem::NormalLaw& law, const nonlinear::ContactSolution& solution, int32_t pair)
{
  const contact::ContactConstraints& rows = solution.constraints;
  double overclosure = 0;
  for (la::Index i = 0; i < solution.contact_lambda.size(); ++i)
    if (rows.pair[i] == pair && solution.contact_lambda(i) > 0 && rows.slave_area[i] > 0)
      overclosure = std::max(overclosure,
                             law.overclosure_at(solution.contact_lambda(i) / (rows.row_norm[i] * rows.slave_area[i])));
  nlohmann::ordered_json out = {{"model", fem::normal_law_name(law.kind)}};
  if (law.kind == fem::NormalLawKind::linear)
    out.update({{"slope", law.slope}, {"sigma_inf", law.sigma_inf}});
  if (law.kind == fem::NormalLawKind::exponential)
    out.update({{"c0", law.c0}, {"p0", law.p0}});
  out["max_overclosure"] = overclosure;
  return out;
}

/// Post-processing: the contact figures of a completed run (the last iterate of a failed solve
/// is no result; its accepted load steps are on disk as VTU and in "steps"), with a built-in
/// problem's comparison with theory, and contact_pressure.csv.
void summarize_contact(RunContext& run, const nonlinear::ContactSolution& solution, nlohmann::ordered_json& summary)
{
  if (!solution.completed || solution.contact_lambda.size() == 0)
    return;
  ScopedTimer t(run.timers, "post-processing");
  const fem::Problem& problem = *run.problem;
  // Pressure along each pair's slave surface; the analytic column is filled where theory is known.
  std::vector<nonlinear::PressureSample> samples;
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
  int64_t active = 0;
  double peak = 0, area = 0;
  for (int32_t p = 0; p < static_cast<int32_t>(problem.contacts.size()); ++p)
  {
    // The interaction of the last step, whose answer this is (a *CHANGE FRICTION may have
    // changed it).
    const fem::ContactInteraction interaction = run.solver.interaction(problem, p, problem.steps.size() - 1);
    const auto mine = nonlinear::slave_pressure_by_x(problem, solution, run.solver.kinematics, interaction.friction, p);
    int64_t pair_active = 0;
    for (la::Index i = 0; i < solution.contact_lambda.size(); ++i)
      pair_active += solution.constraints.pair[i] == p && solution.contact_lambda(i) > 0;
    double pair_peak = 0, pair_area = 0, friction_force = 0;
    int64_t slipping = 0;
    for (const auto& sample : mine)
      pair_peak = std::max(pair_peak, sample.pressure);
    for (const auto& sample : mine)
    {
      pair_area += sample.pressure > problems::loaded_fraction * pair_peak ? sample.area : 0.0;
      friction_force += sample.friction_force.norm();
      slipping += sample.slipping;
    }
    nlohmann::ordered_json figures = {{"slave", problem.contacts[p].slave},
                                      {"master", problem.contacts[p].master},
                                      {"interaction", interaction.name},
                                      {"formulation", fem::formulation_name(interaction.formulation)},
                                      {"friction",
                                       {{"model", fem::friction_model_name(interaction.friction.model)},
                                        {"coefficient", interaction.friction.coefficient},
                                        {"slip_bound", interaction.friction.slip_bound}}},
                                      {"total_normal_force", nonlinear::total_normal_force(solution, p)},
                                      {"peak_pressure", pair_peak},
                                      {"contact_area", pair_area},
                                      {"active_constraints", pair_active}};
    if (interaction.law.kind != fem::NormalLawKind::hard)
      figures["law"] = law_figures(interaction.law, solution, p);
    if (interaction.friction.model != nonlinear::FrictionModel::none)
    {
      figures["friction_force_magnitudes"] = friction_force; // sum over the slave nodes of |F_T| (N)
      figures["slipping_nodes"] = slipping;
    }
    pairs.push_back(std::move(figures));
    active += pair_active;
    peak = std::max(peak, pair_peak);
    area += pair_area;
    samples.insert(samples.end(), mine.begin(), mine.end());
  }
  summary["contact"] = {{"total_normal_force", nonlinear::total_normal_force(solution)},
                        {"peak_pressure", peak},
                        {"contact_area", area},
                        {"active_constraints", active},
                        {"feasibility_error", solution.feasibility_error},
                        {"pairs", std::move(pairs)}};
  if (problem.contacts.size() == 1) // the built-in problems' theories are of one pair
    compare_with_theory(run, solution, samples, summary);
  if (run.writer)
    write_pressure_csv(run.out_dir / "contact_pressure.csv", samples, run.solver.has_friction(problem));
  run.pressures = std::move(samples);
}

/// No silent wrong answers: the deck's and the solver's warnings, and a completed result that
/// is not what it claims (contact forces that do not balance the load) says so. `logged`: what
/// the library warned of on its way (the mesh cache, the preconditioner's scaling).
nlohmann::ordered_json run_warnings(const RunContext& run, const nonlinear::ContactSolution& solution,
                                    const nlohmann::ordered_json& summary, const std::vector<std::string>& logged)
{
  nlohmann::ordered_json warnings = nlohmann::ordered_json::array();
  for (const std::string& w : run.deck.warnings)
    warnings.push_back("deck: " + w);
  for (const std::string& w : solution.warnings)
    warnings.push_back(w);
  for (const std::string& w : logged)
    if (std::ranges::find(warnings, nlohmann::ordered_json(w)) == warnings.end())
      warnings.push_back(w);
  if (run.calculix)
    for (const std::string& w : run.calculix->warnings())
      warnings.push_back("deck output: " + w);
  if (run.calculix && run.solver.has_friction(*run.problem))
    warnings.push_back("deck output: the .frd and .dat hold the normal contact only: slip and shear (CSLIP, "
                       "CSHEAR, the tangential CSTR) are written as 0, and RF subtracts only the normal "
                       "contact force");
  const io::Settings& settings = run.settings();
  const double feasibility_tolerance = settings.number("contact.feasibility_tolerance");
  if (solution.completed && run.solver.method == nonlinear::ContactMethod::dual_penalty &&
      solution.feasibility_error > feasibility_tolerance)
  {
    char line[320];
    std::snprintf(line, sizeof line,
                  "the dual penalty with rho = %g leaves ||G lambda - e|| / ||e|| = %.2g above "
                  "contact.feasibility_tolerance = %g: the contact forces do not balance the load; raise rho "
                  "or use method=smalbe",
                  run.solver.dual.rho, solution.feasibility_error, feasibility_tolerance);
    warnings.push_back(line);
  }
  // Where a built-in problem says the whole load goes through the contact, the contact force must
  // equal it: to round-off with small displacements, to 1.5e-4 with large ones (the force is
  // summed along the rotated normals), far off when the multipliers are infeasible.
  if (summary.contains("contact") && summary["contact"].contains("applied_load"))
  {
    const double load = summary["contact"]["applied_load"], force = summary["contact"]["total_normal_force"];
    if (std::abs(force - load) > feasibility_tolerance * std::abs(load))
    {
      char line[320];
      std::snprintf(line, sizeof line,
                    "the contact force %.6g N differs from the applied load %.6g N by %.2g (relative), more "
                    "than contact.feasibility_tolerance = %g: the contact forces do not carry the load",
                    force, load, std::abs(force - load) / std::abs(load), feasibility_tolerance);
      warnings.push_back(line);
    }
  }
  return warnings;
}

/// Write: the steps, timings and memory into summary.json, history.csv, the plots.
void write_results(RunContext& run, const nonlinear::ContactSolution& solution, nlohmann::ordered_json& summary)
{
  nlohmann::ordered_json steps = nlohmann::ordered_json::array();
  for (const auto& s : solution.steps)
    steps.push_back({{"load_factor", s.load_factor},
                     {"outer_iterations", s.outer_iterations},
                     {"inner_iterations", s.inner_iterations},
                     {"converged", s.converged},
                     {"floor", s.floor},
                     {"relative_displacement_change", s.displacement_change},
                     {"residual_norm", s.residual_norm}});
  summary["steps"] = steps;
  if (run.writer)
    write_history_csv(run.out_dir / "history.csv", solution.history);
  nlohmann::ordered_json timing;
  for (const auto& [phase, seconds] : run.timers.entries())
    timing[phase] = seconds;
  summary["timings_seconds"] = timing;
  summary["ranks"] = run.comm.size();
  summary["blas_core"] = la::blas_core(); // OpenBLAS's kernels (la/blas_core.hpp); "" for another BLAS
  const std::vector<int64_t> memory =
      run.comm.all_gather(std::vector<int64_t>{static_cast<int64_t>(peak_memory_bytes())});
  summary["peak_memory_bytes"] = *std::max_element(memory.begin(), memory.end());
  summary["memory_estimate_bytes"] = run.memory_estimate.per_rank_for(solution.dual_operator);
  if (!run.comm.serial())
    summary["peak_memory_bytes_per_rank"] = memory;
  if (run.writer)
    write_json(run.out_dir / "summary.json", summary);
  log::info(format_summary(summary, run.theory_line));
  if (solution.completed && run.writer && run.settings().flag("output.plots"))
  {
    const auto start = std::chrono::steady_clock::now();
    plot_results(run.out_dir);
    const std::filesystem::path data = run.out_dir / ".picture";
    write_picture_data(data, *run.problem, solution, run.solver.kinematics, run.pressures, run.deck.path.empty());
    draw_model_pictures(data, run.out_dir);
    std::filesystem::remove_all(data);
    char line[96];
    std::snprintf(line, sizeof line, "pictures (model.png, contact.png and the plots) drawn in %.1f s",
                  seconds_since(start));
    log::info(line);
  }
  if (run.files())
    log::info("results written to " + run.out_dir.string());
}

} // namespace

RunResult run_problem(const RunOptions& options)
{
  RunContext run;
  set_up(options, run);
  nonlinear::ContactSolution solution = solve(run);
  nlohmann::ordered_json summary;
  summarize_problem(run, solution, summary);
  summarize_contact(run, solution, summary);
  if (!run.problem->couplings.empty())
    summary["couplings"] = coupling_summary(*run.problem, solution, run.solver.kinematics);
  if (!run.problem->ties.empty())
    summary["ties"] = tie_summary(*run.problem, solution, run.solver.kinematics);
  summary["qp"] = qp_json(solution);
  const std::vector<std::string> logged = log::take_warnings(); // already on stderr
  const nlohmann::ordered_json warnings = run_warnings(run, solution, summary, logged);
  for (const auto& w : warnings)
    if (std::ranges::find(logged, w.get<std::string>()) == logged.end())
      log::warning(w.get<std::string>());
  summary["warnings"] = warnings;
  write_results(run, solution, summary);
  FETICON_CHECK(solution.completed,
                "the solve did not converge: "
                    << solution.reason
                    << (run.files() ? " (converged steps are in " + run.out_dir.string() + ")" : ""));
  return {std::move(summary), run.problem, std::move(solution), std::move(run.pressures), run.solver.kinematics};
}

} // namespace feticon::app
