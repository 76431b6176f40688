/// `feticon bench`: one benchmark measurement as one JSON line on stdout (issue 8);
/// bench/run.sh repeats it and takes medians.
///
/// Sample runs:
///   feticon bench --set hertz.refinement=2.5 --set subdomains=32
///       the FETI contact solve of a problem (as `feticon run` sets it up: file and --set),
///       its phase times, counters and peak memory, then the bonded direct solve of the same
///       mesh with the contact solution's active nodes (nonlinear/bonded_direct_solve.hpp)
///       and the ratio contact-solve time / direct factorization + solve time;
///   feticon bench --mprgp-obstacle 1000
///       MPRGP alone on the 2D obstacle QP with 1000^2 unknowns: time per step against one
///       operator application (app/mprgp_benchmark.hpp).
/// Progress lines are silenced unless --verbose; the JSON is always the last stdout line.

#include "app/commands.hpp"
#include "app/mprgp_benchmark.hpp"
#include "app/memory_guard.hpp"
#include "app/petsc_binary.hpp"
#include "par/communicator.hpp"
#include "app/problem_setup.hpp"
#include "app/qp_counters_json.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/timer.hpp"
#include "la/blas_core.hpp"
#include "nonlinear/bonded_direct_solve.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

#include <filesystem>
#include <iostream>
#include <memory>

