#pragma once
/// @file A supernodal Cholesky factor kept in single precision, applied in double.
///
/// The substitutions with the subdomain factors are most of a 3D FETI step, and they are
/// bound by the memory traffic of reading the factor (docs/benchmarks.md, "Single-precision
/// factors"). CHOLMOD factorizes in double; this copy rounds each entry of L to float, which
/// halves both that traffic and the factors' memory, and does the substitutions in double
/// arithmetic. So the operator it applies is exactly (L~ L~')^{-1} with L~ = fl(L): the
/// inverse of a fixed SPD matrix A + E, |E| <= 2 eps_float |L| |L'| (backward stable), and
/// the Krylov solvers around it see a consistent linear operator, not noise.

#include "la/types.hpp"

#include <cholmod.h>

#include <vector>

namespace feticon::la
{
/// The AVX2/FMA kernels where the CPU has them (the default), or the portable ones (for the
/// tests of the fallback); returns whether the vector kernels are in use. Not thread-safe:
/// call it outside any solve.
bool use_vector_kernels(bool on);

class SinglePrecisionFactor
{
public:
  /// Copies a supernodal LL' factor of CHOLMOD (int indices); `L` may be freed afterwards.
  explicit SinglePrecisionFactor(const cholmod_factor& L);

  /// x = A^{-1} b.
  Vector solve(const Vector& b) const;
  Matrix solve(const Matrix& B) const;
  Index size() const { return static_cast<Index>(_permutation.size()); }
  /// Entries of L (as CHOLMOD's factor of the same matrix counts them).
  long nonzeros() const { return static_cast<long>(_values.size()); }

private:
  /// Supernode k: columns [first, first + ncol) of nrow rows (the first ncol its triangle),
  /// whose last `below` rows are below_rows of the factor; `block` holds its lower trapezoid
  /// packed by columns, column j from its diagonal entry down (nrow - j entries).
  struct Supernode
  {
    Index first, ncol, nrow, below;
    const float* block;
    const int* below_rows;
    /// Column j's diagonal entry; the entry in row i >= j is diagonal(j)[i - j].
    const float* diagonal(Index j) const { return block + j * nrow - j * (j - 1) / 2; }
    /// Entries from a row of column j to the same row of column j + 1.
    Index step(Index j) const { return nrow - j - 1; }
  };
  Supernode supernode(size_t k) const;
  /// y = L^{-1} y, then y = L'^{-1} y, in the factor's (permuted) order.
  void forward(double* y, double* work) const;
  void backward(double* y, double* work) const;

  std::vector<int> _permutation;  ///< row k of the factor is row _permutation[k] of A
  std::vector<int> _first_column; ///< supernode k: columns [_first_column[k], _first_column[k+1])
  std::vector<int> _row_start;    ///< supernode k: rows _rows[_row_start[k] ...]
  std::vector<long> _value_start; ///< supernode k: its packed lower trapezoid in _values
  std::vector<int> _rows;         ///< the first rows of a supernode are its own columns
  std::vector<float> _values;
  Index _max_rows = 0; ///< the largest supernode's row count (workspace size)
};
} // namespace feticon::la
