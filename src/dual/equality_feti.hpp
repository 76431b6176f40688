#pragma once
/// @file FETI with equality constraints only (gluing + Dirichlet): projected CG.
///
///   min 1/2 lambda' F lambda - lambda' d   s.t.  G lambda = e,
/// solved as lambda = lambda~ + mu, mu in Ker G, P F P mu = P (d - F lambda~) by CG with the
/// projector P applied to every residual (Farhat–Roux; Dostál et al. 2006 for Total FETI),
/// optionally preconditioned by the lumped preconditioner P B K B' P.

#include "dual/feti_operators.hpp"
#include "qp/conjugate_gradient.hpp"

namespace feticon::dual
{
struct FetiSolution
{
  la::Vector u;      ///< stacked primal displacement
  la::Vector lambda; ///< multipliers
  la::Vector alpha;  ///< rigid-body amplitudes
  qp::QpReport report;
};

enum class FetiPreconditioner
{
  none,
  lumped,   ///< B K B'
  dirichlet ///< B S B' (needs the Schur complements)
};

/// @param f_stacked stacked load (each global force split among the copies of its node)
FetiSolution solve_equality_feti(const FetiOperators& feti, const la::Vector& c, const la::Vector& f_stacked,
                                 const qp::CgOptions& options,
                                 FetiPreconditioner preconditioner = FetiPreconditioner::lumped,
                                 const decomposition::SchurComplements* schur = nullptr);
} // namespace feticon::dual
