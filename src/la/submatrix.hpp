#pragma once
/// @file Principal submatrices of sparse matrices (restriction to a subset of DOFs).

#include "la/types.hpp"

#include <vector>

namespace feticon::la
{
/// The rows and columns i of the square matrix A with position[i] >= 0, row/column i becoming
/// position[i] of the n_kept x n_kept result. Used to drop eliminated, constrained or fixing
/// DOFs before a factorization.
SparseMatrix principal_submatrix(const SparseMatrix& A, const std::vector<int32_t>& position,
                                 int32_t n_kept);
} // namespace feticon::la
