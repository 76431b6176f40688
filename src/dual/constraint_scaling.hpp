#pragma once
/// @file Y = (B B')^{-1}: the scaling that fits the FETI preconditioners to constraint rows
/// that are not orthonormal.
///
/// The lumped and Dirichlet preconditioners B X B' approximate F^{-1} = (B K+ B')^{-1} only
/// when B B' = I; a general B needs M = Y B X B' Y (the mortar FETI preconditioner of
/// Stefanica & Klawonn 2000; Lacour & Maday 1997). Our gluing and Dirichlet rows are
/// orthonormal (B_E B_E' = I), but a mortar or node-to-segment contact row shares its master
/// nodes with its neighbours and its slave and master copies with gluing rows. Without Y the
/// smallest eigenvalue of M F on such rows falls to about 0.1 and keeps falling as the
/// contact zone gets more subdomains (docs/distributed.md, weak scaling).
///
/// B B' differs from I only on the block C of the contact rows and the equality rows that
/// share a degree of freedom with one, and on the tie rows (decomposition/constraint_rows.hpp),
/// which are left out of C: each is of unit norm and they are nearly orthogonal, and their
/// block is large and fills in. Measured on a tie of 101 200 rows (two 1 x 1 x 0.05 plates of
/// 150^2 and 183^2 hex8 cells, 340k DOFs, 32 subdomains; docs/contact.md, "Ties"): with the tie
/// rows in C, 59 MPRGP steps in 19.2 s (a block of 108k rows, 22M nonzeros in its factor,
/// whose solve cost five times an F product a step); with Y = I on them, 100 steps in 5.8 s. That block, a few rows per contact row, is assembled
/// from the subdomain products B_s B_s', replicated on every rank like G G' and factorized
/// once per dual problem; Y is the identity elsewhere.

#include "dual/feti_operators.hpp"

#include <Eigen/SparseCholesky>

namespace feticon::dual
{
class ConstraintScaling
{
public:
  /// Largest (B B')_CC^{-1} eigenvalue accepted; above it the rows count as nearly
  /// dependent. Measured: 4.6 on hertz3d with friction, 2.5e6 with a nearly repeated row.
  static constexpr double max_amplification = 1e3;

  /// @param n_equality rows with a global id below it are equality rows (B_E B_E' = I).
  ///        If the block is singular or nearly so (dependent rows; max_amplification), Y
  ///        falls back to the identity with a warning and factorized() is false.
  /// @param held owned rows (by dual index) on which Y is the identity, apart from the rest:
  ///        friction rows that supports hold (FrictionRows::held; fixed at 0 in the QP), which
  ///        nearly repeat support rows and would make the block nearly singular. Empty: none.
  ConstraintScaling(const FetiOperators& feti, int64_t n_equality, const std::vector<char>& held = {});

  /// Rows of the block C over all ranks (0: Y = I, nothing to scale).
  int64_t block_size() const { return static_cast<int64_t>(_ids.size()); }
  bool factorized() const { return _factorized; }
  /// Y lambda for an owned dual vector.
  la::Vector apply(const la::Vector& lambda) const;

private:
  const FetiOperators& _feti;
  std::vector<int64_t> _ids;                   ///< global ids of C, increasing
  std::vector<la::Index> _owned_rows;          ///< owned dual indices in C
  std::vector<int64_t> _owned_positions;       ///< and their positions in C
  std::vector<int64_t> _gathered_positions;    ///< positions in C of every rank's rows
  Eigen::SimplicialLLT<la::SparseMatrix> _llt; ///< (B B')_CC = L L'
  bool _factorized = false;
};
} // namespace feticon::dual
