#include "qp/solve_stop.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "la/vector_space.hpp"
#include "qp/norm_estimate.hpp"

#include <cmath>
#include <cstdio>

namespace feticon::qp
{
std::string format_number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", value);
  return text;
}

std::optional<SolveStop> stopping_test(const StopTest& stop, int max_iterations, const QpReport& report,
                                       const la::Vector& x, const la::Vector& g, double gp_norm, double tolerance,
                                       double b_norm)
{
  const bool custom_stop = static_cast<bool>(stop);
  // Stopping tests, in this order: a NaN must not pass as converged.
  if (!std::isfinite(gp_norm))
    return SolveStop{false,
                     "projected gradient norm is not finite (" + format_number(gp_norm) + ") at iteration " +
                         std::to_string(report.iterations)};
  if (custom_stop && stop(x, g, gp_norm))
    return SolveStop{true, "caller's stopping test met, |g_P| = " + format_number(gp_norm)};
  if (!custom_stop && gp_norm <= tolerance)
    return SolveStop{true,
                     "|g_P| = " + format_number(gp_norm) + " <= " + (b_norm > 0.0 ? "rtol |b| = " : "rtol (b = 0) = ") +
                         format_number(tolerance)};
  if (gp_norm == 0.0)
    return SolveStop{true, "projected gradient is exactly zero (KKT conditions hold)"};
  if (report.iterations >= max_iterations)
    return SolveStop{false,
                     "maximum number of iterations (" + std::to_string(max_iterations) +
                         ") reached, |g_P| = " + format_number(gp_norm)};
  return std::nullopt;
}

std::optional<std::string> estimate_alpha_bar(const la::LinearOperator& A, int power_iterations, QpReport& report,
                                              double& alpha_bar)
{
  const NormEstimate norm = estimate_norm(A, power_iterations, 1e-3, 1);
  report.hessian_multiplications += norm.applications;
  if (!std::isfinite(norm.value))
    return "power iteration for ||A|| gave a non-finite Rayleigh quotient "
           "v'Av = " +
        format_number(norm.value);
  if (!(norm.value > 0.0))
    return "operator is not positive definite: power iteration Rayleigh "
           "quotient v'Av = " +
        format_number(norm.value) + " <= 0";
  alpha_bar = 1.8 / norm.value;
  return std::nullopt;
}

void check_solver_options(const char* who, double rtol, double gamma, int max_iterations, double alpha_bar,
                          int power_iterations, int gradient_refresh)
{
  FETICON_CHECK(rtol >= 0.0, who << ": rtol = " << rtol << " must be >= 0");
  FETICON_CHECK(gamma > 0.0, who << ": gamma = " << gamma << " must be > 0");
  FETICON_CHECK(max_iterations >= 0, who << ": max_iterations = " << max_iterations << " must be >= 0");
  FETICON_CHECK(alpha_bar >= 0.0 && std::isfinite(alpha_bar),
                who << ": alpha_bar = " << alpha_bar << " must be > 0 (or 0 to estimate 1.8/||A||)");
  FETICON_CHECK(power_iterations >= 1, who << ": power_iterations = " << power_iterations << " must be >= 1");
  FETICON_CHECK(gradient_refresh >= 1, who << ": gradient_refresh = " << gradient_refresh << " must be >= 1");
}

void log_iterate(const char* solver, const MprgpIterate& it, double tolerance, bool custom_stop)
{
  char line[160];
  if (custom_stop)
    std::snprintf(line, sizeof line, "%s %6d %-13s |g_P| %.3e |phi| %.3e |beta| %.3e tol caller  f %.9e", solver,
                  it.iteration, to_string(it.step), it.projected_gradient_norm, it.free_gradient_norm,
                  it.chopped_gradient_norm, it.cost);
  else
    std::snprintf(line, sizeof line, "%s %6d %-13s |g_P| %.3e |phi| %.3e |beta| %.3e tol %.3e f %.9e", solver,
                  it.iteration, to_string(it.step), it.projected_gradient_norm, it.free_gradient_norm,
                  it.chopped_gradient_norm, tolerance, it.cost);
  log::iteration(line);
}
bool given_gradient_holds(const la::VectorSpace& space, const la::Vector* gradient, const la::Vector& x_given,
                          const la::Vector& x)
{
  return gradient && space.max(gradient->size() == x.size() && x == x_given ? 0.0 : 1.0) == 0.0;
}
} // namespace feticon::qp
