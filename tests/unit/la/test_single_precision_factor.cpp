/// la::SinglePrecisionFactor through CholmodFactor with FactorPrecision::single_precision.
/// References: the double factor of the same matrix (CHOLMOD), the normwise backward error a
/// factor rounded to float allows (Higham, Accuracy and Stability of Numerical Algorithms,
/// 2nd ed., thm. 10.4: |E| <= c eps |L||L'|, eps = 2^-24 here), and symmetry: the operator
/// must be the exact inverse of one SPD matrix for the Krylov solvers around it.

#include "la/cholmod.hpp"
#include "la/single_precision_factor.hpp"
#include "la_test_matrices.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace feticon::la
{
namespace
{
using test::grid_system;

double backward_error(const SparseMatrix& A, const Vector& x, const Vector& b)
{
  const Vector r = b - A * x;
  return r.norm() / (A.norm() * x.norm() + b.norm()); // Frobenius norm of A: an upper bound
}
} // namespace

TEST(SinglePrecisionFactor, BackwardErrorOfAFloatFactor)
{
  const SparseMatrix A = grid_system(12); // 5 184 unknowns
  const Vector b = Vector::LinSpaced(A.rows(), -1.0, 2.0);
  CholmodFactor exact, single;
  exact.factorize(A, "grid system");
  single.factorize(A, "grid system", FactorPrecision::single_precision);
  ASSERT_FALSE(exact.single_precision());
  ASSERT_TRUE(single.single_precision()) << "a 3D grid of this size is factorized supernodally";
  EXPECT_EQ(single.factor_nonzeros(), exact.factor_nonzeros());
  const Vector x_exact = exact.solve(b);
  const Vector x_single = single.solve(b);
  EXPECT_LT(backward_error(A, x_exact, b), 1e-15);
  // Float's round-off, and not more: below c eps with c = 8, above double's.
  const double error = backward_error(A, x_single, b);
  EXPECT_LT(error, 8 * 6e-8);
  EXPECT_GT(error, 1e-12);
  EXPECT_LT((x_single - x_exact).norm(), 1e-5 * x_exact.norm());
}

TEST(SinglePrecisionFactor, PortableKernelsAgreeWithTheVectorOnes)
{
  // The fallback for CPUs without AVX2/FMA computes the same substitutions: the same answer
  // to double round-off (the sums are grouped differently).
  const SparseMatrix A = grid_system(10);
  const Vector b = Vector::LinSpaced(A.rows(), -1.0, 2.0);
  CholmodFactor single;
  single.factorize(A, "grid system", FactorPrecision::single_precision);
  const Vector x_default = single.solve(b);
  use_vector_kernels(false);
  const Vector x_portable = single.solve(b);
  use_vector_kernels(true);
  EXPECT_LT((x_portable - x_default).norm(), 1e-13 * x_default.norm());
  EXPECT_LT(backward_error(A, x_portable, b), 8 * 6e-8);
}

TEST(SinglePrecisionFactor, AppliesOneSymmetricOperator)
{
  // y' A~^-1 z = z' A~^-1 y to double round-off: the substitutions are done in double, so
  // the float entries define one matrix and CG sees a symmetric operator, not noise.
  const SparseMatrix A = grid_system(10);
  CholmodFactor single;
  single.factorize(A, "grid system", FactorPrecision::single_precision);
  ASSERT_TRUE(single.single_precision());
  const Vector y = Vector::LinSpaced(A.rows(), 0.5, 1.5).array().sin();
  const Vector z = Vector::LinSpaced(A.rows(), -2.0, 3.0).array().cos();
  const double yz = y.dot(single.solve(z));
  const double zy = z.dot(single.solve(y));
  EXPECT_NEAR(yz, zy, 1e-13 * std::abs(yz));
  // Linear: A~^-1 (y + 2 z) = A~^-1 y + 2 A~^-1 z.
  const Vector combined = single.solve(Vector(y + 2 * z));
  EXPECT_LT((combined - single.solve(y) - 2 * single.solve(z)).norm(), 1e-13 * combined.norm());
}

TEST(SinglePrecisionFactor, ColumnsSolveAsVectors)
{
  const SparseMatrix A = grid_system(8);
  CholmodFactor single;
  single.factorize(A, "grid system", FactorPrecision::single_precision);
  Matrix B(A.rows(), 3);
  for (Index j = 0; j < 3; ++j)
    B.col(j) = Vector::LinSpaced(A.rows(), -1.0 * j, 1.0 + j);
  const Matrix X = single.solve(B);
  for (Index j = 0; j < 3; ++j)
    EXPECT_EQ((X.col(j) - single.solve(Vector(B.col(j)))).norm(), 0.0);
}

TEST(SinglePrecisionFactor, SimplicialFactorsStayDouble)
{
  // A tridiagonal matrix: CHOLMOD takes the simplicial factorization, which has no
  // supernodes to copy; its solves stay exact.
  const int n = 200;
  std::vector<Triplet> t;
  for (int i = 0; i < n; ++i)
  {
    t.emplace_back(i, i, 2.5);
    if (i + 1 < n)
    {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  CholmodFactor factor;
  factor.factorize(A, "tridiagonal", FactorPrecision::single_precision);
  EXPECT_FALSE(factor.single_precision());
  const Vector b = Vector::Ones(n);
  EXPECT_LT(backward_error(A, factor.solve(b), b), 1e-15);
}
} // namespace feticon::la
