#pragma once
/// @file The one wrapper around SuiteSparse CHOLMOD (via Eigen's CholmodSupport).
///
/// Sparse Cholesky of a symmetric positive definite matrix with a fill-reducing ordering:
/// METIS's nested dissection of the node graph for 3D matrices from 3 000 DOFs
/// (nodal_ordering.hpp), CHOLMOD's choice (AMD/METIS) otherwise. Used for the regularized subdomain stiffnesses of the
/// generalized inverse and for direct reference solves of undecomposed problems.

#include "la/types.hpp"

#include <memory>

namespace feticon::la
{
/// Right-hand sides per multi-column solve: enough columns for BLAS-3 substitutions, few
/// enough that the workspace stays in cache (docs/measurements.md).
inline constexpr Index solve_block = 32;

/// What a factor's entries are stored in once factorized (single_precision_factor.hpp).
enum class FactorPrecision
{
  double_precision,
  single_precision ///< supernodal factors only; simplicial ones (small) stay in double
};

class CholmodFactor
{
public:
  CholmodFactor();
  ~CholmodFactor();
  CholmodFactor(CholmodFactor&&) noexcept;
  CholmodFactor& operator=(CholmodFactor&&) noexcept;

  /// Factorizes the SPD matrix `A` (full symmetric storage; the lower triangle is read).
  /// Throws feticon::Error if `A` is not positive definite, naming `what`.
  void factorize(const SparseMatrix& A, const char* what = "matrix",
                 FactorPrecision precision = FactorPrecision::double_precision);
  /// x = A^{-1} b.
  Vector solve(const Vector& b) const;
  Matrix solve(const Matrix& B) const;
  bool factorized() const { return _impl != nullptr; }
  /// True if the entries are kept in single precision.
  bool single_precision() const;
  /// Nonzeros in the Cholesky factor (memory and cost indicator).
  long factor_nonzeros() const;
  /// CHOLMOD's estimate of the reciprocal condition number, (min L_jj / max L_jj)^2 (LL') or
  /// min |D_jj| / max |D_jj| (LDL'): of the order of machine epsilon where A is singular and
  /// the factorization passed on a pivot at round-off.
  double reciprocal_condition() const;

private:
  struct Impl;
  std::unique_ptr<Impl> _impl;
};
} // namespace feticon::la
