/// MPRGP failure paths: non-convergence is a report (indefinite operator, iteration limit,
/// NaN), invalid input throws feticon::Error (STYLE.md, Errors).

#include "common/error.hpp"
#include "qp/mprgp.hpp"
#include "qp_test_problems.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
using la::infinity;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

la::Vector pair(double first, double second)
{
  la::Vector v(2);
  v << first, second;
  return v;
}

/// An operator whose output is NaN, as after a failed subdomain solve.
class NanOperator : public la::LinearOperator
{
public:
  la::Index size() const override { return 3; }
  void apply(const la::Vector& x, la::Vector& y) const override
  {
    y = x;
    y[1] = not_a_number;
  }
};
} // namespace

// Reference: MPRGP needs p'Ap > 0 (ALGORITHMS.md section 5, invariants). With A = diag(2,-1),
// b = (0,1), x0 = 0 and no bounds, the first direction is p = g = (0,-1) and p'Ap = -1.
TEST(MprgpFailure, IndefiniteOperatorInCgStepIsReported)
{
  const la::Matrix matrix = pair(2.0, -1.0).asDiagonal();
  test::CountingOperator A(matrix);
  qp::Mprgp mprgp(A, {});
  la::Vector x = la::Vector::Zero(2);
  const qp::QpReport report = mprgp.solve(pair(0.0, 1.0), la::Vector::Constant(2, -infinity), x);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.reason.find("not positive definite"), std::string::npos) << report.reason;
  EXPECT_NE(report.reason.find("p'Ap"), std::string::npos) << report.reason;
  EXPECT_EQ(report.iterations, 0);
}

// Reference: as above for the proportioning step: x = l = 0, b = (0,1), A = diag(1,-1) gives
// phi = 0, beta = (0,-1), so x is not proportional and beta'A beta = -1.
TEST(MprgpFailure, IndefiniteOperatorInProportioningStepIsReported)
{
  const la::Matrix matrix = pair(1.0, -1.0).asDiagonal();
  test::CountingOperator A(matrix);
  qp::Mprgp mprgp(A, {.alpha_bar = 1.0});
  la::Vector x = la::Vector::Zero(2);
  const qp::QpReport report = mprgp.solve(pair(0.0, 1.0), la::Vector::Zero(2), x);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.reason.find("not positive definite"), std::string::npos) << report.reason;
  EXPECT_NE(report.reason.find("beta'A beta"), std::string::npos) << report.reason;
}

// Reference: power iteration on diag(-3, 1) converges to the eigenvalue -3 of largest
// modulus, so alpha_bar = 1.8/nu cannot be formed; the solve must refuse, not iterate.
TEST(MprgpFailure, NegativeDefiniteOperatorIsReportedByTheNormEstimate)
{
  const la::Matrix matrix = pair(-3.0, 1.0).asDiagonal();
  test::CountingOperator A(matrix);
  qp::Mprgp mprgp(A, {});
  la::Vector x = la::Vector::Zero(2);
  const qp::QpReport report = mprgp.solve(la::Vector::Ones(2), la::Vector::Zero(2), x);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.reason.find("not positive definite"), std::string::npos) << report.reason;
  EXPECT_EQ(report.iterations, 0);
}

// Reference: the obstacle problem needs far more than 3 steps at rtol 1e-8 (test_obstacle).
TEST(MprgpFailure, IterationLimitIsReported)
{
  const test::BoundQp qp = test::obstacle_problem(100);
  test::CountingOperator A(qp.A);
  qp::Mprgp mprgp(A, {.rtol = 1e-8, .max_iterations = 3});
  la::Vector x = la::Vector::Zero(100);
  const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.iterations, 3);
  EXPECT_NE(report.reason.find("maximum number of iterations (3)"), std::string::npos) << report.reason;
  EXPECT_GT(report.projected_gradient_norm, 1e-8 * qp.b.norm());
  EXPECT_TRUE((x.array() >= qp.lower.array()).all()) << "the last iterate stays feasible";
}

// Reference: a NaN norm stops the solve (STYLE.md, Errors; MFEM CGSolver IsFinite).
TEST(MprgpFailure, NanGradientIsReported)
{
  NanOperator A;
  qp::Mprgp mprgp(A, {.alpha_bar = 1.0});
  la::Vector x = la::Vector::Ones(3);
  const qp::QpReport report = mprgp.solve(la::Vector::Ones(3), la::Vector::Zero(3), x);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.reason.find("not finite"), std::string::npos) << report.reason;
}

// Reference: invalid input is rejected with feticon::Error (STYLE.md, Errors).
TEST(MprgpFailure, InvalidInputIsRejected)
{
  const test::BoundQp qp = test::random_bound_qp(5, 1);
  test::CountingOperator A(qp.A);
  qp::Mprgp mprgp(A, {});
  la::Vector x = la::Vector::Zero(5);

  la::Vector b = qp.b;
  b[2] = not_a_number;
  EXPECT_THROW(mprgp.solve(b, qp.lower, x), Error);
  b[2] = infinity;
  EXPECT_THROW(mprgp.solve(b, qp.lower, x), Error);

  la::Vector lower = qp.lower;
  lower[0] = not_a_number;
  EXPECT_THROW(mprgp.solve(qp.b, lower, x), Error);
  lower[0] = infinity;
  EXPECT_THROW(mprgp.solve(qp.b, lower, x), Error);

  la::Vector bad_start = x;
  bad_start[4] = not_a_number;
  EXPECT_THROW(mprgp.solve(qp.b, qp.lower, bad_start), Error);

  la::Vector short_x = la::Vector::Zero(4);
  EXPECT_THROW(mprgp.solve(qp.b, qp.lower, short_x), Error);
  EXPECT_THROW(mprgp.solve(qp.b.head(4), qp.lower, x), Error);
  EXPECT_THROW(mprgp.solve(qp.b, qp.lower.head(4), x), Error);

  EXPECT_THROW(qp::Mprgp(A, {.gamma = 0.0}), Error);
  EXPECT_THROW(qp::Mprgp(A, {.alpha_bar = -1.0}), Error);
  EXPECT_THROW(qp::Mprgp(A, {.rtol = -1.0}), Error);

  try
  {
    b[2] = not_a_number;
    mprgp.solve(b, qp.lower, x);
    ADD_FAILURE() << "NaN in b accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("b[2]"), std::string::npos) << e.what();
  }
}
