#pragma once
/// @file The interface of the solvers of  min 1/2 x'Ax - b'x  subject to  x in Omega, Omega a
/// set of separable convex constraints (qp::SeparableConstraints): MPRGP for bounds, and the
/// inner solver of SMALBE-M (SmalbeOptions::inner_solver), which builds one for each
/// augmented Hessian it forms (PERMON's QPS under SMALXE).

#include "la/types.hpp"
#include "qp/qp_report.hpp"
#include "qp/separable_constraints.hpp"

namespace feticon::qp
{
class QpSolver
{
public:
  virtual ~QpSolver() = default;
  /// @param[in,out] x the initial guess (projected onto Omega), the last iterate on output
  /// @param[in,out] gradient null, or on input empty or g = A x - b at the given x, which then
  ///        lies in Omega (the solve starts from it instead of a product: SMALBE-M's next inner
  ///        solve, whose b changes by C' (omega - omega_old) only), and on output g at the
  ///        returned x (the solver's recursive gradient)
  virtual QpReport solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x, la::Vector* gradient) = 0;
  QpReport solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x)
  {
    return solve(b, set, x, nullptr);
  }
  /// The expansion step length in use (the solver halves it when a step increased the cost).
  virtual double alpha_bar() const = 0;
};
} // namespace feticon::qp
