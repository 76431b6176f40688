#pragma once
/// @file Principal submatrices of sparse matrices (restriction to a subset of DOFs).

#include "la/types.hpp"

#include <vector>

namespace feticon::la
{
/// Which entries principal_submatrix keeps.
enum class Entries
{
  all,
  lower_triangle
};

/// The rows and columns i of the square matrix A with position[i] >= 0, row/column i becoming
/// position[i] of the n_kept x n_kept result; with Entries::lower_triangle only the entries on or
/// below the result's diagonal. Used to drop eliminated, constrained or fixing DOFs before a
/// factorization. If A holds the lower triangle of a symmetric matrix and position increases
/// with i, so does the result.
SparseMatrix principal_submatrix(const SparseMatrix& A, const std::vector<int32_t>& position, int32_t n_kept,
                                 Entries keep = Entries::all);

/// Rows `rows` and columns `cols` (increasing index lists) of the symmetric matrix whose
/// lower triangle `lower` holds.
SparseMatrix symmetric_block(const SparseMatrix& lower, const std::vector<int32_t>& rows,
                             const std::vector<int32_t>& cols);
} // namespace feticon::la
