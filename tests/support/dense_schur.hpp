#pragma once
/// @file Reference Schur complement for tests: S = A_bb - A_bi A_ii^-1 A_ib by dense
/// elimination (Eigen LLT of A_ii), independent of la::schur_complement's partial factorization.

#include "la/types.hpp"

#include <cstdint>
#include <vector>

namespace feticon::test
{
/// The DOFs of A (n x n) not in `boundary`, increasing.
inline std::vector<int32_t> interior_of(la::Index n, const std::vector<int32_t>& boundary)
{
  std::vector<char> on(n, 0);
  for (int32_t b : boundary)
    on[b] = 1;
  std::vector<int32_t> interior;
  for (int32_t k = 0; k < n; ++k)
    if (!on[k])
      interior.push_back(k);
  return interior;
}

/// S on `boundary`, in its order; A_ii must be positive definite.
inline la::Matrix dense_schur(const la::Matrix& A, const std::vector<int32_t>& boundary)
{
  const std::vector<int32_t> interior = interior_of(A.rows(), boundary);
  const la::Matrix A_ib = A(interior, boundary);
  return A(boundary, boundary) - A_ib.transpose() * A(interior, interior).llt().solve(A_ib);
}
} // namespace feticon::test
