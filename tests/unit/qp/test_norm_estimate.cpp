/// Power-iteration estimate of ||A|| (ALGORITHMS.md section 5, "||A|| estimate").

#include "qp/norm_estimate.hpp"
#include "qp_test_problems.hpp"

#include <gtest/gtest.h>

using namespace feticon;

// Reference: for symmetric A the Rayleigh quotient of a unit vector lies in
// [lambda_min, lambda_max], and power iteration converges to lambda_max with ratio
// (lambda_2/lambda_1)^2 = 0.25 per step here, so rtol 1e-10 is reached in < 30 steps.
TEST(NormEstimate, ConvergesFromBelowToLargestEigenvalue)
{
  la::Vector diagonal = la::Vector::LinSpaced(20, 0.0, 5.0);
  diagonal[7] = 10.0;
  const la::Matrix matrix = diagonal.asDiagonal();
  test::CountingOperator A(matrix);
  const qp::NormEstimate estimate = qp::estimate_norm(A, 100, 1e-10);
  EXPECT_LE(estimate.value, 10.0 * (1 + 1e-15));
  EXPECT_GE(estimate.value, 10.0 * (1 - 1e-9));
  EXPECT_EQ(estimate.applications, A.applications);
  EXPECT_LT(estimate.applications, 30);

  // Few iterations give a lower bound of lambda_max (MPRGP's alpha_bar = 1.8/nu relies on
  // halving when it errs); the default stops after at most 30 applications.
  A.applications = 0;
  const qp::NormEstimate rough = qp::estimate_norm(A, 2, 0.0);
  EXPECT_EQ(rough.applications, 2);
  EXPECT_LE(rough.value, estimate.value);
  EXPECT_GT(rough.value, 0.0);
}

// Reference: the start vector depends only on the seed (raw mt19937 output is fixed by the
// C++ standard), so equal seeds give bit-identical estimates and counts.
TEST(NormEstimate, IsDeterministic)
{
  const test::BoundQp qp = test::obstacle_problem(60);
  test::CountingOperator A(qp.A);
  const qp::NormEstimate first = qp::estimate_norm(A);
  const qp::NormEstimate second = qp::estimate_norm(A);
  EXPECT_EQ(first.value, second.value);
  EXPECT_EQ(first.applications, second.applications);
  EXPECT_LE(first.applications, 30);
  const qp::NormEstimate other = qp::estimate_norm(A, 30, 1e-3, 2);
  EXPECT_NE(first.value, other.value);
  // lambda_max(tridiag(-1,2,-1)/h^2) = 4/h^2 cos^2(pi h/2) < 4/h^2; the estimate is below it
  // and, by the stopping rule, not far below.
  const double h = 1.0 / 61;
  const double lambda_max = 4.0 / (h * h) * std::pow(std::cos(std::numbers::pi * h / 2), 2);
  EXPECT_LE(first.value, lambda_max * (1 + 1e-14));
  EXPECT_GE(first.value, 0.5 * lambda_max);
}

// Reference: A = 0 annihilates any start vector: the estimate is 0 after one application.
TEST(NormEstimate, ZeroOperator)
{
  const la::Matrix matrix = la::Matrix::Zero(4, 4);
  test::CountingOperator A(matrix);
  const qp::NormEstimate estimate = qp::estimate_norm(A);
  EXPECT_EQ(estimate.value, 0.0);
  EXPECT_EQ(estimate.applications, 1);
}