namespace feticon::app
{
namespace
{
struct BenchOptions
{
  std::string problem_file;
  std::vector<std::string> overrides;
  bool direct = true;
  int obstacle_n = 0; ///< > 0: the MPRGP obstacle benchmark instead of a contact solve
  double obstacle_rtol = 1e-5;
  int obstacle_max_iterations = 100000;
  std::string obstacle_expansion = "projcg";
  int applications = 21;
  bool verbose = false;
  std::string bonded_system; ///< folder for the bonded system in PETSc's format (empty: none)
};

/// The bonded system of `solution`'s active set in PETSc's format in `folder` (bench/gamg);
/// what was written, for the JSON line.
nlohmann::ordered_json write_bonded_system(const fem::Problem& problem, const nonlinear::SolverSettings& solver,
                                           const nonlinear::ContactSolution& solution,
                                           const std::filesystem::path& folder)
{
  const nonlinear::BondedSystem system =
      nonlinear::bonded_system(problem, solver, nonlinear::active_slave_nodes(solution));
  std::filesystem::create_directories(folder);
  write_petsc_matrix(folder / "A.petsc", system.A);
  write_petsc_vectors(folder / "b.petsc", system.b);
  write_petsc_vectors(folder / "near_kernel.petsc", system.near_kernel);
  return {{"folder", folder.string()},
          {"unknowns", system.A.rows()},
          {"nonzeros", system.A.nonZeros()},
          {"near_kernel_vectors", system.near_kernel.cols()}};
}

/// The FETI contact solve and the bonded direct solve of one problem.
nlohmann::ordered_json contact_benchmark(const BenchOptions& options)
{
  const io::ProblemFile file = load_problem(options.problem_file, options.overrides);
  FETICON_CHECK(file.settings.text("method") != "primal_penalty",
                "feticon bench measures the FETI methods; set method=smalbe or dual_penalty");
  TimerTable timers;
  const problems::MeshPrediction predicted = predict_mesh(file);
  const std::string what = "problem " + file.settings.text("problem");
  const MemoryBudget budget = memory_budget(file.settings);
  const int ranks = par::Communicator::world().size();
  guard_memory(file.settings,
               choose_feti(file.settings, {predicted.nodes, 0, 1, predicted.plane_strain}, budget, ranks),
               predicted.nodes, predicted.plane_strain, what);
  std::unique_ptr<fem::Problem> problem;
  {
    ScopedTimer t(timers, "mesh");
    problem = std::make_unique<fem::Problem>(build_problem(file));
  }
  const FetiChoice feti = choose_feti(file.settings, model_size(*problem), budget, ranks);
  const MemoryEstimate estimate =
      guard_memory(file.settings, feti, guard_nodes(problem->mesh), problem->eliminated[2], what);
  nonlinear::SolverSettings solver = solver_settings(file.settings, feti);
  solver.explicit_block_budget = estimate.explicit_block_budget;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(*problem, solver, timers);
  const long peak_contact = peak_memory_bytes();

  nlohmann::ordered_json out;
  out["problem"] = problem->name;
  out["displacements"] = file.settings.text("displacements");
  out["method"] = file.settings.text("method");
  out["preconditioner"] = feti.preconditioner_name;
  out["dirichlet_layers"] = feti.dirichlet_layers;
  out["factor_precision"] = feti.single_precision_factors ? "single" : "double";
  out["blas_core"] = la::blas_core();
  out["dual_operator"] = solution.dual_operator; // implicit or explicit, after dual.operator = auto
  out["explicit_operator_bytes"] = solution.explicit_operator_bytes;
  out["converged"] = solution.converged;
  out["completed"] = solution.completed;
  if (!solution.converged)
    out["reason"] = solution.reason;
  out["degrees_of_freedom"] = problem->mesh.dofs_per_node() * static_cast<int64_t>(problem->mesh.n_nodes());
  out["elements"] = problem->mesh.n_cells();
  out["subdomains"] = solution.n_subdomains;
  out["subdomains_reason"] = feti.subdomains_reason;
  out["dual_size"] = solution.n_dual;
  out["coarse_size"] = solution.n_kernel;
  out["load_steps"] = solution.steps.size();
  out["qp"] = qp_json(solution);
  nlohmann::ordered_json timing;
  for (const auto& [phase, seconds] : timers.entries())
    timing[phase] = seconds;
  out["timings_seconds"] = timing;
  const qp::QpCounters sum = qp_totals(solution);
  const int iterations = sum.iterations;
  const double qp_seconds = sum.seconds;
  out["dual_seconds_per_mprgp_iteration"] = timers.total("dual solve (MPRGP)") / std::max(iterations, 1);
  // One application of H = PFP + rho Q is one of F and two of the coarse projector; with a
  // preconditioner the limit of an iteration is one H and one preconditioner application.
  // The ratios say what MPRGP and SMALBE-M add per iteration on top of that.
  const double per_application = sum.operator_seconds / std::max<int64_t>(sum.operator_applications, 1);
  const double per_preconditioner = sum.preconditioner_seconds / std::max<int64_t>(sum.preconditioner_applications, 1);
  out["qp_seconds"] = qp_seconds;
  out["seconds_per_operator_application"] = per_application;
  out["seconds_per_preconditioner_application"] = per_preconditioner;
  out["ratio_iteration_to_operator"] = qp_seconds / std::max(iterations, 1) / per_application;
  out["ratio_iteration_to_operator_and_preconditioner"] =
      qp_seconds / std::max(iterations, 1) / (per_application + per_preconditioner);
  out["peak_memory_bytes"] = peak_contact;
  out["total_normal_force"] = nonlinear::total_normal_force(solution);
  if (!solution.completed)
    return out;
  // The system for another solver (bench/gamg) first: the direct solve's factor is the
  // largest allocation, and its peak is measured alone below.
  if (!options.bonded_system.empty())
    out["bonded_system"] = write_bonded_system(*problem, solver, solution, options.bonded_system);
  if (!options.direct)
    return out;

  const nonlinear::BondedSolve direct =
      nonlinear::bonded_direct_solve(*problem, solver, nonlinear::active_slave_nodes(solution));
  const double direct_seconds = direct.factorization_seconds + direct.solve_seconds;
  out["direct"] = {{"bonded_rows", direct.n_bonded},
                   {"assembly_seconds", direct.assembly_seconds},
                   {"factorization_seconds", direct.factorization_seconds},
                   {"solve_seconds", direct.solve_seconds},
                   {"factor_nonzeros", direct.factor_nonzeros},
                   // How far the bonded solution is from the contact one: small for small
                   // displacements (penalty and active-set edge), a check that both solved
                   // the same mesh and load.
                   {"relative_difference", (direct.u - solution.u).norm() / solution.u.norm()}};
  out["peak_memory_bytes_with_direct"] = peak_memory_bytes();
  out["ratio_contact_to_direct"] = timers.total("total solve") / direct_seconds;
  return out;
}
} // namespace

void register_bench_command(CLI::App& app)
{
  auto options = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand("bench",
                                     "One benchmark measurement as a JSON line: a FETI contact "
                                     "solve against the bonded direct solve, or MPRGP alone");
  cmd->add_option("problem", options->problem_file, "problem file (YAML); omit for the built-in Hertz problem");
  cmd->add_option("--set,-s", options->overrides, "override a setting, KEY=VALUE (repeatable; see run --help)");
  cmd->add_flag("!--no-direct", options->direct, "skip the bonded direct solve");
  cmd->add_option("--bonded-system", options->bonded_system,
                  "also write the bonded system (A.petsc, b.petsc, near_kernel.petsc in PETSc's binary format) to "
                  "this folder, for bench/gamg");
  cmd->add_option("--mprgp-obstacle", options->obstacle_n, "instead: MPRGP on the 2D obstacle QP with N x N unknowns");
  cmd->add_option("--rtol", options->obstacle_rtol, "MPRGP tolerance of the obstacle QP")->capture_default_str();
  cmd->add_option("--max-iterations", options->obstacle_max_iterations, "MPRGP step limit of the obstacle QP")
      ->capture_default_str();
  cmd->add_option("--expansion", options->obstacle_expansion, "MPRGP expansion step of the obstacle QP: std or projcg")
      ->check(CLI::IsMember({"std", "projcg"}))
      ->capture_default_str();
  cmd->add_option("--applications", options->applications, "timed operator applications (median) of the obstacle QP")
      ->capture_default_str();
  cmd->add_flag("--verbose,-v", options->verbose, "progress lines before the JSON");
  cmd->callback([options] {
    if (!options->verbose)
      log::set_level(log::Level::warning);
    const nlohmann::ordered_json out = options->obstacle_n > 0
        ? mprgp_obstacle_benchmark(options->obstacle_n, options->obstacle_rtol, options->obstacle_max_iterations,
                                   options->applications, options->obstacle_expansion)
        : contact_benchmark(*options);
    std::cout << out.dump() << '\n';
  });
}
} // namespace feticon::app
