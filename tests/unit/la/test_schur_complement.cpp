/// la::schur_complement and la::invert_spd against dense Eigen computations of the same
/// formulas (S = A_bb - A_bi A_ii^-1 A_ib by a dense Cholesky of A_ii; the inverse by a dense
/// LU), on graded and singular matrices.

#include "common/error.hpp"
#include "la/schur_complement.hpp"
#include "tests/support/dense_schur.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace feticon;

namespace
{
/// Graph Laplacian of an n x n grid with edge weights spanning `contrast` (a graded mesh's
/// stiffness range), plus `mass` times the identity (0: singular, kernel = constants).
la::SparseMatrix grid_laplacian(int n, double contrast, double mass)
{
  std::vector<la::Triplet> t;
  auto node = [n](int i, int j) { return i * n + j; };
  auto weight = [&](int i, int j) { return std::pow(contrast, (i + 0.5 * j) / (1.5 * n)); };
  auto edge = [&](int a, int b, double w) {
    t.emplace_back(a, a, w);
    t.emplace_back(b, b, w);
    t.emplace_back(a, b, -w);
    t.emplace_back(b, a, -w);
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      if (i + 1 < n)
        edge(node(i, j), node(i + 1, j), weight(i, j));
      if (j + 1 < n)
        edge(node(i, j), node(i, j + 1), weight(i, j));
      if (mass > 0)
        t.emplace_back(node(i, j), node(i, j), mass);
    }
  la::SparseMatrix A(n * n, n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// The grid's outer ring of nodes, in a scrambled order (the result follows the given order).
std::vector<int32_t> ring(int n)
{
  std::vector<int32_t> b;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i == 0 || j == 0 || i == n - 1 || j == n - 1)
        b.push_back(i * n + j);
  for (size_t k = 0; k + 3 < b.size(); k += 3)
    std::swap(b[k], b[k + 2]);
  return b;
}
} // namespace

TEST(SchurComplement, MatchesDenseEliminationOnAGradedMatrix)
{
  const la::SparseMatrix A = grid_laplacian(24, 1e4, 1e-3);
  const auto b = ring(24);
  const la::Matrix S = la::schur_complement(A, b, "graded grid");
  const la::Matrix S_ref = test::dense_schur(la::Matrix(A), b);
  ASSERT_EQ(S.rows(), static_cast<la::Index>(b.size()));
  EXPECT_LT((S - S_ref).norm() / S_ref.norm(), 1e-12);
  EXPECT_LT((S - S.transpose()).norm() / S.norm(), 1e-15);
}

TEST(SchurComplement, SingularMatrixKeepsItsKernel)
{
  // Pure Neumann Laplacian: A 1 = 0, so S 1_b = 0; its interior block is still definite.
  const la::SparseMatrix A = grid_laplacian(20, 1e3, 0);
  const auto b = ring(20);
  const la::Matrix S = la::schur_complement(A, b, "Neumann grid");
  const la::Matrix S_ref = test::dense_schur(la::Matrix(A), b);
  EXPECT_LT((S - S_ref).norm() / S_ref.norm(), 1e-12);
  EXPECT_LT((S * la::Vector::Ones(S.cols())).norm() / S.norm(), 1e-12);
}

TEST(SchurComplement, WholeMatrixAsBoundaryIsTheMatrix)
{
  const la::SparseMatrix A = grid_laplacian(5, 10, 1);
  std::vector<int32_t> all(A.rows());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_LT((la::schur_complement(A, all, "grid") - la::Matrix(A)).norm() / A.norm(), 1e-14);
}

TEST(SchurComplement, IndefiniteInteriorIsAnError)
{
  la::SparseMatrix A = grid_laplacian(6, 1, 1);
  A.coeffRef(14, 14) = -50; // an interior node (not on the ring)
  EXPECT_THROW(la::schur_complement(A, ring(6), "indefinite grid"), Error);
}

TEST(InvertSpd, InverseOfAnIllScaledMatrix)
{
  const la::SparseMatrix A = grid_laplacian(12, 1e3, 1e-2);
  la::Matrix inverse(A);
  la::invert_spd(inverse, "grid");
  const la::Matrix reference = la::Matrix(A).lu().inverse();
  EXPECT_LT((inverse - reference).norm() / reference.norm(), 1e-10);
  la::Matrix not_definite = -la::Matrix(A);
  EXPECT_THROW(la::invert_spd(not_definite, "negative grid"), Error);
}
