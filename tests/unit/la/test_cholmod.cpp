/// la::CholmodFactor on threads. Reference: the same factorization done alone. CHOLMOD's
/// default ordering also tries METIS when AMD fills in much, as on this 3D grid (24^3
/// unknowns: CHOLMOD selects METIS), and METIS draws from a global random generator; two
/// factorizations ordering at once must still give the same factor, bit for bit, or every
/// threaded run's answer depends on timing (docs/distributed.md, determinism).

#include "common/error.hpp"
#include "la/cholmod.hpp"

#include <Eigen/Eigenvalues>

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace feticon::la
{
namespace
{
/// 7-point Laplacian on an m^3 grid, shifted to be positive definite.
SparseMatrix grid_laplacian(int m)
{
  std::vector<Triplet> t;
  auto id = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k)
      {
        const int r = id(i, j, k);
        t.emplace_back(r, r, 6.01);
        const int neighbours[3] = {i + 1 < m ? id(i + 1, j, k) : -1, j + 1 < m ? id(i, j + 1, k) : -1,
                                   k + 1 < m ? id(i, j, k + 1) : -1};
        for (const int c : neighbours)
          if (c >= 0)
          {
            t.emplace_back(r, c, -1.0);
            t.emplace_back(c, r, -1.0);
          }
      }
  SparseMatrix A(m * m * m, m * m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

Vector factor_and_solve(const SparseMatrix& A, const Vector& b)
{
  CholmodFactor factor;
  factor.factorize(A, "grid Laplacian");
  return factor.solve(b);
}
} // namespace

TEST(CholmodFactor, ConcurrentFactorizationsGiveTheSameFactorBitForBit)
{
  const SparseMatrix A = grid_laplacian(24);
  const Vector b = Vector::LinSpaced(A.rows(), -1.0, 2.0);
  const Vector reference = factor_and_solve(A, b);
  ASSERT_LT((A * reference - b).norm(), 1e-10 * b.norm());
  for (int round = 0; round < 3; ++round)
  {
    Vector x[2];
    std::thread other([&] { x[1] = factor_and_solve(A, b); });
    x[0] = factor_and_solve(A, b);
    other.join();
    for (const Vector& xi : x)
    {
      ASSERT_EQ(xi.size(), reference.size());
      EXPECT_EQ((xi - reference).cwiseAbs().maxCoeff(), 0.0) << "round " << round;
    }
  }
}
} // namespace feticon::la

namespace feticon::la
{
// Reference: the spectrum. The 2D grid Laplacian shifted by -0.5 has eigenvalues below zero
// (its smallest is 4 - 4 cos(pi / (m + 1)) - 0.5 < 0 at m = 6), yet has no zero pivot, so
// CHOLMOD's simplicial LDL' completes; the factor must still refuse it in one line, as the
// shifted-up matrix it accepts. Small enough for CHOLMOD's simplicial factor.
TEST(CholmodFactor, SimplicialFactorRefusesAnIndefiniteMatrix)
{
  const int m = 6;
  std::vector<Triplet> t;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
    {
      const int r = i * m + j;
      t.emplace_back(r, r, 3.5);
      if (i + 1 < m)
      {
        t.emplace_back(r, r + m, -1.0);
        t.emplace_back(r + m, r, -1.0);
      }
      if (j + 1 < m)
      {
        t.emplace_back(r, r + 1, -1.0);
        t.emplace_back(r + 1, r, -1.0);
      }
    }
  SparseMatrix A(m * m, m * m);
  A.setFromTriplets(t.begin(), t.end());
  ASSERT_LT(Eigen::SelfAdjointEigenSolver<Matrix>(Matrix(A)).eigenvalues().minCoeff(), 0);
  CholmodFactor factor;
  try
  {
    factor.factorize(A, "the shifted Laplacian");
    FAIL() << "an indefinite matrix was factored";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("the shifted Laplacian failed: the matrix is not positive definite"),
              std::string::npos)
        << e.what();
  }
  SparseMatrix shifted = A;
  shifted.diagonal().array() += 1.0;
  EXPECT_NO_THROW(factor.factorize(shifted, "the shifted Laplacian"));
}
} // namespace feticon::la
