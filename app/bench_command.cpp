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
#include "app/problem_setup.hpp"
#include "app/qp_counters_json.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/timer.hpp"
#include "nonlinear/bonded_direct_solve.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/feti_contact_solver.hpp"

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
};

/// The FETI contact solve and the bonded direct solve of one problem.
nlohmann::ordered_json contact_benchmark(const BenchOptions& options)
{
  const io::ProblemFile file = load_problem(options.problem_file, options.overrides);
  FETICON_CHECK(file.settings.text("method") != "primal_penalty",
                "feticon bench measures the FETI methods; set method=smalbe or dual_penalty");
  TimerTable timers;
  const problems::MeshPrediction predicted = predict_mesh(file);
  const MemoryEstimate estimate =
      guard_memory(file.settings, predicted.nodes, predicted.plane_strain, "problem " + file.settings.text("problem"));
  std::unique_ptr<fem::Problem> problem;
  {
    ScopedTimer t(timers, "mesh");
    problem = std::make_unique<fem::Problem>(build_problem(file));
  }
  nonlinear::SolverSettings solver = solver_settings(file.settings, *problem);
  solver.explicit_block_budget = estimate.explicit_block_budget;
  const nonlinear::ContactSolution solution = nonlinear::solve_feti_contact(*problem, solver, timers);
  const long peak_contact = peak_memory_bytes();

  nlohmann::ordered_json out;
  out["problem"] = problem->name;
  out["displacements"] = file.settings.text("displacements");
  out["method"] = file.settings.text("method");
  out["preconditioner"] = file.settings.text("qp.preconditioner");
  out["dual_operator"] = solution.dual_operator; // implicit or explicit, after dual.operator = auto
  out["explicit_operator_bytes"] = solution.explicit_operator_bytes;
  out["converged"] = solution.converged;
  out["completed"] = solution.completed;
  if (!solution.converged)
    out["reason"] = solution.reason;
  out["degrees_of_freedom"] = 3 * static_cast<int64_t>(problem->mesh.n_nodes());
  out["elements"] = problem->mesh.n_cells();
  out["subdomains"] = solution.n_subdomains;
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
  if (!options.direct || !solution.completed)
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
