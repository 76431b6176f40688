/// (Projected) conjugate gradients against dense direct solves.

#include "common/error.hpp"
#include "qp/conjugate_gradient.hpp"
#include "qp_test_problems.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
/// Random SPD matrix with eigenvalues log-spaced in [1, condition].
la::Matrix random_spd(int n, unsigned seed, double condition)
{
  std::mt19937 generator(seed);
  const la::Matrix V = test::random_orthogonal(n, generator);
  la::Vector lambda(n);
  for (int i = 0; i < n; ++i)
    lambda[i] = std::pow(condition, static_cast<double>(i) / (n - 1));
  const la::Matrix A = V * lambda.asDiagonal() * V.transpose();
  return 0.5 * (A + A.transpose());
}

la::Vector random_vector(int n, unsigned seed)
{
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  la::Vector v(n);
  for (int i = 0; i < n; ++i)
    v[i] = normal(generator);
  return v;
}
} // namespace

// Reference: dense LDLT. ||x - x*|| <= cond(A) ||r|| / ||b|| ||x*|| = 1e3 * 1e-14 ||x*||.
TEST(ConjugateGradient, MatchesDenseLdlt)
{
  for (const unsigned seed : {1u, 2u, 3u})
  {
    const int n = 50;
    const la::Matrix matrix = random_spd(n, seed, 1e3);
    const la::Vector b = random_vector(n, seed + 10);
    test::CountingOperator A(matrix);
    la::Vector x = la::Vector::Zero(n);
    const qp::QpReport report = qp::conjugate_gradient(A, b, x, {.rtol = 1e-14});
    ASSERT_TRUE(report.converged) << report.reason;
    const la::Vector exact = matrix.ldlt().solve(b);
    EXPECT_LE((x - exact).norm(), 1e-10 * exact.norm());
    EXPECT_EQ(report.cg_steps, report.iterations);
    EXPECT_EQ(report.hessian_multiplications, report.iterations) << "x0 = 0 needs no Ax0";
    EXPECT_EQ(A.applications, report.hessian_multiplications);
    EXPECT_NEAR(report.cost, 0.5 * x.dot(matrix * x) - b.dot(x), 1e-10 * std::abs(report.cost));

    // A nonzero start costs one more product.
    A.applications = 0;
    la::Vector warm = la::Vector::Ones(n);
    const qp::QpReport warm_report = qp::conjugate_gradient(A, b, warm, {.rtol = 1e-14});
    ASSERT_TRUE(warm_report.converged);
    EXPECT_EQ(warm_report.hessian_multiplications, warm_report.iterations + 1);
    EXPECT_EQ(A.applications, warm_report.hessian_multiplications);
    EXPECT_LE((warm - exact).norm(), 1e-10 * exact.norm());
  }
}

// Reference: FETI projected CG (Farhat & Roux 1991). With P = I - QQ' (Q orthonormal, rank 3)
// the solution of PAP x = Pb in Im P is x = Z (Z'AZ)^{-1} Z'b for an orthonormal basis Z of
// Im P, computed densely; P(Ax - b) = 0 and Q'x = 0 must hold.
TEST(ConjugateGradient, ProjectedSolveStaysInRangeOfProjector)
{
  const int n = 40, rank = 3;
  std::mt19937 generator(5);
  const la::Matrix basis = test::random_orthogonal(n, generator);
  const la::Matrix Q = basis.leftCols(rank);
  const la::Matrix Z = basis.rightCols(n - rank);
  const la::Matrix P = la::Matrix::Identity(n, n) - Q * Q.transpose();
  const la::Matrix matrix = random_spd(n, 6, 1e2);
  const la::Matrix PAP = P * matrix * P;
  const la::Vector b = random_vector(n, 7);
  test::CountingOperator A(PAP), projector(P);

  la::Vector x = la::Vector::Zero(n);
  const qp::QpReport report = qp::conjugate_gradient(A, P * b, x, {.rtol = 1e-12}, &projector);
  ASSERT_TRUE(report.converged) << report.reason;
  const la::Vector exact = Z * (Z.transpose() * matrix * Z).ldlt().solve(Z.transpose() * b);
  // cond(Z'AZ) <= 100, so the error is below 100 * rtol relative.
  EXPECT_LE((x - exact).norm(), 1e-9 * exact.norm());
  EXPECT_LE((P * (matrix * x - b)).norm(), 1e-11 * (P * b).norm());
  EXPECT_LE((Q.transpose() * x).norm(), 1e-12 * x.norm());
  EXPECT_EQ(projector.applications, report.iterations + 2) << "Pb, Pr0, one per step";
}

// Reference: CG needs p'Ap > 0; diag(1,-1) with b = (0,1) gives p = r = b and p'Ap = -1.
TEST(ConjugateGradient, IndefiniteOperatorIsReported)
{
  la::Vector diagonal(2);
  diagonal << 1.0, -1.0;
  const la::Matrix matrix = diagonal.asDiagonal();
  test::CountingOperator A(matrix);
  la::Vector b(2);
  b << 0.0, 1.0;
  la::Vector x = la::Vector::Zero(2);
  const qp::QpReport report = qp::conjugate_gradient(A, b, x, {});
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.reason.find("not positive definite"), std::string::npos) << report.reason;
}

// Reference: CG on 50 unknowns with cond 1e3 needs more than 2 steps for rtol 1e-10.
TEST(ConjugateGradient, IterationLimitAndInvalidInput)
{
  const la::Matrix matrix = random_spd(50, 8, 1e3);
  test::CountingOperator A(matrix);
  const la::Vector b = random_vector(50, 9);
  la::Vector x = la::Vector::Zero(50);
  const qp::QpReport report = qp::conjugate_gradient(A, b, x, {.rtol = 1e-10, .max_iterations = 2});
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.iterations, 2);
  EXPECT_NE(report.reason.find("maximum number of iterations"), std::string::npos);

  la::Vector bad = b;
  bad[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(qp::conjugate_gradient(A, bad, x, {}), Error);
  la::Vector short_x = la::Vector::Zero(49);
  EXPECT_THROW(qp::conjugate_gradient(A, b, short_x, {}), Error);
}

// Reference: the eigenvalues chosen for the matrix. A run of n CG steps on an n x n SPD
// matrix is n Lanczos steps, whose Ritz values are its eigenvalues: the report's extremes
// are 1 and cond(A) (rtol 1e-12 lets the run take all n steps; round-off of the
// recurrence after n steps bounds the agreement).
TEST(ConjugateGradient, RitzValuesOfAFullRunAreTheExtremeEigenvalues)
{
  const int n = 12;
  const la::Matrix A = random_spd(n, 5, 100.0);
  test::CountingOperator op(A);
  la::Vector x = la::Vector::Zero(n);
  const qp::QpReport report = qp::conjugate_gradient(op, random_vector(n, 6), x, {.rtol = 1e-12});
  EXPECT_GE(report.ritz.cg_steps, n - 1);
  EXPECT_NEAR(report.ritz.min, 1.0, 1e-6);
  EXPECT_NEAR(report.ritz.max, 100.0, 1e-4);
}
