/// MPRGP on random bound-constrained QPs: KKT conditions, agreement with an independent
/// active-set solver, monotone cost, exact product counts (ALGORITHMS.md section 5;
/// Dostal & Schoberl 2005).

#include "qp/mprgp.hpp"
#include "qp/norm_estimate.hpp"
#include "qp_test_problems.hpp"
#include "reference_qp.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace feticon;

namespace
{
/// Products of one solve predicted by the formula of qp/mprgp.hpp.
int predicted_products(const qp::QpReport& report, int power_iterations, int refresh = 50)
{
  return power_iterations + 1 + report.cg_steps + 2 * report.expansion_steps + report.expansion_fallbacks +
      report.proportioning_steps + report.iterations / refresh;
}

using test::largest_eigenvalue;

/// KKT conditions at tolerance `tol` with the true gradient g = Ax - b: x >= l exactly,
/// g_i >= -tol where x_i = l_i, and |g_i| <= tol where x_i > l_i (complementarity: a
/// positive gap leaves no multiplier).
void expect_kkt(const test::BoundQp& qp, const la::Vector& x, double tol)
{
  const la::Vector g = qp.A * x - qp.b;
  for (la::Index i = 0; i < x.size(); ++i)
  {
    ASSERT_GE(x[i], qp.lower[i]) << "component " << i;
    if (x[i] == qp.lower[i])
      EXPECT_GE(g[i], -tol) << "active component " << i;
    else
      EXPECT_LE(std::abs(g[i]), tol) << "free component " << i;
  }
}

using test::seeds;
using test::sizes;
/// Every test below runs with each expansion step (qp/mprgp.hpp).
using test::expansions;
} // namespace

// Reference: the stopping test ||g_P|| <= rtol ||b|| of ALGORITHMS.md section 5 bounds every
// KKT residual component by rtol ||b||; the margin 1e-12 ||A|| ||x|| covers the drift of the
// recursive gradient (refreshed every 50 steps), far below rtol ||b||.
TEST(Mprgp, RandomProblemsSatisfyKktAtRequestedTolerance)
{
  int active = 0, total = 0;
  for (const qp::MprgpExpansion expansion : expansions)
    for (const int n : sizes)
      for (const unsigned seed : seeds)
      {
        SCOPED_TRACE(test::expansion_name(expansion) + ", n = " + std::to_string(n) +
                     ", seed = " + std::to_string(seed));
        const test::BoundQp qp = test::random_bound_qp(n, seed);
        test::CountingOperator A(qp.A);
        const double rtol = 1e-5;
        qp::Mprgp mprgp(A, {.rtol = rtol, .expansion = expansion});
        la::Vector x = la::Vector::Zero(n);
        const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
        ASSERT_TRUE(report.converged) << report.reason;
        const double tol = rtol * qp.b.norm() + 1e-12 * qp.A.norm() * x.norm();
        expect_kkt(qp, x, tol);
        EXPECT_EQ(report.hessian_multiplications, A.applications);
        EXPECT_NEAR(report.cost, 0.5 * x.dot(qp.A * x) - qp.b.dot(x), 1e-10 * (1.0 + std::abs(report.cost)));
        active += static_cast<int>((x.array() == qp.lower.array()).count());
        total += n;
      }
  // The problems must exercise the bounds, or this test would be plain CG.
  EXPECT_GT(active, total / 5);
}

// Reference: the independent primal active-set solver of reference_qp.hpp (exact on its
// final active set). With ||g_P|| <= 1e-12 ||b|| and lambda_min(A) = 1, the error bound
// ||x - x*|| <= ||g_P|| / lambda_min (see test_obstacle.cpp) is 1e-12 ||b||, well inside
// 1e-8 relative.
TEST(Mprgp, RandomProblemsMatchActiveSetReference)
{
  for (const qp::MprgpExpansion expansion : expansions)
    for (const int n : sizes)
      for (const unsigned seed : seeds)
      {
        SCOPED_TRACE(test::expansion_name(expansion) + ", n = " + std::to_string(n) +
                     ", seed = " + std::to_string(seed));
        const test::BoundQp qp = test::random_bound_qp(n, seed + 100);
        const la::Vector reference = test::reference_bound_qp(qp.A, qp.b, qp.lower);
        ASSERT_LE(test::projected_gradient_norm(reference, qp.A * reference - qp.b, qp.lower), 1e-12 * qp.b.norm());
        test::CountingOperator A(qp.A);
        qp::Mprgp mprgp(A, {.rtol = 1e-12, .expansion = expansion});
        la::Vector x = la::Vector::Zero(n);
        const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
        ASSERT_TRUE(report.converged) << report.reason;
        EXPECT_LE((x - reference).norm(), 1e-8 * reference.norm());
      }
}

