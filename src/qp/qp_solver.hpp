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
  virtual QpReport solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x) = 0;
  /// The expansion step length in use (the solver halves it when a step increased the cost).
  virtual double alpha_bar() const = 0;
};
} // namespace feticon::qp
