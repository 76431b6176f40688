/// la::nodal_nested_dissection (nodal_ordering.hpp). References: CHOLMOD's own analysis of
/// the same matrix for the fill, the residual of the solve for the factor.

#include "la/cholmod.hpp"
#include "la/metis_random.hpp"
#include "la/nodal_ordering.hpp"
#include "la/submatrix.hpp"
#include "la_test_matrices.hpp"

#include <Eigen/CholmodSupport>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace feticon::la
{
namespace
{
std::vector<int> ordering(const SparseMatrix& A)
{
  const ThreadPrivateRandom private_draws;
  const std::optional<std::vector<int>> perm = nodal_nested_dissection(A, 0);
  EXPECT_TRUE(perm.has_value());
  return perm.value_or(std::vector<int>{});
}

bool is_permutation(std::vector<int> perm, Index n)
{
  std::sort(perm.begin(), perm.end());
  std::vector<int> identity(static_cast<size_t>(n));
  std::iota(identity.begin(), identity.end(), 0);
  return perm == identity;
}
} // namespace

TEST(NodalOrdering, KeepsEachNodesDofsTogether)
{
  const SparseMatrix A = test::grid_system(12);
  const std::vector<int> perm = ordering(A);
  ASSERT_TRUE(is_permutation(perm, A.rows()));
  for (size_t k = 0; k < perm.size(); k += 3)
  {
    EXPECT_EQ(perm[k] % 3, 0) << "position " << k;
    EXPECT_EQ(perm[k + 1], perm[k] + 1);
    EXPECT_EQ(perm[k + 2], perm[k] + 2);
  }
}

TEST(NodalOrdering, FillsAsCholmodsOwnAnalysis)
{
  const SparseMatrix A = test::grid_system(14);
  CholmodFactor nodal;
  nodal.factorize(A);                                                // 8 232 DOFs: ordered by the node graph
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> reference; // AMD, then METIS on the DOFs
  reference.setMode(Eigen::CholmodSupernodalLLt);
  {
    const ThreadPrivateRandom private_draws;
    reference.compute(A);
  }
  ASSERT_EQ(reference.info(), Eigen::Success);
  const auto reference_entries = static_cast<double>(reference.cholmod().lnz);
  EXPECT_LT(static_cast<double>(nodal.factor_nonzeros()), 1.05 * reference_entries);
  EXPECT_GT(static_cast<double>(nodal.factor_nonzeros()), 0.8 * reference_entries);

  const Vector b = Vector::LinSpaced(A.rows(), -1.0, 2.0);
  const Vector x = nodal.solve(b);
  EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm());
}

TEST(NodalOrdering, ReadsTheLowerTriangleAsCholmodDoes)
{
  const SparseMatrix A = test::grid_system(8);
  const SparseMatrix lower = A.triangularView<Eigen::Lower>();
  EXPECT_EQ(ordering(lower), ordering(A));
}

TEST(NodalOrdering, NodesWithFixedDofsStayWhole)
{
  // A generalized inverse's fixing DOFs removed (generalized_inverse.cpp): nodes of 3, 2 and 1 DOFs.
  const SparseMatrix A = test::grid_system(8);
  std::vector<int32_t> position(static_cast<size_t>(A.rows()));
  int32_t kept = 0;
  for (Index i = 0; i < A.rows(); ++i)
    position[static_cast<size_t>(i)] = (i == 30 || i == 31 || i == 95) ? -1 : kept++;
  const SparseMatrix K = principal_submatrix(A, position, kept);
  const std::vector<int> perm = ordering(K);
  ASSERT_TRUE(is_permutation(perm, K.rows()));
  // Node 10 kept DOF 32 alone (position 30), node 31 DOFs 93 and 94 (positions 91, 92).
  const auto at = [&perm](int dof) { return std::find(perm.begin(), perm.end(), dof) - perm.begin(); };
  EXPECT_EQ(at(92), at(91) + 1);
}

TEST(NodalOrdering, LeavesSmallAndTwoDimensionalMatricesToCholmod)
{
  const SparseMatrix A = test::grid_system(6); // 648 DOFs
  EXPECT_FALSE(nodal_nested_dissection(A, 3000).has_value());
  SparseMatrix scalar(900, 900); // one DOF per node: a 30 x 30 Laplacian
  std::vector<Triplet> t;
  for (int i = 0; i < 900; ++i)
  {
    t.emplace_back(i, i, 4.0);
    if (i % 30 != 29)
    {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
    if (i + 30 < 900)
    {
      t.emplace_back(i, i + 30, -1.0);
      t.emplace_back(i + 30, i, -1.0);
    }
  }
  scalar.setFromTriplets(t.begin(), t.end());
  EXPECT_FALSE(nodal_nested_dissection(scalar, 0).has_value());
}
} // namespace feticon::la
