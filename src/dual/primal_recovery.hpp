#pragma once
/// @file Primal solution from multipliers: u = K+(f - B' lambda) + R alpha.
///
/// alpha solves G_A' alpha = (F lambda - d)_A on the active rows A (equality rows and
/// contact rows with positive multiplier) in the least-squares sense:
///   alpha = (G_A G_A')^{-1} G_A (F lambda - d)_A   (ALGORITHMS.md section 1).
/// Using all rows instead of the active ones is wrong once a contact row is open.
///
/// Friction rows at their bound (the node slides) hold no row with equality. Where the active
/// rows alone leave a rigid-body motion free (every friction row of a body slides: a block
/// dragged one way, free the other), recover_primal determines it from them:
/// - a disc at its bound slides along lambda_t, so the gradient's component across it (along
///   p, perpendicular to lambda_t) vanishes: those components join the active rows;
/// - in the modes these still leave free, alpha gives the least slip: it minimizes the
///   gradient's norm on the sliding rows (the boxes at a bound, the discs' components along
///   the slide), the slip of this solve. The QP leaves that motion undetermined (the slide's
///   end is any point along it); the least slip is feticon's choice: an increment slides no
///   further than its load asks.

#include "dual/feti_operators.hpp"

#include <string>
#include <vector>

namespace feticon::dual
{
struct PrimalSolution
{
  la::Vector u;     ///< stacked primal displacement
  la::Vector alpha; ///< rigid-body amplitudes (multiplier of G lambda = e)
};

/// A disc row pair (owned rows i, j) at its bound, and the unit vector (p_i, p_j) perpendicular
/// to its multiplier (lambda_i, lambda_j).
struct SlidingDisc
{
  la::Index i = 0, j = 0;
  double p_i = 0, p_j = 0;
};

/// The owned friction rows at their bound.
struct SlidingRows
{
  std::vector<SlidingDisc> discs;
  std::vector<la::Index> boxes; ///< single tangential rows (2D, or a node's row beside a held one)
  bool empty() const { return discs.empty() && boxes.empty(); }
};

/// @param active  one flag per owned dual row: 1 for rows that hold with equality
/// @param unheld  the error if the active rows leave a rigid-body motion free, where the caller
///                knows the cause (empty: a message listing the usual ones)
/// @param sliding the owned friction rows at their bound (file comment)
PrimalSolution recover_primal(const FetiOperators& feti, const la::Vector& f_stacked, const la::Vector& c,
                              const la::Vector& lambda, const std::vector<char>& active, const std::string& unheld = {},
                              const SlidingRows& sliding = {});
} // namespace feticon::dual