// Reference: Dostal & Schoberl (2005): with alpha_bar in (0, 2/||A||] every MPRGP step
// (CG, expansion, proportioning) does not increase f; a projected CG expansion that would is
// replaced by the standard one. alpha_bar = 1.8/lambda_max exactly
// here; 1e-12 |f| is the round-off of evaluating f from the recursive gradient.
TEST(Mprgp, CostDecreasesMonotonically)
{
  std::set<qp::MprgpStep> kinds;
  int fallbacks = 0;
  for (const qp::MprgpExpansion expansion : expansions)
    for (const double condition : {1e2, 1e4}) // 1e4: projected CG steps that raise f
      for (const int n : sizes)
        for (const unsigned seed : seeds)
        {
          SCOPED_TRACE(test::expansion_name(expansion) + ", condition " + std::to_string(condition) +
                       ", n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
          const test::BoundQp qp = test::random_bound_qp(n, seed + 200, condition);
          test::CountingOperator A(qp.A);
          std::vector<double> costs;
          qp::MprgpOptions options{.rtol = 1e-10, .expansion = expansion, .alpha_bar = 1.8 / largest_eigenvalue(qp.A)};
          options.monitor = [&](const qp::MprgpIterate& it) {
            EXPECT_EQ(it.iteration, static_cast<int>(costs.size()));
            costs.push_back(it.cost);
            kinds.insert(it.step);
          };
          qp::Mprgp mprgp(A, options);
          la::Vector x = la::Vector::Zero(n);
          const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
          ASSERT_TRUE(report.converged) << report.reason;
          ASSERT_EQ(static_cast<int>(costs.size()), report.iterations + 1);
          for (std::size_t k = 1; k < costs.size(); ++k)
            EXPECT_LE(costs[k], costs[k - 1] + 1e-12 * std::abs(costs[k - 1])) << "step " << k;
          EXPECT_EQ(mprgp.alpha_bar(), options.alpha_bar) << "no expansion may increase f";
          fallbacks += report.expansion_fallbacks;
        }
  // The projected CG step does raise f on some of these problems: the fallback is exercised.
  EXPECT_GT(fallbacks, 0);
  EXPECT_EQ(kinds.count(qp::MprgpStep::cg), 1u);
  EXPECT_EQ(kinds.count(qp::MprgpStep::expansion), 1u);
  EXPECT_EQ(kinds.count(qp::MprgpStep::proportioning), 1u);
}

// Reference: the product count of ALGORITHMS.md section 5 plus power iterations and
// refreshes (formula in qp/mprgp.hpp), checked against an operator that counts its calls.
TEST(Mprgp, ProductCountersFollowTheDocumentedFormula)
{
  const test::BoundQp qp = test::obstacle_problem(100);
  test::CountingOperator A(qp.A);
  qp::Mprgp mprgp(A, {.rtol = 1e-8});
  la::Vector x = la::Vector::Zero(qp.b.size());
  const qp::QpReport first = mprgp.solve(qp.b, qp.lower, x);
  ASSERT_TRUE(first.converged) << first.reason;
  ASSERT_GT(first.iterations, 50) << "the problem must be long enough to refresh g";
  const int power = qp::estimate_norm(A, 30).applications;
  EXPECT_EQ(first.iterations, first.cg_steps + first.expansion_steps + first.proportioning_steps);
  EXPECT_EQ(first.hessian_multiplications, predicted_products(first, power));
  EXPECT_EQ(first.hessian_multiplications + power, A.applications);

  // A second solve with the same object reuses alpha_bar: no power iterations.
  A.applications = 0;
  la::Vector y = la::Vector::Zero(qp.b.size());
  const qp::QpReport second = mprgp.solve(qp.b, qp.lower, y);
  ASSERT_TRUE(second.converged) << second.reason;
  EXPECT_EQ(second.hessian_multiplications, predicted_products(second, 0));
  EXPECT_EQ(second.hessian_multiplications, A.applications);

  // Another refresh interval changes only the refresh term.
  const test::BoundQp small = test::random_bound_qp(30, 7);
  test::CountingOperator B(small.A);
  qp::Mprgp refreshed(B, {.rtol = 1e-10, .alpha_bar = 1.0 / largest_eigenvalue(small.A), .gradient_refresh = 7});
  la::Vector z = la::Vector::Zero(30);
  const qp::QpReport third = refreshed.solve(small.b, small.lower, z);
  ASSERT_TRUE(third.converged) << third.reason;
  ASSERT_GE(third.iterations, 7);
  EXPECT_EQ(third.hessian_multiplications, predicted_products(third, 0, 7));
  EXPECT_EQ(third.hessian_multiplications, B.applications);
}

// Reference: without finite bounds MPRGP takes only CG steps and reduces to CG, which ends
// in at most n steps in exact arithmetic (Dostal 2009, section 8); compared with LDLT.
TEST(Mprgp, UnboundedProblemIsConjugateGradients)
{
  const test::BoundQp qp = test::random_bound_qp(40, 11, 100.0, 1.0);
  ASSERT_EQ(qp.lower.maxCoeff(), -std::numeric_limits<double>::infinity());
  test::CountingOperator A(qp.A);
  qp::Mprgp mprgp(A, {.rtol = 1e-12});
  la::Vector x = la::Vector::Constant(40, 3.0);
  const qp::QpReport report = mprgp.solve(qp.b, qp.lower, x);
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.cg_steps, report.iterations);
  EXPECT_LE(report.iterations, 60) << "CG on 40 unknowns, with some round-off slack";
  const la::Vector exact = qp.A.ldlt().solve(qp.b);
  EXPECT_LE((x - exact).norm(), 1e-9 * exact.norm());
}

