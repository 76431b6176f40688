/// Submatrices of a symmetric matrix stored as its lower triangle, as the subdomain stiffness
/// is. Reference: the same rows and columns taken from the full dense matrix; the matrix is
/// random and exactly symmetric, so any entry read from the wrong place or left out shows.
#include "la/submatrix.hpp"

#include <gtest/gtest.h>

#include <random>

namespace feticon::la
{
namespace
{
/// Random sparse symmetric n x n matrix (about a third of the entries nonzero).
SparseMatrix random_symmetric(Index n, unsigned seed)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Triplet> triplets;
  for (Index j = 0; j < n; ++j)
    for (Index i = j; i < n; ++i)
      if (i == j || generator() % 3 == 0)
      {
        const double v = value(generator);
        triplets.emplace_back(i, j, v);
        if (i != j)
          triplets.emplace_back(j, i, v);
      }
  SparseMatrix A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

TEST(Submatrix, SymmetricBlockReadsTheMirroredEntries)
{
  const Index n = 40;
  const SparseMatrix A = random_symmetric(n, 7);
  const SparseMatrix lower = A.triangularView<Eigen::Lower>();
  const Matrix full(A);
  std::vector<int32_t> odd, even, some;
  for (int32_t i = 0; i < n; ++i)
    (i % 2 ? odd : even).push_back(i);
  for (int32_t i = 3; i < n; i += 5)
    some.push_back(i);
  for (const auto& [rows, cols] :
       {std::pair{odd, even}, std::pair{even, odd}, std::pair{some, some}, std::pair{even, some}})
  {
    const Matrix block(symmetric_block(lower, rows, cols));
    ASSERT_EQ(block.rows(), static_cast<Index>(rows.size()));
    ASSERT_EQ(block.cols(), static_cast<Index>(cols.size()));
    for (size_t r = 0; r < rows.size(); ++r)
      for (size_t c = 0; c < cols.size(); ++c)
        EXPECT_EQ(block(r, c), full(rows[r], cols[c])) << "row " << rows[r] << " col " << cols[c];
  }
}

TEST(Submatrix, LowerTrianglePrincipalSubmatrix)
{
  const Index n = 30;
  const SparseMatrix A = random_symmetric(n, 11);
  // Keep every DOF but those divisible by 4, in increasing order.
  std::vector<int32_t> position(n, -1), kept;
  for (int32_t i = 0; i < n; ++i)
    if (i % 4 != 0)
    {
      position[i] = static_cast<int32_t>(kept.size());
      kept.push_back(i);
    }
  const int32_t m = static_cast<int32_t>(kept.size());
  const Matrix expected = Matrix(A)(kept, kept);
  const Matrix whole(principal_submatrix(A, position, m));
  EXPECT_EQ(whole, expected);
  // From the full matrix, or from its lower triangle (increasing positions keep it lower).
  const SparseMatrix lower = A.triangularView<Eigen::Lower>();
  for (const SparseMatrix* source : {&A, &lower})
  {
    const SparseMatrix half = principal_submatrix(*source, position, m, Entries::lower_triangle);
    EXPECT_EQ(Matrix(half), Matrix(expected.triangularView<Eigen::Lower>()));
    const SparseMatrix mirrored = half.selfadjointView<Eigen::Lower>();
    EXPECT_EQ(Matrix(mirrored), expected);
  }
}
} // namespace
} // namespace feticon::la
