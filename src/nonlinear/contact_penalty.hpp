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

/// @brief The springs of a linear pressure-overclosure law p = K d (contact.law = deck): K A_i
/// |b_i|^2 (N/m) for the normalized row i, whose B_i u - c_i is the overclosure over |b_i|
/// (contact_constraints.hpp), A_i its slave node's area.
la::Vector law_penalties(const contact::ContactConstraints& rows, double slope);
/// @brief The overclosure at which `law`'s pressure starts, sigma_inf / K, in the units of each
/// normalized row's c (over |b_i|): the shift of c that makes the springs law_penalties its law.
la::Vector law_shifts(const contact::ContactConstraints& rows, const fem::NormalLaw& law);

/// @brief B_A' E B_A and B_A' E c_A (E = diag of row penalties `eps`) for the rows flagged
/// in `active` (one flag per row).
void penalty_terms(const contact::ContactConstraints& rows, const std::vector<char>& active, const la::Vector& eps,
                   la::SparseMatrix& K_pen, la::Vector& f_pen);
} // namespace feticon::nonlinear
