#pragma once
/// @file Matrix Market text files (NIST, https://math.nist.gov/MatrixMarket/formats.html):
/// the exchange format of `feticon qp` and of debugging dumps.
///
/// Supported headers (case-insensitive):
///   %%MatrixMarket matrix coordinate real|integer general|symmetric   (sparse matrices)
///   %%MatrixMarket matrix array real|integer general                  (dense column vectors)
/// Values are parsed with strtod, so "inf", "-inf", "Inf", "-Infinity" (unbounded
/// components of a bound vector) are accepted. Every malformed input throws feticon::Error
/// with one line "<path>:<line>: <what is wrong>".
///
/// Usage:
///   const la::SparseMatrix A = la::read_matrix_market_sparse("A.mtx");
///   const la::Vector lower = la::read_matrix_market_dense("l.mtx");
///   la::write_matrix_market_dense("x.mtx", x);

#include "la/types.hpp"

#include <string>

namespace feticon::la
{
/// What a file's header and size line declare, read without its entries (memory guard).
struct MatrixMarketSize
{
  int rows = 0;
  int cols = 0;
  long long entries = 0; ///< stored entries (one triangle of a symmetric file); rows * cols for `array`
  bool symmetric = false;
};
MatrixMarketSize read_matrix_market_size(const std::string& path);

/// @brief Reads a sparse matrix from a `coordinate` file.
/// @param[in] path  the file.
/// @return the matrix; duplicate entries are summed; a `symmetric` file stores one
///         triangle (either one, not both), which is mirrored.
SparseMatrix read_matrix_market_sparse(const std::string& path);

/// @brief Reads a column vector from an `array ... general` file with one column, or from
///        a `coordinate ... general` file with one column (missing entries are 0).
/// @param[in] path  the file.
/// @return the vector.
Vector read_matrix_market_dense(const std::string& path);

/// @brief Writes `vector` as an `array real general` column with 17 significant digits (a
///        round trip through read_matrix_market_dense is exact).
/// @param[in] path    the file, overwritten.
/// @param[in] vector  the values; infinities are written as inf/-inf.
void write_matrix_market_dense(const std::string& path, const Vector& vector);
} // namespace feticon::la
