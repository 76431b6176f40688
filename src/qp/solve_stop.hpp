#pragma once
/// @file What MPRGP and MPGP share around their steps: the stopping test, the expansion step
/// length alpha_bar from the norm estimate, the start from a given gradient, the log line of an
/// iterate, numbers in messages.

#include "la/operator.hpp"
#include "qp/mprgp.hpp"
#include "qp/qp_report.hpp"

#include <functional>
#include <optional>
#include <string>

namespace feticon::qp
{
/// How a solve ends: the test that was met, or what stopped it.
struct SolveStop
{
  bool converged;
  std::string reason;
};

/// The caller's stopping test of MprgpOptions::stop and MpgpOptions::stop.
using StopTest = std::function<bool(const la::Vector& x, const la::Vector& g, double projected_gradient_norm)>;

/// A number as "%.3e", for messages.
std::string format_number(double value);

/// @brief Why the solve stops at x with ||g_P|| = gp_norm (no value while it goes on), in
///        this order: a non-finite norm, the caller's test `stop` if set (else
///        gp_norm <= tolerance), g_P = 0 exactly, report.iterations >= max_iterations.
/// @param[in] b_norm  ||b||, to word the default test (rtol ||b|| or, for b = 0, rtol).
std::optional<SolveStop> stopping_test(const StopTest& stop, int max_iterations, const QpReport& report,
                                       const la::Vector& x, const la::Vector& g, double gp_norm, double tolerance,
                                       double b_norm);

/// Whether a solve starts from the caller's gradient (QpSolver::solve): given, of x's size,
/// and x the same as given (`x_given`, before the projection onto the set) on every rank,
/// since the product it replaces is collective.
bool given_gradient_holds(const la::VectorSpace& space, const la::Vector* gradient, const la::Vector& x_given,
                          const la::Vector& x);

/// @brief alpha_bar = 1.8 / nu with nu from estimate_norm(A, power_iterations), its products
///        added to report.hessian_multiplications; a reason when nu is not finite or not
///        positive (alpha_bar unchanged then).
std::optional<std::string> estimate_alpha_bar(const la::LinearOperator& A, int power_iterations, QpReport& report,
                                              double& alpha_bar);

/// @brief Checks the parameters MprgpOptions and MpgpOptions share (FETICON_CHECK, `who` names
///        the solver): rtol >= 0, gamma > 0, max_iterations >= 0, alpha_bar >= 0 and finite,
///        power_iterations >= 1, gradient_refresh >= 1.
void check_solver_options(const char* who, double rtol, double gamma, int max_iterations, double alpha_bar,
                          int power_iterations, int gradient_refresh);

/// One log line (level `iterations`) of an iterate of `solver` ("mprgp", "mpgp").
void log_iterate(const char* solver, const MprgpIterate& it, double tolerance, bool custom_stop);
} // namespace feticon::qp
