/// Spectrum estimate of MPRGP's CG runs (QpReport::ritz, qp/ritz_estimate.hpp).

#include "qp/mprgp.hpp"
#include "qp_test_problems.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
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

/// MPRGP without bounds on A = V diag(eigenvalues(i)) V', V random orthogonal, and a random
/// right-hand side: every step a CG step, the run a full Lanczos process on A.
qp::QpReport solve_with_eigenvalues(const std::function<double(int)>& eigenvalue, unsigned seed)
{
  std::mt19937 generator(seed);
  const int n = 40;
  la::Vector eigenvalues(n), b(n);
  std::normal_distribution<double> normal;
  for (int i = 0; i < n; ++i)
  {
    eigenvalues[i] = eigenvalue(i);
    b[i] = normal(generator);
  }
  const la::Matrix V = test::random_orthogonal(n, generator);
  const la::Matrix matrix = V * eigenvalues.asDiagonal() * V.transpose();
  const test::CountingOperator A(matrix);
  return solve_unbounded(A, nullptr, b);
}
} // namespace

// Reference: the eigenvalues 1..40 of A = V diag(1..40) V' (V random orthogonal). Without
// bounds every MPRGP step is a CG step, so the run is a full Lanczos process on A and its
// extreme Ritz values converge to the extreme eigenvalues.
TEST(RitzEstimate, ExtremeEigenvaluesOfAnUnboundedCgRun)
{
  const qp::QpReport report = solve_with_eigenvalues([](int i) { return i + 1.0; }, 7);
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

// Reference: A = V diag(d) V' with d the ten values 1, 2, 4, ..., 512, each four times. A
// Krylov space of A holds one vector per distinct eigenvalue, so after ten steps the Ritz
// values are the ten eigenvalues; the steps that round-off adds to reach rtol 1e-12 (14 here)
// may add Ritz values that are not eigenvalues, and repeat converged ones (ghosts). The list:
// every eigenvalue once, ascending, nothing outside [1, 512], no two within the merge
// tolerance.
TEST(RitzEstimate, DistinctValuesHoldEachEigenvalueOnce)
{
  const qp::QpReport report = solve_with_eigenvalues([](int i) { return std::ldexp(1.0, i % 10); }, 11);
  ASSERT_TRUE(report.converged) << report.reason;
  const std::vector<double>& values = report.ritz.distinct;
  ASSERT_FALSE(values.empty());
  EXPECT_LE(static_cast<int>(values.size()), report.ritz.cg_steps);
  EXPECT_GE(values.front(), 1.0 - 1e-9);
  EXPECT_LE(values.back(), 512.0 * (1 + 1e-9));
  for (size_t i = 1; i < values.size(); ++i)
    EXPECT_GT(values[i], values[i - 1] * (1 + 1e-3)) << "i = " << i;
  for (int j = 0; j < 10; ++j)
  {
    const double eigenvalue = std::ldexp(1.0, j);
    const auto matches = std::count_if(values.begin(), values.end(),
                                       [&](double v) { return std::abs(v - eigenvalue) <= 1e-6 * eigenvalue; });
    EXPECT_EQ(matches, 1) << "eigenvalue " << eigenvalue;
  }
}
