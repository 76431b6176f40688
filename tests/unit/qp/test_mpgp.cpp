/// MPGP over separable convex sets (qp/mpgp.hpp, qp/separable_constraints.hpp): bounds and
/// discs ||(x_i, x_j)|| <= r. KKT conditions checked directly, agreement with an independent
/// accelerated projected gradient solve, monotone cost, the expansion step as a projection,
/// exact product counts, MPRGP reproduced bitwise without discs, rejected input.

#include "common/error.hpp"
#include "qp/mpgp.hpp"
#include "qp/mprgp.hpp"
#include "qp/norm_estimate.hpp"
#include "qp/separable_constraints.hpp"
#include "qp_test_problems.hpp"
#include "solve_trace.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace feticon;

namespace
{
using la::infinity;

/// min 1/2 x'Ax - b'x subject to x in `set`.
struct DiscQp
{
  la::Matrix A;
  la::Vector b;
  qp::SeparableConstraints set;
};

/// The random SPD A and b of test::random_bound_qp (eigenvalues log-spaced in [1, condition]);
/// from the unconstrained minimizer x_u, components taken in order become, at random, a disc
/// with the next one (radius `small` ||x_u pair||: mostly active at the solution; 2.5 ||x_u
/// pair||: mostly inactive; 0: a fixed pair), a lower bound scattered about x_u (Tresca's normal
/// multipliers), a box, or free.
DiscQp random_disc_qp(int n, unsigned seed, double condition = 100.0, double small = 0.4)
{
  const test::BoundQp base = test::random_bound_qp(n, seed, condition, 0.0);
  std::mt19937 generator(seed + 4099);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const la::Vector unconstrained = base.A.ldlt().solve(base.b);
  const double spread = std::sqrt(unconstrained.squaredNorm() / n);
  DiscQp qp{base.A, base.b, {la::Vector::Constant(n, -infinity), la::Vector::Constant(n, infinity), {}}};
  for (int i = 0; i < n; ++i)
  {
    const double kind = uniform(generator);
    if (kind < 0.5 && i + 1 < n)
    {
      const double size = std::hypot(unconstrained[i], unconstrained[i + 1]);
      const double shape = uniform(generator);
      const double radius = shape < 0.45 ? small * size : shape < 0.9 ? 2.5 * size + 0.1 * spread : 0.0;
      qp.set.discs.push_back({i, i + 1, radius});
      ++i;
    }
    else if (kind < 0.75)
      qp.set.lower[i] = unconstrained[i] + 0.5 * spread * normal(generator);
    else if (kind < 0.85)
    {
      qp.set.lower[i] = unconstrained[i] + 0.5 * spread * normal(generator);
      qp.set.upper[i] = qp.set.lower[i] + 0.5 * spread * std::abs(normal(generator));
    }
  }
  return qp;
}

/// P_Omega written here from the definition, independent of qp::project.
la::Vector projected(const qp::SeparableConstraints& set, la::Vector x)
{
  for (la::Index i = 0; i < x.size(); ++i)
    x[i] = std::min(std::max(x[i], set.lower[i]), set.upper[i]);
  for (const qp::Disc& disc : set.discs)
  {
    const double norm = std::sqrt(x[disc.i] * x[disc.i] + x[disc.j] * x[disc.j]);
    if (norm > disc.radius)
    {
      x[disc.i] = norm > 0.0 ? x[disc.i] * disc.radius / norm : 0.0;
      x[disc.j] = norm > 0.0 ? x[disc.j] * disc.radius / norm : 0.0;
    }
  }
  return x;
}

/// The components of the set's discs.
std::vector<bool> disc_components(const qp::SeparableConstraints& set, la::Index n)
{
  std::vector<bool> in_disc(static_cast<std::size_t>(n), false);
  for (const qp::Disc& disc : set.discs)
    in_disc[disc.i] = in_disc[disc.j] = true;
  return in_disc;
}

/// How the discs ended at the checked point.
struct DiscCounts
{
  int active = 0;
  int inactive = 0;
  int fixed = 0; ///< radius 0
};

/// KKT conditions at tolerance `tol` with the true gradient g = Ax - b, from their definition:
/// x in Omega (bounds exactly, discs to 1e-12 relative); on bounds the sign conditions of
/// test_mprgp_box.cpp; |g_i| <= tol on free components; on a disc inside its circle
/// |g_d| <= tol; on its circle g_d = -nu x_d/||x_d|| with nu >= -tol and the tangential part
/// of g_d below tol; a disc of radius 0 has x_d = 0 exactly and any g_d.
DiscCounts expect_kkt(const DiscQp& qp, const la::Vector& x, double tol)
{
  const la::Vector g = qp.A * x - qp.b;
  const qp::SeparableConstraints& set = qp.set;
  const std::vector<bool> in_disc = disc_components(set, x.size());
  for (la::Index i = 0; i < x.size(); ++i)
  {
    if (in_disc[i])
      continue;
    EXPECT_GE(x[i], set.lower[i]) << "component " << i;
    EXPECT_LE(x[i], set.upper[i]) << "component " << i;
    if (set.lower[i] == set.upper[i])
      continue;
    if (x[i] == set.lower[i])
      EXPECT_GE(g[i], -tol) << "component " << i << " at its lower bound";
    else if (x[i] == set.upper[i])
      EXPECT_LE(g[i], tol) << "component " << i << " at its upper bound";
    else
      EXPECT_LE(std::abs(g[i]), tol) << "free component " << i;
  }
  DiscCounts counts;
  for (const qp::Disc& disc : set.discs)
  {
    const double norm = std::hypot(x[disc.i], x[disc.j]);
    EXPECT_LE(norm, disc.radius * (1.0 + 1e-12)) << "disc (" << disc.i << ", " << disc.j << ")";
    if (disc.radius == 0.0)
    {
      EXPECT_EQ(x[disc.i], 0.0);
      EXPECT_EQ(x[disc.j], 0.0);
      ++counts.fixed;
    }
    else if (norm < disc.radius * (1.0 - 1e-9))
    {
      EXPECT_LE(std::hypot(g[disc.i], g[disc.j]), tol) << "inactive disc (" << disc.i << ", " << disc.j << ")";
      ++counts.inactive;
    }
    else
    {
      const double n_i = x[disc.i] / norm;
      const double n_j = x[disc.j] / norm;
      const double nu = -(n_i * g[disc.i] + n_j * g[disc.j]);
      EXPECT_GE(nu, -tol) << "active disc (" << disc.i << ", " << disc.j << ")";
      EXPECT_LE(std::hypot(g[disc.i] + nu * n_i, g[disc.j] + nu * n_j), tol)
          << "tangential gradient on active disc (" << disc.i << ", " << disc.j << ")";
      ++counts.active;
    }
  }
  return counts;
}

/// Independent reference: FISTA (Beck & Teboulle 2009) with the adaptive restart of
/// O'Donoghue & Candes (2015), step 1/L with L = lambda_max(A) exactly, the projection of
/// `projected` above; stops when the natural residual L ||x - P(x - g/L)|| <= tol.
la::Vector accelerated_projected_gradient(const DiscQp& qp, double tol, int& iterations)
{
  const double L = Eigen::SelfAdjointEigenSolver<la::Matrix>(qp.A).eigenvalues().maxCoeff();
  la::Vector x = projected(qp.set, la::Vector::Zero(qp.b.size()));
  la::Vector y = x;
  double t = 1.0;
  for (iterations = 1; iterations <= 200000; ++iterations)
  {
    const la::Vector x_next = projected(qp.set, y - (qp.A * y - qp.b) / L);
    if ((y - x_next).dot(x_next - x) > 0.0)
      t = 1.0; // restart: the momentum points uphill
    const double t_next = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * t * t));
    y = x_next + ((t - 1.0) / t_next) * (x_next - x);
    x = x_next;
    t = t_next;
    if (iterations % 10 == 0 && L * (x - projected(qp.set, x - (qp.A * x - qp.b) / L)).norm() <= tol)
      return x;
  }
  throw std::runtime_error("accelerated_projected_gradient: no convergence");
}

