#pragma once
/// @file (Projected) conjugate gradients for A x = b with A symmetric positive definite on
/// the range of an optional orthogonal projector P.
///
/// Hestenes & Stiefel (1952), "Methods of conjugate gradients for solving linear systems",
/// J. Res. Nat. Bur. Standards 49; projected variant of Farhat & Roux (1991) for FETI, where
/// A = PFP, b = P d and every residual is projected, r_k = P(b - A x_k), to stop round-off
/// from leaving Im P. The iterate stays in Im P when x_0 does. Stops on
/// ||P r|| <= rtol ||P b|| (absolute ||P r|| <= rtol when P b = 0).
///
/// Operator products (QpReport::hessian_multiplications): 1 for the initial residual, none
/// when x_0 = 0 exactly, plus 1 per iteration. Projector applications are not counted: 2 at
/// the start (P b and P r_0) and 1 per iteration.
///
/// Usage:
///   la::Vector x = la::Vector::Zero(n);
///   const qp::QpReport report = qp::conjugate_gradient(A, b, x, {.rtol = 1e-8});
///   const qp::QpReport dual = qp::conjugate_gradient(PFP, Pd, lambda, {}, &P);

#include "la/operator.hpp"
#include "la/vector_space.hpp"
#include "qp/qp_report.hpp"

#include <functional>

namespace feticon::qp
{
/// Parameters of conjugate_gradient.
struct CgOptions
{
  /// Stop when ||P r|| <= rtol ||P b||.
  double rtol = 1e-6;
  /// Iterations allowed before the solve stops unconverged.
  int max_iterations = 10000;
  /// If set, called with (iteration, ||P r||) at the start and after every iteration.
  std::function<void(int iteration, double residual_norm)> monitor{};
  /// Optional symmetric positive (semi)definite preconditioner M: directions are
  /// z = P M P r. Not owned; must outlive the solve. Stopping stays on ||P r||.
  const la::LinearOperator* preconditioner = nullptr;
};

/// @brief Solves A x = b by (projected) conjugate gradients.
/// @param[in]     A          symmetric operator, positive definite on Im P (on all vectors
///                           when projector is null); referenced only during the call.
/// @param[in]     b          right-hand side, finite, size A.size().
/// @param[in,out] x          initial guess on input (finite, size A.size(), in Im P for the
///                           projected variant), solution on output.
/// @param[in]     options    tolerances and monitor.
/// @param[in]     projector  optional orthogonal projector P of size A.size(); null means I.
/// @return report with iterations = cg_steps, hessian_multiplications as in the file
///         comment, projected_gradient_norm = ||P r||, cost = 1/2 x'Ax - b'x, ritz = the
///         extreme eigenvalues of P M P A on Im P estimated from the run; converged =
///         false with a reason on max_iterations, a non-finite residual norm or p'Ap <= 0.
/// Throws feticon::Error on size mismatch or non-finite b or x.
QpReport conjugate_gradient(const la::LinearOperator& A, const la::Vector& b, la::Vector& x, const CgOptions& options,
                            const la::LinearOperator* projector = nullptr);
} // namespace feticon::qp
