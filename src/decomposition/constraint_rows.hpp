#pragma once
/// @file Rows of the constraint matrix B = [B_E; B_I] in subdomain terms, with c.
///
/// A row is a list of (subdomain, active DOF, coefficient) entries; the constraint is
/// b_i u = c_i (equality rows) or b_i u <= c_i (contact rows). This format needs no
/// global matrix, so the same rows serve a distributed B later.

#include "decomposition/decomposition.hpp"
#include "fem/dirichlet.hpp"

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
  void add_row(std::span<const RowEntry> entries, double c);
  /// Appends all rows of `other`.
  void append(const ConstraintRows& other);
  int64_t n_rows() const { return static_cast<int64_t>(_c.size()); }
  std::span<const RowEntry> row(int64_t i) const;
  const std::vector<double>& c() const { return _c; }
  la::Vector c_vector() const;

private:
  std::vector<int64_t> _offsets{0};
  std::vector<RowEntry> _entries;
  std::vector<double> _c;
};

/// Equality rows B_E of Total FETI: orthonormal gluing rows (Helmert rows for a node with
/// p copies: (sum_{t<=q} e_t - q e_{q+1}) / sqrt(q(q+1)), q = 1..p-1) for every component
/// that is not prescribed, and for prescribed components a unit row on every copy with
/// c = prescribed value (ALGORITHMS.md section 3). B_E B_E' = I.
struct EqualityRows
{
  ConstraintRows rows;
  int64_t n_gluing = 0;
  int64_t n_dirichlet = 0;
};
EqualityRows build_equality_rows(const Decomposition& decomposition,
                                 const fem::ConstrainedDofs& dirichlet);

/// Converts rows over global mesh DOFs (3*node + component; `B_global` row-major, one row
/// per constraint) to subdomain rows. A DOF shared by several subdomains is put on its
/// first copy (the copies are glued). Entries on eliminated components are dropped: those
/// components are identically zero.
ConstraintRows rows_from_global(const Decomposition& decomposition,
                                const Eigen::SparseMatrix<double, Eigen::RowMajor>& B_global,
                                const la::Vector& c);
} // namespace feticon::decomposition
