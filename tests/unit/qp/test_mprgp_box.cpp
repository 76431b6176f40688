/// MPRGP with two-sided bounds l <= x <= u (qp/mprgp.hpp; Dostal 2009, Optimal Quadratic
/// Programming Algorithms, ch. 8): KKT conditions, agreement with an independent active-set
/// solver, monotone cost, rejected empty boxes, and the lower-bound solve reproduced bitwise
/// when u = +infinity.

#include "common/error.hpp"
#include "qp/mprgp.hpp"
#include "qp_test_problems.hpp"
#include "reference_qp.hpp"
#include "solve_trace.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <vector>

using namespace feticon;

namespace
{
using la::infinity;

using test::largest_eigenvalue;

/// Components of x at their lower (l_i < u_i) and at their upper bound (l_i < u_i).
struct ActiveCounts
{
  int at_lower = 0;
  int at_upper = 0;
};

/// KKT conditions at tolerance `tol` with the true gradient g = Ax - b: l <= x <= u exactly;
/// g_i >= -tol where x_i = l_i < u_i, g_i <= tol where x_i = u_i > l_i, |g_i| <= tol where
/// l_i < x_i < u_i; a fixed component (l_i = u_i) has any multiplier.
ActiveCounts expect_box_kkt(const test::BoxQp& qp, const la::Vector& x, double tol)
{
  const la::Vector g = qp.A * x - qp.b;
  ActiveCounts counts;
  for (la::Index i = 0; i < x.size(); ++i)
  {
    EXPECT_GE(x[i], qp.lower[i]) << "component " << i;
    EXPECT_LE(x[i], qp.upper[i]) << "component " << i;
    if (qp.lower[i] == qp.upper[i])
      continue;
    if (x[i] == qp.lower[i])
    {
      EXPECT_GE(g[i], -tol) << "component " << i << " at its lower bound";
      ++counts.at_lower;
    }
    else if (x[i] == qp.upper[i])
    {
      EXPECT_LE(g[i], tol) << "component " << i << " at its upper bound";
      ++counts.at_upper;
    }
    else
      EXPECT_LE(std::abs(g[i]), tol) << "free component " << i;
  }
  return counts;
}

using test::expansions;
using test::seeds;
using test::sizes;

/// One solve of `qp` from x0 = 0, with u = `upper` (the lower-bound overload if null).
test::Trace traced_solve(const la::Matrix& matrix, const la::Vector& b, const la::Vector& lower,
                         const la::Vector* upper, qp::MprgpOptions options)
{
  test::Trace trace;
  options.monitor = [&](const qp::MprgpIterate& it) { trace.iterates.push_back(it); };
  test::CountingOperator A(matrix);
  qp::Mprgp mprgp(A, options);
  trace.x = la::Vector::Zero(b.size());
  trace.report = upper ? mprgp.solve(b, lower, *upper, trace.x) : mprgp.solve(b, lower, trace.x);
  return trace;
}

/// The minimizer of a box QP by enumeration (n <= 8): every assignment of each component to
/// free, its lower or its upper bound (finite ones only), the free part solved by LDLT; the
/// assignment whose point is feasible and meets the KKT sign conditions to `tol` is the
/// minimizer (unique, A SPD). Independent of Mprgp and of reference_box_qp.
la::Vector enumerated_box_qp(const test::BoxQp& qp, double tol)
{
  const la::Index n = qp.b.size();
  std::vector<int> state(static_cast<std::size_t>(n), 0); // 0 free, 1 lower, 2 upper
  for (;;)
  {
    bool valid = true;
    la::Vector x = la::Vector::Zero(n);
    std::vector<la::Index> free;
    for (la::Index i = 0; i < n; ++i)
    {
      if (state[i] == 0)
        free.push_back(i);
      else
        x[i] = state[i] == 1 ? qp.lower[i] : qp.upper[i];
      valid = valid && std::isfinite(x[i]);
    }
    if (valid)
    {
      const auto m = static_cast<la::Index>(free.size());
      la::Matrix A_ff(m, m);
      la::Vector rhs(m);
      const la::Vector fixed_part = qp.A * x;
      for (la::Index r = 0; r < m; ++r)
      {
        rhs[r] = qp.b[free[r]] - fixed_part[free[r]];
        for (la::Index c = 0; c < m; ++c)
          A_ff(r, c) = qp.A(free[r], free[c]);
      }
      const la::Vector z = A_ff.ldlt().solve(rhs);
      for (la::Index r = 0; r < m; ++r)
        x[free[r]] = z[r];
      const la::Vector g = qp.A * x - qp.b;
      bool kkt = true;
      for (la::Index i = 0; i < n; ++i)
      {
        kkt = kkt && x[i] >= qp.lower[i] - tol && x[i] <= qp.upper[i] + tol;
        if (state[i] == 1 && qp.lower[i] < qp.upper[i])
          kkt = kkt && g[i] >= -tol;
        if (state[i] == 2 && qp.lower[i] < qp.upper[i])
          kkt = kkt && g[i] <= tol;
      }
      if (kkt)
        return x;
    }
    la::Index i = 0; // the next assignment, in base 3
    while (i < n && state[i] == 2)
      state[i++] = 0;
    if (i == n)
      throw std::runtime_error("enumerated_box_qp: no KKT point");
    ++state[i];
  }
}
} // namespace

