/// Spectrum estimate of MPRGP's CG runs (QpReport::ritz, qp/ritz_estimate.hpp).

#include "qp/mprgp.hpp"
#include "qp_test_problems.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace feticon;

namespace
{
const double minus_infinity = -std::numeric_limits<double>::infinity();

qp::QpReport solve_unbounded(const la::LinearOperator& A, const la::LinearOperator* M, const la::Vector& b)
{
  qp::MprgpOptions options;
  options.rtol = 1e-12;
  options.preconditioner = M;
  qp::Mprgp mprgp(A, options);
  la::Vector x = la::Vector::Zero(b.size());
  return mprgp.solve(b, la::Vector::Constant(b.size(), minus_infinity), x);
}
} // namespace

// Reference: the eigenvalues 1..40 of A = V diag(1..40) V' (V random orthogonal). Without
// bounds every MPRGP step is a CG step, so the run is a full Lanczos process on A and its
// extreme Ritz values converge to the extreme eigenvalues.
TEST(RitzEstimate, ExtremeEigenvaluesOfAnUnboundedCgRun)
{
  std::mt19937 generator(7);
  const int n = 40;
  la::Vector eigenvalues(n), b(n);
  std::normal_distribution<double> normal;
  for (int i = 0; i < n; ++i)
  {
    eigenvalues[i] = i + 1.0;
    b[i] = normal(generator);
  }
  const la::Matrix V = test::random_orthogonal(n, generator);
  const la::Matrix matrix = V * eigenvalues.asDiagonal() * V.transpose();
  const test::CountingOperator A(matrix);
  const qp::QpReport report = solve_unbounded(A, nullptr, b);
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.ritz.cg_steps, report.cg_steps);
  EXPECT_NEAR(report.ritz.min, 1.0, 1e-6);
  EXPECT_NEAR(report.ritz.max, 40.0, 40e-6);
}

// Reference: with A = diag(d) and M = diag(d^(-1/2)), M A = diag(sqrt(d)): the estimate is
// of the preconditioned operator, extremes sqrt(1) and sqrt(40), approached from inside
// (the run stops at 1e-12 before the largest Ritz value has all its digits).
TEST(RitzEstimate, PreconditionedRunEstimatesTheSpectrumOfMA)
{
  const int n = 40;
  la::Vector d(n), b(n);
  for (int i = 0; i < n; ++i)
  {
    d[i] = i + 1.0;
    b[i] = std::cos(1.0 + i);
  }
  const la::Matrix matrix = d.asDiagonal(), inverse_root = d.cwiseSqrt().cwiseInverse().asDiagonal();
  const test::CountingOperator A(matrix), M(inverse_root);
  const qp::QpReport report = solve_unbounded(A, &M, b);
  ASSERT_TRUE(report.converged) << report.reason;
  const double top = std::sqrt(40.0);
  EXPECT_GE(report.ritz.min, 1.0 - 1e-12);
  EXPECT_LT(report.ritz.min, 1.0 + 1e-6);
  EXPECT_LE(report.ritz.max, top * (1 + 1e-12));
  EXPECT_GT(report.ritz.max, top * (1 - 1e-5));
}

// Reference: Cauchy interlacing. With active bounds the runs work on faces, principal
// submatrices of A, whose eigenvalues lie in [lambda_min(A), lambda_max(A)] = [1, 100]
// (random_bound_qp); the Ritz values lie inside those, and the run is at most the CG steps.
TEST(RitzEstimate, FaceRunsStayInsideTheSpectrum)
{
  for (unsigned seed : {1u, 5u, 9u})
  {
    const test::BoundQp problem = test::random_bound_qp(60, seed, 100.0);
    const test::CountingOperator A(problem.A);
    qp::MprgpOptions options;
    options.rtol = 1e-10;
    qp::Mprgp mprgp(A, options);
    la::Vector x = la::Vector::Zero(60);
    const qp::QpReport report = mprgp.solve(problem.b, problem.lower, x);
    ASSERT_TRUE(report.converged) << report.reason;
    ASSERT_GE(report.ritz.cg_steps, 2);
    EXPECT_LE(report.ritz.cg_steps, report.cg_steps);
    EXPECT_GE(report.ritz.min, 1.0 - 1e-9);
    EXPECT_LE(report.ritz.max, 100.0 * (1 + 1e-9));
    EXPECT_LT(report.ritz.min, report.ritz.max);
  }
}