/// One MPGP solve from x0 = 0 with its trace.
test::Trace traced_mpgp(const la::Matrix& matrix, const la::Vector& b, const qp::SeparableConstraints& set,
                        qp::MpgpOptions options, int* applications = nullptr)
{
  test::Trace trace;
  options.monitor = [&](const qp::MprgpIterate& it) { trace.iterates.push_back(it); };
  test::CountingOperator A(matrix);
  qp::Mpgp mpgp(A, options);
  trace.x = la::Vector::Zero(b.size());
  trace.report = mpgp.solve(b, set, trace.x);
  if (applications)
    *applications = A.applications;
  return trace;
}

const int disc_sizes[] = {20, 60, 200};
using test::seeds;
} // namespace

// Reference: hand computation. With A = I the minimizer of 1/2||x||^2 - b'x over Omega is
// P_Omega(b): b = (3, 4) on the unit disc gives (0.6, 0.8) (active, nu = 4), b = (0.3, 0.4)
// stays inside, x_2 >= 1 with b_2 = -2 gives 1, and a disc of radius 0 gives (0, 0).
TEST(Mpgp, IdentityHessianGivesTheProjectionOfB)
{
  const la::Matrix identity = la::Matrix::Identity(7, 7);
  la::Vector b(7);
  b << 3.0, 4.0, -2.0, 0.3, 0.4, 5.0, -1.0;
  qp::SeparableConstraints set{
      la::Vector::Constant(7, -infinity), la::Vector::Constant(7, infinity), {{0, 1, 1.0}, {3, 4, 1.0}, {5, 6, 0.0}}};
  set.lower[2] = 1.0;
  test::CountingOperator A(identity);
  qp::Mpgp mpgp(A, {.rtol = 1e-14, .alpha_bar = 1.0});
  la::Vector x = la::Vector::Zero(7);
  const qp::QpReport report = mpgp.solve(b, set, x);
  ASSERT_TRUE(report.converged) << report.reason;
  la::Vector expected(7);
  expected << 0.6, 0.8, 1.0, 0.3, 0.4, 0.0, 0.0;
  EXPECT_LE((x - expected).norm(), 1e-14);
  EXPECT_EQ(report.hessian_multiplications, A.applications);
}