// Reference: the stopping test ||g_P|| <= rtol ||b|| (ALGORITHMS.md section 5, with the
// projected gradient of the box) bounds every KKT residual component by rtol ||b||; the
// margin 1e-12 ||A|| ||x|| covers the drift of the recursive gradient, as in test_mprgp.cpp.
TEST(MprgpBox, RandomBoxProblemsSatisfyKktAtRequestedTolerance)
{
  ActiveCounts total;
  int components = 0;
  for (const qp::MprgpExpansion expansion : expansions)
    for (const int n : sizes)
      for (const unsigned seed : seeds)
      {
        SCOPED_TRACE(test::expansion_name(expansion) + ", n = " + std::to_string(n) +
                     ", seed = " + std::to_string(seed));
        const test::BoxQp qp = test::random_box_qp(n, seed);
        test::CountingOperator A(qp.A);
        const double rtol = 1e-5;
        qp::Mprgp mprgp(A, {.rtol = rtol, .expansion = expansion});
        la::Vector x = la::Vector::Zero(n);
        const qp::QpReport report = mprgp.solve(qp.b, qp.lower, qp.upper, x);
        ASSERT_TRUE(report.converged) << report.reason;
        const ActiveCounts counts = expect_box_kkt(qp, x, rtol * qp.b.norm() + 1e-12 * qp.A.norm() * x.norm());
        EXPECT_EQ(report.hessian_multiplications, A.applications);
        EXPECT_NEAR(report.cost, 0.5 * x.dot(qp.A * x) - qp.b.dot(x), 1e-10 * (1.0 + std::abs(report.cost)));
        total.at_lower += counts.at_lower;
        total.at_upper += counts.at_upper;
        components += n;
      }
  // Both bounds must be exercised, or this would test the lower-bound algorithm only.
  EXPECT_GT(total.at_lower, components / 10);
  EXPECT_GT(total.at_upper, components / 10);
}

