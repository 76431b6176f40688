/// SMALBE-M on hand-built QPs with bound and equality constraints:
///   min 1/2 x'Ax - b'x  s.t.  x >= l (or l <= x <= u),  C x = 0   (C with orthonormal rows),
/// SMALBE-M augments A to H = A + rho C'C itself. The reference is an independent solve: the penalized
/// bound QP (A + K C'C, K = 1e6 ||A||) by the dense active-set method of reference_qp.hpp
/// finds the active bounds, then the KKT system of that face (bounds as equalities) is solved
/// by a dense LU; the test checks that the reference's bound multipliers have the right sign
/// and its x is feasible, which certifies it as the minimizer.

#include "qp/smalbe.hpp"
#include "qp_test_problems.hpp"
#include "reference_qp.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <vector>

namespace feticon::qp
{
namespace
{
class DenseEquality : public EqualityOperator
{
public:
  explicit DenseEquality(const la::Matrix& C) : _C(C) {}
  la::Vector apply(const la::Vector& x) const override { return _C * x; }
  la::Vector apply_transpose(const la::Vector& y) const override { return _C.transpose() * y; }

private:
  const la::Matrix& _C;
};

struct EqualityQp
{
  la::Matrix A, C;
  la::Vector b, lower;
};

/// n unknowns, m orthonormal equality rows; bounds on about 80 % of the components, placed
/// below a point of Ker C (so the feasible set is not empty) and above the unconstrained
/// minimizer in places (so some bounds are active).
EqualityQp make_qp(int n, int m, unsigned seed)
{
  const test::BoundQp bound = test::random_bound_qp(n, seed, 100.0, 0.2);
  std::mt19937 generator(seed + 1);
  std::normal_distribution<double> normal;
  EqualityQp qp{bound.A, test::random_orthogonal(n, generator).topRows(m), bound.b, bound.lower};
  la::Vector feasible(n);
  for (int i = 0; i < n; ++i)
    feasible[i] = normal(generator);
  feasible -= qp.C.transpose() * (qp.C * feasible);
  for (int i = 0; i < n; ++i)
    if (std::isfinite(qp.lower[i]))
      qp.lower[i] = std::min(qp.lower[i], feasible[i]);
  return qp;
}

struct Reference
{
  la::Vector x;
  la::Vector omega; ///< multiplier of C x = 0 (A x - b + C' omega = bound multipliers)
  int active_bounds = 0;
};

/// A box QP (random_box_qp) with m orthonormal equality rows, its box widened to hold a point
/// of Ker C, and its solution by the same independent route as reference_solve: the penalized
/// box QP (reference_box_qp) finds the components at either bound, the KKT system of that face
/// gives x and omega, certified by feasibility and the signs of the bound multipliers.
struct BoxEqualityQp
{
  la::Matrix A, C;
  la::Vector b, lower, upper;
};

BoxEqualityQp make_box_qp(int n, int m, unsigned seed)
{
  const test::BoxQp box = test::random_box_qp(n, seed);
  std::mt19937 generator(seed + 3);
  std::normal_distribution<double> normal;
  BoxEqualityQp qp{box.A, test::random_orthogonal(n, generator).topRows(m), box.b, box.lower, box.upper};
  la::Vector feasible(n);
  for (int i = 0; i < n; ++i)
    feasible[i] = normal(generator);
  feasible -= qp.C.transpose() * (qp.C * feasible);
  qp.lower = qp.lower.cwiseMin(feasible);
  qp.upper = qp.upper.cwiseMax(feasible);
  return qp;
}

struct BoxReference
{
  la::Vector x, omega;
  int at_lower = 0, at_upper = 0;
};

BoxReference reference_box_solve(const BoxEqualityQp& qp)
{
  const la::Index n = qp.b.size(), m = qp.C.rows();
  const double K = 1e6 * qp.A.norm();
  const la::Vector penalized = test::reference_box_qp(qp.A + K * qp.C.transpose() * qp.C, qp.b, qp.lower, qp.upper);
  std::vector<std::pair<la::Index, double>> active; // component and its bound
  BoxReference out;
  for (la::Index i = 0; i < n; ++i)
    if (penalized[i] <= qp.lower[i] + 1e-9 * (1 + std::abs(qp.lower[i])))
    {
      active.emplace_back(i, qp.lower[i]);
      ++out.at_lower;
    }
    else if (penalized[i] >= qp.upper[i] - 1e-9 * (1 + std::abs(qp.upper[i])))
    {
      active.emplace_back(i, qp.upper[i]);
      ++out.at_upper;
    }
  const auto a = static_cast<la::Index>(active.size());
  la::Matrix kkt = la::Matrix::Zero(n + m + a, n + m + a);
  la::Vector rhs = la::Vector::Zero(n + m + a);
  kkt.topLeftCorner(n, n) = qp.A;
  kkt.block(0, n, n, m) = qp.C.transpose();
  kkt.block(n, 0, m, n) = qp.C;
  rhs.head(n) = qp.b;
  for (la::Index r = 0; r < a; ++r)
  {
    kkt(active[r].first, n + m + r) = kkt(n + m + r, active[r].first) = 1.0;
    rhs[n + m + r] = active[r].second;
  }
  const la::Vector solution = kkt.partialPivLu().solve(rhs);
  out.x = solution.head(n);
  out.omega = solution.segment(n, m);
  EXPECT_LT((qp.C * out.x).norm(), 1e-10 * (1 + out.x.norm()));
  for (la::Index i = 0; i < n; ++i)
  {
    EXPECT_GE(out.x[i], qp.lower[i] - 1e-10);
    EXPECT_LE(out.x[i], qp.upper[i] + 1e-10);
  }
  // A x - b + C' omega = nu: nu >= 0 at a lower bound, <= 0 at an upper one (a fixed
  // component, l = u, may have either sign).
  for (la::Index r = 0; r < a; ++r)
  {
    const la::Index i = active[r].first;
    if (qp.lower[i] == qp.upper[i])
      continue;
    const double nu = -solution[n + m + r];
    if (active[r].second == qp.lower[i])
      EXPECT_GE(nu, -1e-10) << "lower bound " << i << " pulls the wrong way";
    else
      EXPECT_LE(nu, 1e-10) << "upper bound " << i << " pulls the wrong way";
  }
  return out;
}

Reference reference_solve(const EqualityQp& qp)
{
  const la::Vector no_upper = la::Vector::Constant(qp.b.size(), std::numeric_limits<double>::infinity());
  const BoxReference box = reference_box_solve({qp.A, qp.C, qp.b, qp.lower, no_upper});
  return {box.x, box.omega, box.at_lower};
}

/// The QP and its operators; rho = ||A|| (eigenvalues 1..100), as rho ~ ||PFP|| in FETI, and
/// H = A + rho C'C, which SMALBE-M works with.
struct Augmented
{
  explicit Augmented(EqualityQp problem)
      : qp(std::move(problem)), H(qp.A + rho * qp.C.transpose() * qp.C), Aop(qp.A), C(qp.C)
  {
  }
  static constexpr double rho = 100.0;
  EqualityQp qp;
  la::Matrix H;
  test::CountingOperator Aop;
  DenseEquality C;
};

/// The caller's own measure of Cx in the tests of SmalbeOptions::equality_error: ||W Cx||,
/// W = diag(1..4), as FETI weighs G mu by the subdomains' net-force weights.
double weighted_equality_error(const la::Vector& Cx)
{
  return Cx.cwiseProduct(la::Vector::LinSpaced(Cx.size(), 1.0, static_cast<double>(Cx.size()))).norm();
}

SmalbeOptions options(double rho)
{
  SmalbeOptions o;
  o.rtol = 1e-10;
  o.rho = rho;
  o.rho_growth = 1; // fixed rho: the updates below are checked against ALGORITHMS.md section 1
  return o;
}

TEST(Smalbe, MatchesAnIndependentSolveOfBoundAndEqualityConstraints)
{
  for (const unsigned seed : {1u, 2u, 3u})
  {
    const Augmented p(make_qp(24, 4, seed));
    const EqualityQp& qp = p.qp;
    const Reference reference = reference_solve(qp);
    ASSERT_GT(reference.active_bounds, 0) << "the test QP should have active bounds";
    ASSERT_GT(reference.omega.norm(), 0.1) << "and a multiplier of C x = 0";
    Smalbe smalbe(p.Aop, p.C, options(p.rho));
    la::Vector x = la::Vector::Zero(24);
    const SmalbeReport r = smalbe.solve(qp.b, {qp.lower, {}, {}}, x);
    ASSERT_TRUE(r.converged) << r.reason;
    EXPECT_LT((x - reference.x).norm(), 1e-7 * reference.x.norm()) << "seed " << seed;
    EXPECT_LT((r.omega - reference.omega).norm(), 1e-6 * reference.omega.norm()) << "seed " << seed;
  }
}

TEST(Smalbe, MatchesAnIndependentSolveOfBoxAndEqualityConstraints)
{
  for (const unsigned seed : {1u, 2u, 3u})
  {
    const BoxEqualityQp qp = make_box_qp(24, 4, seed);
    const BoxReference reference = reference_box_solve(qp);
    ASSERT_GT(reference.at_lower, 0) << "the test QP should have components at lower bounds";
    ASSERT_GT(reference.at_upper, 0) << "and at upper bounds";
    const double rho = 100.0;
    test::CountingOperator A(qp.A);
    DenseEquality C(qp.C);
    Smalbe smalbe(A, C, options(rho));
    la::Vector x = la::Vector::Zero(24);
    const SmalbeReport r = smalbe.solve(qp.b, {qp.lower, qp.upper, {}}, x);
    ASSERT_TRUE(r.converged) << r.reason;
    EXPECT_TRUE((x.array() >= qp.lower.array()).all() && (x.array() <= qp.upper.array()).all());
    EXPECT_LT((x - reference.x).norm(), 1e-7 * reference.x.norm()) << "seed " << seed;
    EXPECT_LT((r.omega - reference.omega).norm(), 1e-6 * reference.omega.norm()) << "seed " << seed;
  }
}

// SmalbeOptions::inner_solver: SMALBE-M solves its inner QPs with the solver the caller
// builds, one for each augmented Hessian (at the start and after every rho update). The
// reference is the default inner MPRGP: wrapping it must change nothing, bitwise.
TEST(Smalbe, TakesTheCallersInnerSolver)
{
  class CountedMprgp : public Mprgp
  {
  public:
    CountedMprgp(const la::LinearOperator& H, const MprgpOptions& options, int& solves)
        : Mprgp(H, options), _solves(solves)
    {
    }
    QpReport solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x, la::Vector* gradient) override
    {
      ++_solves;
      return Mprgp::solve(b, set, x, gradient);
    }

  private:
    int& _solves;
  };
  const Augmented p(make_qp(24, 4, 3));
  SmalbeOptions o = options(p.rho);
  o.rho = 1; // small enough that the stall test raises rho
  o.rho_growth = 10;
  la::Vector x_default = la::Vector::Zero(24);
  const SmalbeReport r_default = Smalbe(p.Aop, p.C, o).solve(p.qp.b, {p.qp.lower, {}, {}}, x_default);
  int built = 0, solves = 0;
  o.inner_solver = [&](const la::LinearOperator& H, const MprgpOptions& inner) {
    ++built;
    return std::make_unique<CountedMprgp>(H, inner, solves);
  };
  la::Vector x = la::Vector::Zero(24);
  const SmalbeReport r = Smalbe(p.Aop, p.C, o).solve(p.qp.b, {p.qp.lower, {}, {}}, x);
  ASSERT_TRUE(r.converged) << r.reason;
  ASSERT_GT(r.rho_updates, 0) << "the run should raise rho, so that more than one inner solver is built";
  EXPECT_EQ(built, 1 + r.rho_updates);
  EXPECT_EQ(solves, r.outer_iterations);
  EXPECT_EQ(x, x_default);
  EXPECT_EQ(r.iterations, r_default.iterations);
  EXPECT_EQ(r.rho_updates, r_default.rho_updates);
}

// The rho update stays within [rho_growth, rho_growth_max] a step (smalbe.hpp's rule): from
// rho = 1, after u updates rho lies in [3^u, 5^u] for the factors 3 and 5. Reference for the
// answer: the independent solve (reference_solve), as above.
TEST(Smalbe, RaisesRhoWithinTheLeastAndLargestGrowth)
{
  const Augmented p(make_qp(24, 4, 3));
  const Reference reference = reference_solve(p.qp);
  SmalbeOptions o = options(p.rho);
  o.rho = 1;
  o.rho_growth = 3;
  o.rho_growth_max = 5;
  la::Vector x = la::Vector::Zero(24);
  const SmalbeReport r = Smalbe(p.Aop, p.C, o).solve(p.qp.b, {p.qp.lower, {}, {}}, x);
  ASSERT_TRUE(r.converged) << r.reason;
  ASSERT_GT(r.rho_updates, 0) << "the run should raise rho";
  EXPECT_GE(r.final_rho, std::pow(3.0, r.rho_updates) * (1 - 1e-12));
  EXPECT_LE(r.final_rho, std::pow(5.0, r.rho_updates) * (1 + 1e-12));
  EXPECT_LT((x - reference.x).norm(), 1e-7 * reference.x.norm());
}

// The caller's own feasibility measure (SmalbeOptions::equality_error): with a loose rtol the
// ||Cx|| <= rtol ||b|| test passes with ||Cx|| far above a tolerance the caller states in its
// own units (here ||W Cx||, W = diag(1..m), as FETI weighs G mu by the subdomains' net-force
// weights); with equality_error set, SMALBE-M goes on until that holds too, and the answer
// moves towards the independent solve's.
TEST(Smalbe, MeetsTheCallersEqualityToleranceBeyondRtol)
{
  const Augmented p(make_qp(24, 4, 2));
  const Reference reference = reference_solve(p.qp);
  const auto weighted = weighted_equality_error;
  SmalbeOptions loose = options(p.rho);
  loose.rtol = 1e-3;
  la::Vector x_loose = la::Vector::Zero(24);
  const SmalbeReport r_loose = Smalbe(p.Aop, p.C, loose).solve(p.qp.b, {p.qp.lower, {}, {}}, x_loose);
  ASSERT_TRUE(r_loose.converged) << r_loose.reason;
  const double tolerance = 1e-3 * weighted(p.qp.C * x_loose);
  ASSERT_GT(tolerance, 0) << "the loose solve should leave Cx != 0, or the test shows nothing";

  SmalbeOptions strict = loose;
  strict.equality_error = weighted;
  strict.equality_tolerance = tolerance;
  la::Vector x = la::Vector::Zero(24);
  const SmalbeReport r = Smalbe(p.Aop, p.C, strict).solve(p.qp.b, {p.qp.lower, {}, {}}, x);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_LE(weighted(p.qp.C * x), tolerance);
  EXPECT_GT(r.outer_iterations, r_loose.outer_iterations);
  EXPECT_LT((x - reference.x).norm(), (x_loose - reference.x).norm());
}

// The feasibility correction on the face (SmalbeOptions::feasibility_correction): with the
// caller's equality tolerance far below rtol ||b|| (as FETI's force-unit test), the outer
// iterations after the gradient test holds only reduce Cx; the correction removes it within
// the face in one step. Reference: the independent solve; the corrected solve must be as close
// to it as the uncorrected one (both stop at the same rtol), feasible for the bounds, meet the
// caller's tolerance, and take fewer outer iterations.
TEST(Smalbe, FeasibilityCorrectionOnTheFaceEndsTheSolveEarlier)
{
  const Augmented p(make_qp(24, 4, 2));
  const Reference reference = reference_solve(p.qp);
  const auto weighted = weighted_equality_error;
  SmalbeOptions base = options(p.rho);
  base.rtol = 1e-6;
  base.equality_error = weighted;
  base.equality_tolerance = 1e-12 * p.qp.b.norm();
  SmalbeOptions uncorrected = base;
  uncorrected.feasibility_correction = false;

  la::Vector x_plain = la::Vector::Zero(24);
  const SmalbeReport r_plain = Smalbe(p.Aop, p.C, uncorrected).solve(p.qp.b, {p.qp.lower, {}, {}}, x_plain);
  ASSERT_TRUE(r_plain.converged) << r_plain.reason;
  EXPECT_EQ(r_plain.feasibility_corrections, 0);
  la::Vector x = la::Vector::Zero(24);
  const SmalbeReport r = Smalbe(p.Aop, p.C, base).solve(p.qp.b, {p.qp.lower, {}, {}}, x);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(r.feasibility_corrections, 1);
  EXPECT_LT(r.outer_iterations, r_plain.outer_iterations);
  EXPECT_LE(weighted(p.qp.C * x), base.equality_tolerance);
  EXPECT_TRUE(((x - p.qp.lower).array() >= 0).all());
  const double error = (x - reference.x).norm() / reference.x.norm();
  EXPECT_LT(error, 1e-5);
  EXPECT_LT(error, 10 * std::max((x_plain - reference.x).norm() / reference.x.norm(), 1e-7));
}

TEST(Smalbe, UpdatesOmegaAndMAsInAlgorithmsSection1)
{
  const Augmented p(make_qp(24, 4, 7));
  const EqualityQp& qp = p.qp;
  const double rho = p.rho;
  struct Record
  {
    la::Vector x, omega;
    double M, lagrangian;
  };
  std::vector<Record> records;
  SmalbeOptions o = options(rho);
  o.M0 = 1e3; // loose first inner solves (M ~ 10 ||H||): M has to come down
  o.monitor = [&](const SmalbeIterate& it) { records.push_back({*it.x, *it.omega, it.M, it.lagrangian}); };
  Smalbe smalbe(p.Aop, p.C, o);
  la::Vector x = la::Vector::Zero(24);
  const SmalbeReport r = smalbe.solve(qp.b, {qp.lower, {}, {}}, x);
  ASSERT_TRUE(r.converged) << r.reason;
  ASSERT_GE(records.size(), 4u);
  int decreases = 0;
  for (size_t k = 0; k < records.size(); ++k)
  {
    const Record& it = records[k];
    const la::Vector Cx = qp.C * it.x;
    // L(x, omega) computed here, not by the solver's recursive cost.
    const double L = 0.5 * it.x.dot(p.H * it.x) - qp.b.dot(it.x) + it.omega.dot(Cx);
    EXPECT_NEAR(it.lagrangian, L, 1e-9 * (1 + std::abs(L))) << "outer " << k;
    if (k + 1 == records.size())
      break;
    const Record& next = records[k + 1];
    // omega <- omega + rho C x
    EXPECT_LT((next.omega - (it.omega + rho * Cx)).norm(), 1e-12 * (1 + next.omega.norm())) << "outer " << k;
    // M <- M / beta when L did not grow by rho/2 ||Cx||^2 (k > 0), else unchanged.
    // (Ties within round-off of L, whose solver value is a recursive cost, may go either way.)
    const double wanted = k > 0 ? records[k - 1].lagrangian + 0.5 * rho * Cx.squaredNorm() : 0.0;
    if (k > 0 && std::abs(L - wanted) <= 1e-9 * (1 + std::abs(L)))
      continue;
    const bool decrease = k > 0 && L < wanted;
    EXPECT_DOUBLE_EQ(next.M, decrease ? it.M / o.beta : it.M) << "outer " << k;
    decreases += decrease;
  }
  EXPECT_GT(decreases, 0) << "the run should exercise the M update";
  EXPECT_DOUBLE_EQ(r.final_M, records.back().M);
}

TEST(Smalbe, StartsFromTheMultiplierMAndRhoOfAnEarlierSolve)
{
  const Augmented p(make_qp(24, 4, 11));
  const EqualityQp& qp = p.qp;
  const double rho = p.rho;
  Smalbe smalbe(p.Aop, p.C, options(rho));
  la::Vector x = la::Vector::Zero(24);
  const SmalbeReport first = smalbe.solve(qp.b, {qp.lower, {}, {}}, x);
  ASSERT_TRUE(first.converged) << first.reason;
  ASSERT_GT(first.outer_iterations, 3);

  // Restarted at its own solution, the solve stops at once.
  const QpState same{{}, first.omega, first.final_M, first.final_rho};
  la::Vector again = x;
  const SmalbeReport restarted = smalbe.solve(qp.b, {qp.lower, {}, {}}, again, &same);
  EXPECT_TRUE(restarted.converged);
  EXPECT_EQ(restarted.outer_iterations, 1);
  EXPECT_LE(restarted.iterations, 1);

  // A nearby problem (b perturbed by 1 %), as the next outer iteration of a Newton loop:
  // starting from the earlier multiplier needs fewer outer iterations and steps than from
  // omega = 0, both from the earlier x, and both reach the same answer.
  std::mt19937 generator(5);
  std::normal_distribution<double> normal;
  la::Vector b = qp.b;
  for (la::Index i = 0; i < b.size(); ++i)
    b[i] += 0.01 * qp.b.norm() / std::sqrt(24.0) * normal(generator);
  la::Vector warm_x = x, cold_x = x;
  const SmalbeReport warm = smalbe.solve(b, {qp.lower, {}, {}}, warm_x, &same);
  const SmalbeReport cold = smalbe.solve(b, {qp.lower, {}, {}}, cold_x);
  ASSERT_TRUE(warm.converged && cold.converged);
  EXPECT_LT(warm.outer_iterations, cold.outer_iterations);
  EXPECT_LT(warm.iterations, cold.iterations);
  EXPECT_LT((warm_x - cold_x).norm(), 1e-7 * cold_x.norm());

  // A raised rho is taken over: H is augmented by the difference.
  const QpState raised{{}, first.omega, first.final_M, 10 * rho};
  la::Vector raised_x = x;
  const SmalbeReport with_raised = smalbe.solve(b, {qp.lower, {}, {}}, raised_x, &raised);
  ASSERT_TRUE(with_raised.converged) << with_raised.reason;
  EXPECT_DOUBLE_EQ(with_raised.final_rho, 10 * rho);
  EXPECT_LT((raised_x - cold_x).norm(), 1e-7 * cold_x.norm());
}
} // namespace
} // namespace feticon::qp