// Reference: the KKT conditions from their definition (expect_kkt). The stopping test
// ||g_P|| <= rtol ||b|| bounds each residual: on an active disc beta is the tangential part of
// g (then nu >= 0 exactly) or g itself (then nu >= -||g_P||); the margin 1e-12 ||A|| ||x||
// covers the drift of the recursive gradient, as in test_mprgp_box.cpp. The products are
// those of CountingOperator, and they exceed MPRGP's formula by one per CG step along circles
// (the recomputed gradient) and per fallback at most (qp/mpgp.hpp).
TEST(Mpgp, RandomDiscProblemsSatisfyKkt)
{
  DiscCounts total;
  for (const int n : disc_sizes)
    for (const unsigned seed : seeds)
    {
      SCOPED_TRACE("n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
      const DiscQp qp = random_disc_qp(n, seed);
      const double rtol = 1e-8;
      int applications = 0;
      const test::Trace trace = traced_mpgp(qp.A, qp.b, qp.set, {.rtol = rtol}, &applications);
      const qp::QpReport& r = trace.report;
      ASSERT_TRUE(r.converged) << r.reason;
      EXPECT_TRUE(qp::is_feasible(qp.set, trace.x));
      const DiscCounts counts = expect_kkt(qp, trace.x, rtol * qp.b.norm() + 1e-12 * qp.A.norm() * trace.x.norm());
      EXPECT_EQ(r.hessian_multiplications, applications);
      EXPECT_NEAR(r.cost, 0.5 * trace.x.dot(qp.A * trace.x) - qp.b.dot(trace.x), 1e-10 * (1.0 + std::abs(r.cost)));
      const int counted =
          1 + r.cg_steps + 2 * r.expansion_steps + r.proportioning_steps + r.expansion_fallbacks + r.iterations / 50;
      // What is left after the power iterations (estimate_norm's count, rerun here with
      // Mpgp's arguments): one product per CG step along circles and per fallback.
      test::CountingOperator power_operator(qp.A);
      const int power_iterations = qp::estimate_norm(power_operator, 30, 1e-3, 1).applications;
      EXPECT_GE(applications - power_iterations - counted, 0);
      EXPECT_LE(applications - power_iterations - counted, r.cg_steps + r.expansion_fallbacks);
      total.active += counts.active;
      total.inactive += counts.inactive;
      total.fixed += counts.fixed;
    }
  // Both kinds of disc must occur, or this would test bounds only.
  const int discs = total.active + total.inactive + total.fixed;
  EXPECT_GT(total.active, discs / 5);
  EXPECT_GT(total.inactive, discs / 5);
  EXPECT_GT(total.fixed, discs / 20);
}

// Reference: accelerated_projected_gradient above (FISTA with restart, its own projection),
// run until its natural residual is below 1e-13 ||b||, then certified by expect_kkt at
// 1e-10 ||b||. MPGP at rtol 1e-12 must agree to 1e-8 relative: with lambda_min(A) = 1 the
// error of either is at most a few times its residual, 1e-12 ||b||. With and without the Jacobi
// preconditioner in the face, which changes the path, not the minimizer.
TEST(Mpgp, RandomDiscProblemsMatchAcceleratedProjectedGradient)
{
  for (const bool preconditioned : {false, true})
    for (const int n : disc_sizes)
      for (const unsigned seed : seeds)
      {
        SCOPED_TRACE(std::string(preconditioned ? "jacobi, " : "") + "n = " + std::to_string(n) +
                     ", seed = " + std::to_string(seed));
        const DiscQp qp = random_disc_qp(n, seed + 100);
        int reference_iterations = 0;
        const la::Vector reference = accelerated_projected_gradient(qp, 1e-13 * qp.b.norm(), reference_iterations);
        expect_kkt(qp, reference, 1e-10 * qp.b.norm());
        const test::JacobiOperator jacobi(qp.A);
        const test::Trace trace =
            traced_mpgp(qp.A, qp.b, qp.set, {.rtol = 1e-12, .preconditioner = preconditioned ? &jacobi : nullptr});
        ASSERT_TRUE(trace.report.converged) << trace.report.reason;
        EXPECT_LE((trace.x - reference).norm(), 1e-8 * reference.norm());
        std::printf("[ figures  ] n %3d seed %u%s: MPGP %4d steps (cg %4d, exp %3d, prop %3d, fallback %2d), "
                    "%4d products; FISTA %5d iterations\n",
                    n, seed + 100, preconditioned ? " jacobi" : "", trace.report.iterations, trace.report.cg_steps,
                    trace.report.expansion_steps, trace.report.proportioning_steps, trace.report.expansion_fallbacks,
                    trace.report.hessian_multiplications, reference_iterations);
      }
}

// Reference: the substitution x = y + c. Discs centred at c (a homogenized contact dual's
// friction discs, centred at -lambda~_T) give the QP of discs at the origin in y with
// b_x = b_y + A c: the solution is y* + c, y* from MPGP on the centred problem (itself checked
// against FISTA above), to the solve's tolerance.
TEST(Mpgp, ShiftedDiscsGiveTheShiftedSolution)
{
  for (const unsigned seed : seeds)
  {
    const DiscQp centred = random_disc_qp(60, seed + 300);
    la::Vector c = la::Vector::Zero(60);
    DiscQp shifted = centred;
    std::mt19937 generator(seed);
    std::normal_distribution<double> normal;
    for (qp::Disc& disc : shifted.set.discs)
    {
      disc.centre_i = c[disc.i] = normal(generator);
      disc.centre_j = c[disc.j] = normal(generator);
    }
    shifted.b = centred.b + centred.A * c;
    const test::Trace y = traced_mpgp(centred.A, centred.b, centred.set, {.rtol = 1e-12});
    const test::Trace x = traced_mpgp(shifted.A, shifted.b, shifted.set, {.rtol = 1e-12});
    ASSERT_TRUE(x.report.converged && y.report.converged) << x.report.reason << y.report.reason;
    EXPECT_LE((x.x - (y.x + c)).norm(), 1e-8 * (y.x + c).norm()) << "seed " << seed + 300;
    EXPECT_TRUE(qp::is_feasible(shifted.set, x.x));
  }
}

// Reference: Dostal & Kozubek (2012): with alpha_bar in (0, 2/||A||] no MPGP step increases f;
// a step along circles (monotone to second order only) is kept only if f did not increase,
// else replaced by the gradient projection step, monotone for such alpha_bar. alpha_bar =
// 1.8/lambda_max exactly; 1e-12 |f| is the round-off of evaluating f from the recursive
// gradient, and at a gradient refresh the drift the refresh removes (50 eps ||A|| ||x||^2, seen
// with small f). Small discs (radius 0.01 of the unconstrained pair: strong curvature nu/r) too.
TEST(Mpgp, CostDecreasesMonotonically)
{
  std::set<qp::MprgpStep> kinds;
  int fallbacks = 0;
  for (const double small : {0.4, 0.01})
    for (const double condition : {1e2, 1e4})
      for (const int n : disc_sizes)
        for (const unsigned seed : seeds)
        {
          SCOPED_TRACE("small discs " + std::to_string(small) + ", condition " + std::to_string(condition) +
                       ", n = " + std::to_string(n) + ", seed = " + std::to_string(seed));
          const DiscQp qp = random_disc_qp(n, seed + 200, condition, small);
          const double lambda_max = Eigen::SelfAdjointEigenSolver<la::Matrix>(qp.A).eigenvalues().maxCoeff();
          const test::Trace trace =
              traced_mpgp(qp.A, qp.b, qp.set, {.rtol = 1e-10, .max_iterations = 100000, .alpha_bar = 1.8 / lambda_max});
          ASSERT_TRUE(trace.report.converged) << trace.report.reason;
          ASSERT_EQ(static_cast<int>(trace.iterates.size()), trace.report.iterations + 1);
          // At a gradient refresh (every 50 steps) f is evaluated from the exact gradient after
          // 50 recursive updates, each off by round-off eps ||A|| ||x||.
          const double refresh_drift = 50 * std::numeric_limits<double>::epsilon() * lambda_max * trace.x.squaredNorm();
          for (std::size_t k = 1; k < trace.iterates.size(); ++k)
          {
            const double previous = trace.iterates[k - 1].cost;
            EXPECT_LE(trace.iterates[k].cost,
                      previous + 1e-12 * std::abs(previous) + (k % 50 == 0 ? refresh_drift : 0.0))
                << "step " << k;
            kinds.insert(trace.iterates[k].step);
          }
          fallbacks += trace.report.expansion_fallbacks;
        }
  EXPECT_EQ(kinds.count(qp::MprgpStep::cg), 1u);
  EXPECT_EQ(kinds.count(qp::MprgpStep::expansion), 1u);
  EXPECT_EQ(kinds.count(qp::MprgpStep::proportioning), 1u);
  std::printf("[ figures  ] fallbacks to the gradient projection step: %d\n", fallbacks);
}

// Reference: the expansion step of qp/mpgp.hpp computed here by hand. From x0 = 0 inside every
// disc, g0 = -b = phi, the CG direction is p = g0 and x - t p leaves disc d at t = r_d/||p_d||;
// with small discs the CG step leaves one, so the first step is an expansion:
// x_h = -alpha_f p (alpha_f the smallest such t), g_h = g0 - alpha_f A p, phi_h = g_h but the
// tangential part of g_h on the blocking disc (on its circle now), and
// x1 = P(x_h - alpha_bar phi_h) with P from its definition (`projected`).
TEST(Mpgp, ExpansionStepIsTheProjectionOfTheGradientStep)
{
  const test::BoundQp base = test::random_bound_qp(8, 17, 10.0, 0.0);
  const la::Vector unconstrained = base.A.ldlt().solve(base.b);
  qp::SeparableConstraints set{la::Vector::Constant(8, -infinity), la::Vector::Constant(8, infinity), {}};
  for (la::Index i = 0; i < 8; i += 2)
    set.discs.push_back({i, i + 1, 0.2 * std::hypot(unconstrained[i], unconstrained[i + 1])});
  const double alpha_bar = 1.0 / base.A.norm();

  const la::Vector p = -base.b;
  double alpha_f = infinity;
  la::Index blocking = -1;
  for (const qp::Disc& disc : set.discs)
    if (const double t = disc.radius / std::hypot(p[disc.i], p[disc.j]); t < alpha_f)
    {
      alpha_f = t;
      blocking = disc.i;
    }
  ASSERT_GT(p.dot(p) / p.dot(base.A * p), alpha_f) << "the CG step stays feasible: no expansion";
  const la::Vector x_half = -alpha_f * p;
  la::Vector phi = -base.b - alpha_f * (base.A * p);
  const double normal_i = x_half[blocking] / std::hypot(x_half[blocking], x_half[blocking + 1]);
  const double normal_j = x_half[blocking + 1] / std::hypot(x_half[blocking], x_half[blocking + 1]);
  const double normal_part = normal_i * phi[blocking] + normal_j * phi[blocking + 1];
  phi[blocking] -= normal_part * normal_i; // tangential on the disc it reached
  phi[blocking + 1] -= normal_part * normal_j;
  const la::Vector expected = projected(set, x_half - alpha_bar * phi);

  const test::Trace trace = traced_mpgp(base.A, base.b, set, {.max_iterations = 1, .alpha_bar = alpha_bar});
  ASSERT_EQ(trace.iterates.size(), 2u);
  EXPECT_EQ(trace.iterates[1].step, qp::MprgpStep::expansion);
  EXPECT_LE((trace.x - expected).norm(), 1e-13 * expected.norm());
  EXPECT_NEAR(std::hypot(trace.x[blocking], trace.x[blocking + 1]), set.discs[blocking / 2].radius, 1e-14);
}

// Reference: the projection's variational inequality (z - P z)'(w - P z) <= 0 for every w in
// Omega, which characterizes P_Omega for a closed convex set; checked at random z and w, and
// P z feasible, P(P z) = P z.
TEST(Mpgp, ProjectionSatisfiesTheVariationalInequality)
{
  const DiscQp qp = random_disc_qp(40, 7);
  std::mt19937 generator(11);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial)
  {
    la::Vector z(40), w(40);
    for (la::Index i = 0; i < 40; ++i)
    {
      z[i] = 3.0 * normal(generator);
      w[i] = 3.0 * normal(generator);
    }
    la::Vector pz = z;
    qp::project(qp.set, pz);
    w = projected(qp.set, w);
    ASSERT_TRUE(qp::is_feasible(qp.set, pz));
    EXPECT_LE((z - pz).dot(w - pz), 1e-12 * (1.0 + z.squaredNorm())) << "trial " << trial;
    la::Vector again = pz;
    qp::project(qp.set, again);
    EXPECT_LE((again - pz).norm(), 1e-15 * (1.0 + pz.norm()));
  }
}