// Reference: the independent primal active-set solver reference_box_qp (reference_qp.hpp,
// exact on its final working set; its own KKT residual is checked first). With
// ||g_P|| <= 1e-12 ||b|| and lambda_min(A) = 1 the error bound ||x - x*|| <= ||g_P|| /
// lambda_min is 1e-12 ||b||, well inside 1e-8 relative. With and without the Jacobi
// preconditioner in the face, which changes the path, not the minimizer.
TEST(MprgpBox, RandomBoxProblemsMatchActiveSetReference)
{
  for (const bool preconditioned : {false, true})
    for (const qp::MprgpExpansion expansion : expansions)
      for (const int n : sizes)
        for (const unsigned seed : seeds)
        {
          SCOPED_TRACE(test::expansion_name(expansion) + (preconditioned ? " jacobi" : "") +
                       ", n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
          const test::BoxQp qp = test::random_box_qp(n, seed + 100);
          const la::Vector reference = test::reference_box_qp(qp.A, qp.b, qp.lower, qp.upper);
          ASSERT_LE(test::projected_gradient_norm(reference, qp.A * reference - qp.b, qp.lower, qp.upper),
                    1e-12 * qp.b.norm());
          test::CountingOperator A(qp.A);
          const test::JacobiOperator jacobi(qp.A);
          qp::Mprgp mprgp(
              A, {.rtol = 1e-12, .expansion = expansion, .preconditioner = preconditioned ? &jacobi : nullptr});
          la::Vector x = la::Vector::Zero(n);
          const qp::QpReport report = mprgp.solve(qp.b, qp.lower, qp.upper, x);
          ASSERT_TRUE(report.converged) << report.reason;
          EXPECT_LE((x - reference).norm(), 1e-8 * reference.norm());
        }
}

// Reference: Dostal & Schoberl (2005): with alpha_bar in (0, 2/||A||] no MPRGP step increases
// f; the proportioning step cut at a bound keeps this (f is a convex parabola along beta,
// decreasing up to the uncut step). alpha_bar = 1.8/lambda_max exactly; 1e-12 |f| is the
// round-off of evaluating f from the recursive gradient (as in test_mprgp.cpp).
TEST(MprgpBox, CostDecreasesMonotonically)
{
  std::set<qp::MprgpStep> kinds;
  for (const qp::MprgpExpansion expansion : expansions)
    for (const double condition : {1e2, 1e4})
      for (const int n : sizes)
        for (const unsigned seed : seeds)
        {
          SCOPED_TRACE(test::expansion_name(expansion) + ", condition " + std::to_string(condition) +
                       ", n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
          const test::BoxQp qp = test::random_box_qp(n, seed + 200, condition);
          const test::Trace trace =
              traced_solve(qp.A, qp.b, qp.lower, &qp.upper,
                           {.rtol = 1e-10, .expansion = expansion, .alpha_bar = 1.8 / largest_eigenvalue(qp.A)});
          ASSERT_TRUE(trace.report.converged) << trace.report.reason;
          ASSERT_EQ(static_cast<int>(trace.iterates.size()), trace.report.iterations + 1);
          for (std::size_t k = 1; k < trace.iterates.size(); ++k)
          {
            const double previous = trace.iterates[k - 1].cost;
            EXPECT_LE(trace.iterates[k].cost, previous + 1e-12 * std::abs(previous)) << "step " << k;
            kinds.insert(trace.iterates[k].step);
          }
        }
  EXPECT_EQ(kinds.count(qp::MprgpStep::cg), 1u);
  EXPECT_EQ(kinds.count(qp::MprgpStep::expansion), 1u);
  EXPECT_EQ(kinds.count(qp::MprgpStep::proportioning), 1u);
}

// Reference: the bitwise claim of qp/mprgp.hpp: with u = +infinity everywhere every
// per-component test and clamp reduces to the lower-bound one, so iterates, x and report are
// those of the lower-bound overload exactly (std and projcg, with and without Jacobi).
TEST(MprgpBox, InfiniteUpperBoundReproducesTheLowerBoundSolveBitwise)
{
  for (const bool preconditioned : {false, true})
    for (const qp::MprgpExpansion expansion : expansions)
      for (const int n : {5, 25, 60})
        for (const unsigned seed : {1u, 2u, 3u})
        {
          SCOPED_TRACE(test::expansion_name(expansion) + (preconditioned ? " jacobi" : "") +
                       ", n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
          const test::BoundQp qp = test::random_bound_qp(n, seed + 300, 1e3);
          const la::Vector upper = la::Vector::Constant(n, infinity);
          const test::JacobiOperator jacobi(qp.A);
          const qp::MprgpOptions options{
              .rtol = 1e-10, .expansion = expansion, .preconditioner = preconditioned ? &jacobi : nullptr};
          const test::Trace lower_only = traced_solve(qp.A, qp.b, qp.lower, nullptr, options);
          const test::Trace box = traced_solve(qp.A, qp.b, qp.lower, &upper, options);
          ASSERT_TRUE(lower_only.report.converged) << lower_only.report.reason;
          ASSERT_GT(lower_only.report.proportioning_steps + lower_only.report.expansion_steps, 0);
          test::expect_identical(lower_only, box);
        }
}

// Reference: x <= u is y = -x >= -u, and IEEE negation is exact (A(-x) = -(Ax), min and max
// swap), so MPRGP on min 1/2 x'Ax - b'x, x <= u takes bitwise the steps of MPRGP on
// min 1/2 y'Ay + b'y, y >= -u, with x = -y. This checks the upper-bound branches against the
// lower-bound algorithm of test_mprgp.cpp.
TEST(MprgpBox, UpperBoundsMirrorLowerBoundsExactly)
{
  for (const qp::MprgpExpansion expansion : expansions)
    for (const int n : {5, 25, 60})
      for (const unsigned seed : {1u, 2u, 3u})
      {
        SCOPED_TRACE(test::expansion_name(expansion) + ", n = " + std::to_string(n) +
                     ", seed = " + std::to_string(seed));
        const test::BoundQp qp = test::random_bound_qp(n, seed + 400);
        const la::Vector no_lower = la::Vector::Constant(n, -infinity);
        const la::Vector upper = -qp.lower;
        const la::Vector minus_b = -qp.b;
        const qp::MprgpOptions options{.rtol = 1e-10, .expansion = expansion};
        const test::Trace mirrored = traced_solve(qp.A, minus_b, no_lower, &upper, options);
        test::Trace lower = traced_solve(qp.A, qp.b, qp.lower, nullptr, options);
        ASSERT_TRUE(lower.report.converged) << lower.report.reason;
        lower.x = -lower.x;
        test::expect_identical(lower, mirrored);
      }
}

// Reference: STYLE.md, Errors: an empty box (l_i > u_i) is input, rejected by FETICON_CHECK
// with one line naming the component; so are NaN, -inf and a wrong size for u.
TEST(MprgpBox, InvalidUpperBoundsAreRejectedNamingTheComponent)
{
  const test::BoxQp qp = test::random_box_qp(6, 1);
  test::CountingOperator A(qp.A);
  qp::Mprgp mprgp(A, {});
  la::Vector x = la::Vector::Zero(6);
  la::Vector lower = la::Vector::Zero(6);
  la::Vector upper = la::Vector::Ones(6);
  upper[3] = -0.5;
  try
  {
    mprgp.solve(qp.b, lower, upper, x);
    ADD_FAILURE() << "l[3] > u[3] accepted";
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("component 3"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_EQ(x, la::Vector::Zero(6)) << "x changed by a rejected solve";

  upper = la::Vector::Ones(6);
  upper[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mprgp.solve(qp.b, lower, upper, x), Error);
  upper[1] = -infinity;
  EXPECT_THROW(mprgp.solve(qp.b, lower, upper, x), Error);
  EXPECT_THROW(mprgp.solve(qp.b, lower, la::Vector::Ones(5), x), Error);

  // l_i = u_i fixes x_i; it is not an empty box.
  upper = la::Vector::Ones(6);
  upper[2] = lower[2];
  ASSERT_TRUE(mprgp.solve(qp.b, lower, upper, x).converged);
  EXPECT_EQ(x[2], 0.0);
}

// Reference: enumeration of all 3^n assignments to free / lower / upper (enumerated_box_qp
// above, exact up to the LDLT solve), independent of both Mprgp and reference_box_qp; the
// KKT tolerance 1e-9 ||b|| only admits round-off of the n <= 7 dense solves. MPRGP at
// rtol 1e-12 and the active-set reference must both agree with it to 1e-8 relative (the
// error bound of RandomBoxProblemsMatchActiveSetReference).
TEST(MprgpBox, SmallProblemsMatchEnumeratedActiveSets)
{
  for (const int n : {2, 3, 5, 7})
    for (const unsigned seed : seeds)
    {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
      const test::BoxQp qp = test::random_box_qp(n, seed + 500);
      const la::Vector enumerated = enumerated_box_qp(qp, 1e-9 * qp.b.norm());
      const la::Vector reference = test::reference_box_qp(qp.A, qp.b, qp.lower, qp.upper);
      test::CountingOperator A(qp.A);
      qp::Mprgp mprgp(A, {.rtol = 1e-12});
      la::Vector x = la::Vector::Zero(n);
      ASSERT_TRUE(mprgp.solve(qp.b, qp.lower, qp.upper, x).converged);
      const double scale = 1e-8 * std::max(enumerated.norm(), 1.0);
      EXPECT_LE((x - enumerated).norm(), scale);
      EXPECT_LE((reference - enumerated).norm(), scale);
    }
}

// Reference: hand computation. min 1/2 x^2 - 5x on 0 <= x <= 1 from x0 = 0: no free
// component, beta = g = -5, so a proportioning step; its length g'beta / beta'A beta = 1 would
// reach x = 5 > u, so it is cut at alpha_f = (0 - 1)/(-5) = 0.2: x = 1 exactly, where g = -4
// is a multiplier of the upper bound (chopped gradient max(g, 0) = 0): converged after one
// step, f = 1/2 - 5 = -4.5.
TEST(MprgpBox, ProportioningStepStopsAtTheOppositeBound)
{
  const la::Matrix one = la::Matrix::Identity(1, 1);
  test::CountingOperator A(one);
  qp::Mprgp mprgp(A, {.rtol = 1e-12, .alpha_bar = 1.0});
  la::Vector x = la::Vector::Zero(1);
  const qp::QpReport report = mprgp.solve(la::Vector::Constant(1, 5.0), la::Vector::Zero(1), la::Vector::Ones(1), x);
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.iterations, 1);
  EXPECT_EQ(report.proportioning_steps, 1);
  EXPECT_EQ(x[0], 1.0);
  EXPECT_EQ(report.cost, -4.5);
}
