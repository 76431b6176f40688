#pragma once
/// @file Primal solution from multipliers: u = K+(f - B' lambda) + R alpha.
///
/// alpha solves G_A' alpha = (F lambda - d)_A on the active rows A (equality rows and
/// contact rows with positive multiplier) in the least-squares sense:
///   alpha = (G_A G_A')^{-1} G_A (F lambda - d)_A   (ALGORITHMS.md section 1).
/// Using all rows instead of the active ones is wrong once a contact row is open.

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

/// @param active  one flag per owned dual row: 1 for rows that hold with equality
/// @param unheld  the error if the active rows leave a rigid-body motion free, where the caller
///                knows the cause (empty: a message listing the usual ones)
PrimalSolution recover_primal(const FetiOperators& feti, const la::Vector& f_stacked, const la::Vector& c,
                              const la::Vector& lambda, const std::vector<char>& active,
                              const std::string& unheld = {});
} // namespace feticon::dual
