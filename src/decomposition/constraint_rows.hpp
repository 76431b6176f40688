#pragma once
/// @file Rows of the constraint matrix B = [B_E; B_I] in subdomain terms, with c.
///
/// A row is a list of (subdomain, active DOF, coefficient) entries; the constraint is
/// b_i u = c_i (equality rows) or b_i u <= c_i (contact rows). This format needs no
/// global matrix. Every row carries its global row id: distributed over ranks, a rank holds
/// only the rows that touch its subdomains (each with all its entries, also those on other
/// ranks' subdomains, so that both sides of an interface know who shares a row).

#include "decomposition/decomposition.hpp"
#include "fem/dirichlet.hpp"
#include "fem/problem.hpp"

#include <span>
#include <string>
#include <vector>

namespace feticon::decomposition
{
struct RowEntry
{
  int32_t subdomain;
  int32_t dof; ///< active DOF within the subdomain
  double value;
};

class ConstraintRows
{
public:
  /// Adds a row with global id `id` (ids must increase).
  void add_row(std::span<const RowEntry> entries, double c, int64_t id);
  /// Appends all rows of `other`, their ids shifted by `id_offset`.
  void append(const ConstraintRows& other, int64_t id_offset);
  /// Rows held here (on one rank: all rows) and the global id of row i.
  int64_t n_rows() const { return static_cast<int64_t>(_c.size()); }
  int64_t id(int64_t i) const { return _ids[i]; }
  std::span<const RowEntry> row(int64_t i) const;
  const std::vector<double>& c() const { return _c; }
  la::Vector c_vector() const;

private:
  std::vector<int64_t> _offsets{0};
  std::vector<RowEntry> _entries;
  std::vector<double> _c;
  std::vector<int64_t> _ids;
};

/// Equality rows B_E of Total FETI: orthonormal gluing rows (Helmert rows for a node with
/// p copies: (sum_{t<=q} e_t - q e_{q+1}) / sqrt(q(q+1)), q = 1..p-1) for every component
/// that is not prescribed, and for prescribed components a unit row on every copy with
/// c = prescribed value (ALGORITHMS.md section 3); then one row per linear equation
/// (*EQUATION, fem/linear_equations.hpp) with c = 0, or minus its terms on prescribed DOFs.
///
/// B_E B_E' = I, which the projectors do not need but the preconditioners' scaling does
/// (dual/constraint_scaling.hpp takes the equality block as I, and B S B' approximates F^-1 only
/// for orthonormal rows). The equation rows keep it: a term's coefficient is split equally over
/// the p copies of its node, a/p on each, which is orthogonal to that node's gluing rows (they
/// span the complement of (1,...,1)) and, on glued displacements, says the same as the whole
/// coefficient on one copy; terms on prescribed DOFs move to c (orthogonal to the unit rows,
/// and the same on their feasible set); the equations that share a DOF are orthonormalized
/// among themselves (thin QR in the inner product of the split rows: a combination of
/// equations, with c combined alike, is the same constraint). Row e of the result combines
/// equations 1..e of its group, so a multiplier is no longer that of one equation.
///
/// Tie rows (fem::Problem::tie_equations, contact/tie_rows.hpp) come last, a block of their own:
/// reduced against the supports like the equations (a tie whose slave DOF this step holds is
/// dropped: the support wins) and split over the copies alike, then each scaled to unit norm,
/// not orthonormalized: every tie row has a slave DOF of its own, so they are independent, and
/// the dense orthonormalization of a tied surface's rows (all linked through master nodes) would
/// cost O(n m^2) (ALGORITHMS.md section 10). B B' is then near I on them, not equal: the
/// preconditioner's scaling takes it as I (dual/constraint_scaling.hpp says why).
///
/// Supports of held DOFs beyond the global ones, along local axes (fem/node_frames.hpp) and on
/// reference nodes (fem/coupling.hpp), are equation rows sum_k a_k u_k = value with the
/// combination `held` gives them (fem::Problem::held_combinations), first among the equations
/// (CalculiX makes them multi-point constraints likewise).
///
/// Ids: gluing rows in node order, then Dirichlet rows, then equation rows in equation order,
/// then tie rows in their order; only rows touching owned subdomains are kept (every rank builds
/// every row, the same way).
/// @throws feticon::Error naming the equation if one has no free term or is linearly dependent
///         on the supports and the equations before it (fem/linear_equations.hpp).
struct EqualityRows
{
  ConstraintRows rows;
  int64_t n_gluing = 0; ///< global counts
  int64_t n_dirichlet = 0;
  int64_t n_equations = 0;
  int64_t n_ties = 0;
  int64_t n_global() const { return n_gluing + n_dirichlet + n_equations + n_ties; }
};
EqualityRows build_equality_rows(const Decomposition& decomposition, const fem::ConstrainedDofs& dirichlet,
                                 const std::vector<fem::LinearEquation>& equations = {},
                                 const std::vector<fem::LinearEquation>& ties = {},
                                 const std::vector<fem::DofCombination>& held = {});

/// Converts rows over global mesh DOFs (3*node + component; `B_global` row-major, one row
/// per constraint) to subdomain rows. A DOF shared by several subdomains is put on its
/// first copy (the copies are glued). Entries on eliminated components are dropped: those
/// components are identically zero. Row r gets id r; only rows touching owned subdomains
/// are kept.
ConstraintRows rows_from_global(const Decomposition& decomposition,
                                const Eigen::SparseMatrix<double, Eigen::RowMajor>& B_global, const la::Vector& c);
} // namespace feticon::decomposition
