/// `feticon qp`: one QP from Matrix Market files, solved by MPRGP, or by MPGP with discs.
///
///     min 1/2 x'Ax - b'x   subject to   l <= x <= u   (A symmetric positive definite)
///                          and ||(x_i, x_j)|| <= r_k for the discs of --discs (app/disc_file.hpp)
///
/// Sample runs:
///   feticon qp --A A.mtx --b b.mtx                       # unconstrained: MPRGP = CG
///   feticon qp --A A.mtx --b b.mtx --lower l.mtx --rtol 1e-8 --out x.mtx --monitor
///   feticon qp --A A.mtx --b b.mtx --lower l.mtx --upper u.mtx   # box l <= x <= u
///   feticon qp --A A.mtx --b b.mtx --lower l.mtx --discs discs.txt  # l on the others: MPGP
///
/// stdout gets exactly one JSON line with the report; --monitor writes one line per step to
/// stderr. With --discs, MPGP (qp/mpgp.hpp) solves the QP with the standard expansion step
/// (--expansion is MPRGP's only); l and u default to -inf and +inf, as disc components need. Exit status: 0 converged, 3 not converged (the JSON and x are still
/// written), 1 invalid input (one line on stderr, from app/main.cpp).

#include "app/commands.hpp"
#include "app/disc_file.hpp"
#include "app/memory_guard.hpp"
#include "app/qp_counters_json.hpp"
#include "common/error.hpp"
#include "la/matrix_market.hpp"
#include "la/operator.hpp"
#include "qp/mpgp.hpp"
#include "qp/mprgp.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace feticon::app
{
namespace
{
struct QpArguments
{
  std::string matrix_path;
  std::string rhs_path;
  std::string lower_path;
  std::string upper_path;
  std::string discs_path;
  std::string output_path;
  double rtol = 1e-5;
  int max_iterations = 10000;
  std::string expansion = "projcg";
  bool monitor = false;
};

/// Rejects a non-square A, or one whose asymmetry exceeds round-off (relative 1e-12 of the
/// largest entry): MPRGP minimizes 1/2 x'Ax - b'x, which only sees the symmetric part.
void check_symmetric(const la::SparseMatrix& A, const std::string& path)
{
  FETICON_CHECK(A.rows() == A.cols(),
                path << ": A is " << A.rows() << " x " << A.cols() << "; the QP needs a square matrix");
  const la::SparseMatrix asymmetry = A - la::SparseMatrix(A.transpose());
  double largest = 0.0;
  for (la::Index k = 0; k < A.nonZeros(); ++k)
    largest = std::max(largest, std::abs(A.valuePtr()[k]));
  double largest_asymmetry = 0.0;
  for (la::Index k = 0; k < asymmetry.nonZeros(); ++k)
    largest_asymmetry = std::max(largest_asymmetry, std::abs(asymmetry.valuePtr()[k]));
  FETICON_CHECK(std::isfinite(largest), path << ": A has a NaN or infinite entry");
  FETICON_CHECK(largest_asymmetry <= 1e-12 * largest,
                path << ": A is not symmetric: max |a_ij - a_ji| = " << largest_asymmetry << " > 1e-12 max |a_ij| = "
                     << 1e-12 * largest << "; store a symmetric matrix (or one triangle with 'symmetric')");
}

void print_iterate(const char* solver, const qp::MprgpIterate& it)
{
  char line[160];
  std::snprintf(line, sizeof line, "%s %6d %-13s |g_P| %.6e |phi| %.6e |beta| %.6e f %.12e", solver, it.iteration,
                qp::to_string(it.step), it.projected_gradient_norm, it.free_gradient_norm, it.chopped_gradient_norm,
                it.cost);
  std::cerr << line << '\n';
}

/// The bound vector in `path` (symbol l or u), checked to have n entries; `absent` everywhere
/// if no path is given.
la::Vector read_bound(const std::string& path, const char* symbol, la::Index n, double absent)
{
  if (path.empty())
    return la::Vector::Constant(n, absent);
  la::Vector bound = la::read_matrix_market_dense(path);
  FETICON_CHECK(bound.size() == n,
                path << ": " << symbol << " has " << bound.size() << " entries but A has " << n << " rows");
  return bound;
}

/// MPRGP on l <= x <= u; without --upper its lower-bound solve, whose arithmetic the box
/// solve reproduces for u = +inf (qp/mprgp.hpp).
qp::QpReport solve_box(const QpArguments& arguments, const la::LinearOperator& op, const la::Vector& b,
                       const la::Vector& lower, const std::optional<la::Vector>& upper, la::Vector& x)
{
  qp::MprgpOptions options{.rtol = arguments.rtol,
                           .max_iterations = arguments.max_iterations,
                           .expansion = qp::expansion_from_name(arguments.expansion)};
  if (arguments.monitor)
    options.monitor = [](const qp::MprgpIterate& it) { print_iterate("mprgp", it); };
  qp::Mprgp mprgp(op, options);
  return upper ? mprgp.solve(b, lower, *upper, x) : mprgp.solve(b, lower, x);
}

/// MPGP on l <= x <= u and the discs of --discs.
qp::QpReport solve_discs(const QpArguments& arguments, const la::LinearOperator& op, const la::Vector& b,
                         const la::Vector& lower, const std::optional<la::Vector>& upper, la::Vector& x)
{
  const la::Index n = b.size();
  qp::SeparableConstraints set{
      lower, upper ? *upper : la::Vector::Constant(n, std::numeric_limits<double>::infinity()), {}};
  set.discs = read_disc_file(arguments.discs_path, n, set.lower, set.upper);
  qp::MpgpOptions options{.rtol = arguments.rtol, .max_iterations = arguments.max_iterations};
  if (arguments.monitor)
    options.monitor = [](const qp::MprgpIterate& it) { print_iterate("mpgp", it); };
  qp::Mpgp mpgp(op, options);
  return mpgp.solve(b, set, x);
}

void run_qp(const QpArguments& arguments)
{
  // The memory guard, from the size line before the entries are read.
  const la::MatrixMarketSize declared = la::read_matrix_market_size(arguments.matrix_path);
  check_fits(
      estimate_qp_memory(std::max(declared.rows, declared.cols), (declared.symmetric ? 2 : 1) * declared.entries),
      memory_budget(0.0),
      "qp: " + arguments.matrix_path + " (" + std::to_string(declared.rows) + " x " + std::to_string(declared.cols) +
          ", " + std::to_string(declared.entries) + " entries)");
  const la::SparseMatrix A = la::read_matrix_market_sparse(arguments.matrix_path);
  check_symmetric(A, arguments.matrix_path);
  const la::Index n = A.rows();
  const la::Vector b = la::read_matrix_market_dense(arguments.rhs_path);
  FETICON_CHECK(b.size() == n, arguments.rhs_path << ": b has " << b.size() << " entries but A has " << n << " rows");
  const la::Vector lower = read_bound(arguments.lower_path, "l", n, -std::numeric_limits<double>::infinity());
  const std::optional<la::Vector> upper = arguments.upper_path.empty()
      ? std::nullopt
      : std::optional<la::Vector>(read_bound(arguments.upper_path, "u", n, 0.0));

  la::Vector x = la::Vector::Zero(n); // projected onto Omega by the solvers
  const la::SparseOperator op(A);
  const qp::QpReport report = arguments.discs_path.empty() ? solve_box(arguments, op, b, lower, upper, x)
                                                           : solve_discs(arguments, op, b, lower, upper, x);
  FETICON_CHECK(std::isfinite(report.cost) && std::isfinite(report.projected_gradient_norm) && x.allFinite(),
                "qp: the solve produced non-finite values (cost "
                    << report.cost
                    << "); are A, b and the bounds of "
                       "a moderate size (bounds like 1e300 overflow the cost)?");

  nlohmann::ordered_json json = {{"converged", report.converged}};
  json.update(qp_counters_json(report));
  json["projected_gradient_norm"] = report.projected_gradient_norm;
  json["cost"] = report.cost;
  json["seconds"] = report.seconds;
  std::cout << json.dump() << std::endl;

  if (!arguments.output_path.empty())
    la::write_matrix_market_dense(arguments.output_path, x);
  if (!report.converged)
  {
    std::cerr << "feticon qp: not converged: " << report.reason << '\n';
    // CLI::App::exit() returns a RuntimeError's code without printing anything.
    throw CLI::RuntimeError(3);
  }
}
} // namespace

void register_qp_command(CLI::App& app)
{
  auto arguments = std::make_shared<QpArguments>();
  CLI::App* command = app.add_subcommand(
      "qp", "Solve min 1/2 x'Ax - b'x subject to l <= x <= u (and discs) with MPRGP (MPGP); print a JSON report");
  command
      ->add_option("--A", arguments->matrix_path,
                   "symmetric positive definite matrix A "
                   "(Matrix Market coordinate)")
      ->required();
  command->add_option("--b", arguments->rhs_path, "right-hand side b (Matrix Market vector)")->required();
  command->add_option("--lower", arguments->lower_path,
                      "lower bounds l (Matrix Market vector, -inf allowed); default: none");
  command->add_option("--upper", arguments->upper_path,
                      "upper bounds u (Matrix Market vector, inf allowed, l <= u); default: none");
  command->add_option("--discs", arguments->discs_path,
                      "discs ||(x_i, x_j)|| <= r: a text file of lines 'i j r', 1-based indices, no bounds "
                      "on disc components; solved by MPGP (standard expansion); default: none");
  command->add_option("--rtol", arguments->rtol, "stop when |g_P| <= rtol |b|")->capture_default_str();
  command->add_option("--max-iterations", arguments->max_iterations, "MPRGP steps allowed")->capture_default_str();
  command->add_option("--out", arguments->output_path, "write the solution x (Matrix Market)");
  command
      ->add_option("--expansion", arguments->expansion,
                   "expansion step: std (half step + projected gradient) or projcg (projected CG step)")
      ->check(CLI::IsMember({"std", "projcg"}))
      ->capture_default_str();
  command->add_flag("--monitor", arguments->monitor, "one line per MPRGP step on stderr");
  command->callback([arguments] { run_qp(*arguments); });
}
} // namespace feticon::app
