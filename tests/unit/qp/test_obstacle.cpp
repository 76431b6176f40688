/// The 1D obstacle problem of the MPRGP literature (Dostal 2009, section 8.7 style):
/// -u'' = -15 on (0,1), u(0) = u(1) = 0, u >= sin(4 pi x - pi/6)/2 - 2 at 100 interior points.

#include "qp/mprgp.hpp"
#include "qp_test_problems.hpp"
#include "reference_qp.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace feticon;

// Reference: the active-set solution of reference_qp.hpp (||g_P|| <= 1e-12 ||b||). Error bound
// for a strongly convex box QP: ||x - x*|| <= ||g_P(x)|| / lambda_min(A), from the natural
// residual bound ||x - x*|| <= (1 + a||A||)/(a lambda_min) ||x - P(x - a g)|| with
// ||x - P(x - a g)|| <= a ||g_P|| and a -> 0. lambda_min = 4/h^2 sin^2(pi h/2) exactly.
TEST(MprgpObstacle, ConvergesToActiveSetReference)
{
  const int n = 100;
  const double h = 1.0 / (n + 1);
  const test::BoundQp qp = test::obstacle_problem(n);
  const double lambda_min = 4.0 / (h * h) * std::pow(std::sin(std::numbers::pi * h / 2), 2);

  const la::Vector reference = test::reference_bound_qp(qp.A, qp.b, qp.lower);
  const double reference_gp = test::projected_gradient_norm(reference, qp.A * reference - qp.b, qp.lower);
  ASSERT_LE(reference_gp, 1e-12 * qp.b.norm());

  test::CountingOperator A(qp.A);
  const double rtol = 1e-5;
  qp::Mprgp mprgp(A, {.rtol = rtol});
  la::Vector x = la::Vector::Zero(n);
  const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
  std::cout << "obstacle n = " << n << ", rtol = " << rtol << ": iterations " << report.iterations << ", cg "
            << report.cg_steps << ", expansion " << report.expansion_steps << ", proportioning "
            << report.proportioning_steps << ", multiplications " << report.hessian_multiplications << " (of which "
            << "power iterations "
            << report.hessian_multiplications -
          (1 + report.cg_steps + 2 * report.expansion_steps + report.proportioning_steps + report.iterations / 50)
            << "), |g_P| " << report.projected_gradient_norm << ", cost " << report.cost << '\n';
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.hessian_multiplications, A.applications);

  const double gp = test::projected_gradient_norm(x, qp.A * x - qp.b, qp.lower);
  EXPECT_LE(gp, rtol * qp.b.norm() * (1 + 1e-9)) << "true vs recursive gradient";
  const double error_bound = (gp + reference_gp) / lambda_min;
  EXPECT_LE((x - reference).cwiseAbs().maxCoeff(), error_bound);

  // Contact set: where the reference touches the obstacle, x is within the error bound of
  // it, and conversely; contact lies under the two humps of the obstacle (sin > 0).
  int contacts = 0;
  for (int i = 0; i < n; ++i)
  {
    const bool reference_active = reference[i] == qp.lower[i];
    contacts += reference_active;
    if (reference_active)
    {
      EXPECT_LE(x[i] - qp.lower[i], error_bound) << "node " << i;
      EXPECT_GT(qp.lower[i], -2.0) << "contact off the obstacle's humps at node " << i;
    }
    if (x[i] == qp.lower[i])
    {
      EXPECT_LE(reference[i] - qp.lower[i], error_bound) << "node " << i;
    }
  }
  EXPECT_GT(contacts, 0);
  EXPECT_LT(contacts, n);
  std::cout << "obstacle contact nodes (reference): " << contacts << '\n';
}