// Reference: the bitwise claim of qp/mpgp.hpp: without discs every per-component operation and
// every reduction of MPGP is MPRGP's with the standard expansion, so on box QPs the iterates,
// x and report are those of Mprgp::solve(b, l, u, x) exactly, with and without Jacobi.
TEST(Mpgp, WithoutDiscsIteratesEqualMprgpBitwise)
{
  int proportioning = 0;
  int expansions = 0;
  for (const bool preconditioned : {false, true})
    for (const int n : {5, 25, 60})
      for (const unsigned seed : {1u, 2u, 3u, 4u})
      {
        SCOPED_TRACE(std::string(preconditioned ? "jacobi, " : "") + "n = " + std::to_string(n) +
                     ", seed = " + std::to_string(seed));
        const test::BoxQp qp = test::random_box_qp(n, seed + 300, 1e3);
        const test::JacobiOperator jacobi(qp.A);
        const la::LinearOperator* M = preconditioned ? &jacobi : nullptr;
        test::Trace mprgp;
        test::CountingOperator A(qp.A);
        qp::Mprgp solver(A,
                         {.rtol = 1e-10,
                          .expansion = qp::MprgpExpansion::standard,
                          .monitor = [&](const qp::MprgpIterate& it) { mprgp.iterates.push_back(it); },
                          .preconditioner = M});
        mprgp.x = la::Vector::Zero(n);
        mprgp.report = solver.solve(qp.b, qp.lower, qp.upper, mprgp.x);
        ASSERT_TRUE(mprgp.report.converged) << mprgp.report.reason;
        const test::Trace mpgp =
            traced_mpgp(qp.A, qp.b, {qp.lower, qp.upper, {}}, {.rtol = 1e-10, .preconditioner = M});
        test::expect_identical(mprgp, mpgp);
        proportioning += mprgp.report.proportioning_steps;
        expansions += mprgp.report.expansion_steps;
      }
  EXPECT_GT(proportioning, 0);
  EXPECT_GT(expansions, 0);
}

