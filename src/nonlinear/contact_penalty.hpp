#pragma once
/// @file Penalty springs on contact rows, shared by the primal penalty solver and the bonded
/// direct reference (bonded_direct_solve.hpp).
///
/// For normalized rows B u <= c the springs of an active set A add B_A' E B_A to K and
/// B_A' E c_A to the load, E = diag(eps_i), eps_i = eps_n A_i / mean(A) with A_i the slave
/// node's tributary area (a per-area penalty). A contact law's springs (row_spring) serve the
/// primal penalty and, as the compliance 1 / spring on the dual rows, the FETI solver.

#include "contact/contact_constraints.hpp"
#include "la/types.hpp"

#include <vector>

namespace feticon::nonlinear
{
/// @brief Penalty eps_i (N/m) of every row: eps_n times the slave node's tributary area over
/// the mean one, so that a uniform penetration gives a uniform pressure (a node-wise spring
/// would give the half-area node on a symmetry plane twice the pressure of its neighbours).
la::Vector row_penalties(const contact::ContactConstraints& rows, double eps_n);

/// @brief The spring of a contact law on one normalized row (contact.law = deck): the law's
/// tangent p = k (d - d_0) at the row's overclosure d = -|b| c (fem::NormalLaw::tangent) is the
/// spring k A |b|^2 (N/m; A the slave node's area) on B u - c, with c shifted by d_0 / |b|
/// (contact_constraints.hpp: B u - c is the overclosure over |b|, lambda |b| A times the pressure).
struct RowSpring
{
  double stiffness; ///< k A |b|^2
  double shift;     ///< d_0 / |b|, added to c
};
RowSpring row_spring(const fem::NormalLaw& law, double area, double row_norm, double c);

/// @brief The area row i's law acts on: the slave node's, or where the law says so
/// (fem::NormalLaw::on_master_face) and the row has one, the master face's.
double law_area(const contact::ContactConstraints& rows, la::Index i, const fem::NormalLaw& law);

/// @brief The springs (and c's shifts) of `law` on every row of `rows` (row_spring).
void law_springs(const contact::ContactConstraints& rows, const fem::NormalLaw& law, la::Vector& stiffness,
                 la::Vector& shift);

/// @brief B_A' E B_A and B_A' E c_A (E = diag of row penalties `eps`) for the rows flagged
/// in `active` (one flag per row).
void penalty_terms(const contact::ContactConstraints& rows, const std::vector<char>& active, const la::Vector& eps,
                   la::SparseMatrix& K_pen, la::Vector& f_pen);
} // namespace feticon::nonlinear
