/// MPRGP options: caller's stopping test, b = 0, alpha_bar halving, iteration log.

#include "common/log.hpp"
#include "qp/mprgp.hpp"
#include "qp_test_problems.hpp"
#include "reference_qp.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
using test::largest_eigenvalue;
} // namespace

// Reference: MprgpOptions::stop replaces ||g_P|| <= rtol ||b|| (qp/mprgp.hpp), as SMALBE-M
// needs (ALGORITHMS.md section 1). A loose caller test must stop earlier than rtol = 1e-12
// would, and see the true gradient.
TEST(MprgpOptions, CallerStoppingTestReplacesDefault)
{
  const test::BoundQp qp = test::random_bound_qp(40, 3);
  test::CountingOperator A(qp.A);
  const double loose = 1e-2 * qp.b.norm();
  int calls = 0;
  qp::MprgpOptions options{.rtol = 1e-12};
  options.stop = [&](const la::Vector& x, const la::Vector& g, double gp_norm) {
    ++calls;
    EXPECT_LE((g - (qp.A * x - qp.b)).norm(), 1e-10 * qp.b.norm());
    EXPECT_NEAR(gp_norm, test::projected_gradient_norm(x, g, qp.lower), 1e-12 * qp.b.norm());
    return gp_norm <= loose;
  };
  qp::Mprgp hooked(A, options);
  la::Vector x = la::Vector::Zero(40);
  const qp::QpReport report = hooked.solve(qp.b, qp.lower, x);
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_LE(report.projected_gradient_norm, loose);
  EXPECT_GT(report.projected_gradient_norm, 1e-12 * qp.b.norm());
  EXPECT_EQ(calls, report.iterations + 1);

  qp::Mprgp plain(A, {.rtol = 1e-12});
  la::Vector y = la::Vector::Zero(40);
  const qp::QpReport tight = plain.solve(qp.b, qp.lower, y);
  ASSERT_TRUE(tight.converged);
  EXPECT_LT(report.iterations, tight.iterations);
}

// Reference: for b = 0 the relative test degenerates, so the test is absolute,
// ||g_P|| <= rtol (qp/mprgp.hpp). With l <= 0, x = P(0) = 0 is the exact solution.
TEST(MprgpOptions, ZeroRightHandSide)
{
  const test::BoundQp qp = test::random_bound_qp(20, 5);
  test::CountingOperator A(qp.A);
  const la::Vector zero = la::Vector::Zero(20);

  qp::Mprgp mprgp(A, {.rtol = 1e-10});
  la::Vector x = la::Vector::Zero(20);
  const la::Vector nonpositive = qp.lower.cwiseMin(0.0);
  qp::QpReport report = mprgp.solve(zero, nonpositive, x);
  EXPECT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.iterations, 0);
  EXPECT_EQ(report.projected_gradient_norm, 0.0);
  EXPECT_EQ(x, zero);

  // Positive bounds make the solution nonzero; compare with the active-set reference.
  const la::Vector shifted = qp.lower.array() + 0.3;
  la::Vector y = la::Vector::Zero(20);
  report = mprgp.solve(zero, shifted, y);
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_NE(report.reason.find("b = 0"), std::string::npos) << report.reason;
  EXPECT_LE(report.projected_gradient_norm, 1e-10);
  const la::Vector reference = test::reference_bound_qp(qp.A, zero, shifted);
  ASSERT_GT(reference.norm(), 0.1);
  // ||y - x*|| <= ||g_P|| / lambda_min with lambda_min = 1 (see test_obstacle.cpp).
  EXPECT_LE((y - reference).norm(), 1e-10 * (1 + 1e-6));
}

// Reference: f is monotone only for alpha_bar <= 2/||A|| (Dostal & Schoberl 2005); with
// alpha_bar = 20/||A|| some expansion increases f, so alpha_bar must be halved
// (ALGORITHMS.md section 5), and the solve still converges.
TEST(MprgpOptions, TooLongExpansionStepIsHalved)
{
  const test::BoundQp qp = test::random_bound_qp(30, 9);
  test::CountingOperator A(qp.A);
  const double too_long = 20.0 / largest_eigenvalue(qp.A);
  qp::Mprgp mprgp(A, {.rtol = 1e-8, .alpha_bar = too_long});
  la::Vector x = la::Vector::Zero(30);
  const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_GT(report.expansion_steps, 0);
  EXPECT_LT(mprgp.alpha_bar(), too_long);
  EXPECT_GE(mprgp.alpha_bar(), too_long / 1024) << "halved only when f increased";
  const la::Vector reference = test::reference_bound_qp(qp.A, qp.b, qp.lower);
  EXPECT_LE((x - reference).norm(), 1e-8 * qp.b.norm() * (1 + 1e-6));
}

// Reference: STYLE.md, Logging: with level `iterations` MPRGP prints one line per step with
// the step kind, gradient norms and tolerance.
TEST(MprgpOptions, IterationLogHasOneLinePerStep)
{
  const test::BoundQp qp = test::obstacle_problem(30);
  test::CountingOperator A(qp.A);
  qp::Mprgp mprgp(A, {.rtol = 1e-6});
  la::Vector x = la::Vector::Zero(30);
  const log::Level saved = log::level();
  log::set_level(log::Level::iterations);
  testing::internal::CaptureStdout();
  const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
  const std::string output = testing::internal::GetCapturedStdout();
  log::set_level(saved);
  ASSERT_TRUE(report.converged);
  int lines = 0;
  for (const char c : output)
    lines += c == '\n';
  EXPECT_EQ(lines, report.iterations + 1);
  for (const char* word : {"start", "cg", "|g_P|", "|phi|", "|beta|", "tol"})
    EXPECT_NE(output.find(word), std::string::npos) << word;
}