// Reference: STYLE.md, Errors: invalid sets are input, rejected by FETICON_CHECK with one line
// naming the component or disc, before x is touched.
TEST(Mpgp, InvalidConstraintsAreRejectedNamingTheComponent)
{
  const la::Matrix identity = la::Matrix::Identity(6, 6);
  test::CountingOperator A(identity);
  qp::Mpgp mpgp(A, {});
  const la::Vector b = la::Vector::Ones(6);
  const qp::SeparableConstraints valid{
      la::Vector::Constant(6, -infinity), la::Vector::Constant(6, infinity), {{0, 1, 1.0}, {2, 3, 0.5}}};
  const auto expect_rejected = [&](const qp::SeparableConstraints& set, const std::string& words) {
    la::Vector x = la::Vector::Constant(6, 7.0);
    try
    {
      mpgp.solve(b, set, x);
      ADD_FAILURE() << "accepted; expected a message with '" << words << "'";
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find(words), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_EQ(x, la::Vector::Constant(6, 7.0)) << "x changed by a rejected solve";
  };
  qp::SeparableConstraints set = valid;
  set.discs[1].j = 6;
  expect_rejected(set, "names component 6, outside [0, 6)");
  set = valid;
  set.discs[1].i = 1;
  expect_rejected(set, "component 1 is in disc 0 and in disc 1");
  set = valid;
  set.lower[3] = 0.0;
  expect_rejected(set, "component 3 of disc 1 has the bounds [0, inf]");
  set = valid;
  set.discs[0].radius = -1.0;
  expect_rejected(set, "disc 0 (components 0, 1) has radius -1");
  set = valid;
  set.discs[0].radius = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(set, "disc 0 (components 0, 1) has radius nan");
  set = valid;
  set.discs[0].j = 0;
  expect_rejected(set, "disc 0 names component 0 twice");
  set = valid;
  set.upper[5] = -1.0;
  set.lower[5] = 0.0;
  expect_rejected(set, "empty box at component 5");
}