// Reference: the initial guess is projected, x0 = max(x0, l) (ALGORITHMS.md section 5);
// a start on the solution (of a tighter solve) stops at iteration 0.
TEST(Mprgp, InitialGuessIsProjectedAndWarmStartStopsAtOnce)
{
  const test::BoundQp qp = test::random_bound_qp(20, 21);
  test::CountingOperator A(qp.A);
  qp::Mprgp mprgp(A, {.rtol = 1e-5, .alpha_bar = 1.0 / largest_eigenvalue(qp.A)});
  std::vector<double> start_costs;
  la::Vector x = qp.lower.cwiseMax(0.0) - la::Vector::Constant(20, 5.0);
  const la::Vector projected = x.cwiseMax(qp.lower);
  qp::MprgpOptions options{.rtol = 1e-6, .alpha_bar = 1.0 / largest_eigenvalue(qp.A)};
  options.monitor = [&](const qp::MprgpIterate& it) {
    if (it.iteration == 0)
      start_costs.push_back(it.cost);
  };
  qp::Mprgp monitored(A, options);
  ASSERT_TRUE(monitored.solve(qp.b, qp.lower, x).converged);
  ASSERT_EQ(start_costs.size(), 1u);
  EXPECT_NEAR(start_costs[0], 0.5 * projected.dot(qp.A * projected) - qp.b.dot(projected),
              1e-12 * (1.0 + std::abs(start_costs[0])));

  la::Vector warm = x;
  const qp::QpReport report = mprgp.solve(qp.b, qp.lower, warm);
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.iterations, 0);
  EXPECT_EQ(report.hessian_multiplications, 1);
  EXPECT_EQ(warm, x);
}

// QpSolver::solve's gradient: the solve hands back g = Ax - b at its last iterate, and a solve
// given that gradient (for a changed b, as SMALBE-M's next inner solve) starts without the
// product. Reference: the true gradient A x - b, and the same solve started from x alone.
TEST(Mprgp, StartsFromTheCallersGradient)
{
  const test::BoundQp qp = test::random_bound_qp(40, 3);
  test::CountingOperator A(qp.A);
  const qp::SeparableConstraints set{qp.lower, {}, {}};
  qp::Mprgp mprgp(A, {.rtol = 1e-6, .alpha_bar = 1.8 / largest_eigenvalue(qp.A)});
  la::Vector x = la::Vector::Zero(40), g;
  ASSERT_TRUE(mprgp.solve(qp.b, set, x, &g).converged);
  ASSERT_EQ(g.size(), 40);
  EXPECT_LT((g - (qp.A * x - qp.b)).norm(), 1e-12 * qp.b.norm());

  // b shifted along a vector d: the gradient at the same x shifts by -d.
  const la::Vector d = la::Vector::LinSpaced(40, -0.3, 0.2) * qp.b.norm() / 40;
  const la::Vector b2 = qp.b + d;
  la::Vector x_given = x, g_given = g - d, x_fresh = x;
  const int before = A.applications;
  const qp::QpReport given = mprgp.solve(b2, set, x_given, &g_given);
  const int given_products = A.applications - before;
  const qp::QpReport fresh = mprgp.solve(b2, set, x_fresh);
  ASSERT_TRUE(given.converged && fresh.converged);
  EXPECT_EQ(given_products, given.hessian_multiplications);
  EXPECT_EQ(given.hessian_multiplications + 1, fresh.hessian_multiplications);
  EXPECT_EQ(given.iterations, fresh.iterations);
  EXPECT_LT((x_given - x_fresh).norm(), 1e-10 * x_fresh.norm());

  // A start the set moves (x outside Omega) ignores the given gradient.
  la::Vector outside = x;
  outside[0] = qp.lower[0] - 1;
  la::Vector g_stale = g;
  const int before_outside = A.applications;
  const qp::QpReport projected = mprgp.solve(qp.b, set, outside, &g_stale);
  EXPECT_EQ(A.applications - before_outside, projected.hessian_multiplications);
  EXPECT_EQ(projected.hessian_multiplications, predicted_products(projected, 0));
}
