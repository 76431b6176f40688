#pragma once
/// @file Penalty springs on contact rows, shared by the primal penalty solver and the bonded
/// direct reference (bonded_direct_solve.hpp).
///
/// For normalized rows B u <= c the springs of an active set A add B_A' E B_A to K and
/// B_A' E c_A to the load, E = diag(eps_i), eps_i = eps_n A_i / mean(A) with A_i the slave
/// node's tributary area (a per-area penalty).

#include "contact/contact_constraints.hpp"
#include "la/types.hpp"

#include <vector>

namespace feticon::nonlinear
{
/// @brief Penalty eps_i (N/m) of every row: eps_n times the slave node's tributary area over
/// the mean one, so that a uniform penetration gives a uniform pressure (a node-wise spring
/// would give the half-area node on a symmetry plane twice the pressure of its neighbours).
la::Vector row_penalties(const contact::ContactConstraints& rows, double eps_n);

/// @brief B_A' E B_A and B_A' E c_A (E = diag of row penalties `eps`) for the rows flagged
/// in `active` (one flag per row).
void penalty_terms(const contact::ContactConstraints& rows, const std::vector<char>& active, const la::Vector& eps,
                   la::SparseMatrix& K_pen, la::Vector& f_pen);
} // namespace feticon::nonlinear
