#include "qp/mpgp.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/timer.hpp"
#include "la/vector_space.hpp"
#include "qp/gradient_split.hpp"
#include "qp/ritz_estimate.hpp"
#include "qp/solve_stop.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <utility>

namespace feticon::qp
{
namespace
{
using la::Index;
using la::Vector;

/// The bound a step along -p reaches at component i (l_i if p_i > 0, u_i if p_i < 0); infinite
/// for a disc component.
double bound_reached(const SeparableConstraints& set, Index i, double p_i)
{
  return p_i > 0.0 ? set.lower[i] : set.upper[i];
}

/// Largest step along -p that stays in Omega over all ranks (active discs skipped unless
/// `include_active`: max_disc_step), and the local component that limits it (-1 if none does
/// here).
double max_feasible_step(const la::VectorSpace& space, const SeparableConstraints& set, const Vector& x,
                         const Vector& p, bool include_active, Index& blocking)
{
  Index disc_blocking = -1;
  double alpha = max_bound_step(set, x, p, blocking);
  const double disc_alpha = max_disc_step(set, x, p, include_active, disc_blocking);
  if (disc_alpha < alpha)
  {
    alpha = disc_alpha;
    blocking = disc_blocking;
  }
  const auto [global_alpha, local_blocking] = space.min_location(alpha, blocking);
  blocking = local_blocking;
  return global_alpha;
}

/// Whether p moves an active disc along its circle on some rank.
bool moves_along_circles(const la::VectorSpace& space, const SeparableConstraints& set, const Vector& x,
                         const Vector& p)
{
  return space.max(moves_along_a_circle(set, x, p) ? 1.0 : 0.0) > 0.0;
}

void check_input(const la::LinearOperator& A, const Vector& b, const SeparableConstraints& set, const Vector& x)
{
  const Index n = A.size();
  FETICON_CHECK(b.size() == n, "Mpgp::solve: b has size " << b.size() << " but the operator has size " << n);
  FETICON_CHECK(x.size() == n,
                "Mpgp::solve: the initial guess has size " << x.size() << " but the operator has size " << n);
  for (Index i = 0; i < n; ++i)
  {
    FETICON_CHECK(std::isfinite(b[i]),
                  "Mpgp::solve: b[" << i << "] = " << b[i] << " is not finite; check the right-hand side");
    FETICON_CHECK(std::isfinite(x[i]), "Mpgp::solve: initial guess x[" << i << "] = " << x[i] << " is not finite");
  }
  check_separable_constraints(set, n, "Mpgp::solve");
}
} // namespace

Mpgp::Mpgp(const la::LinearOperator& A, MpgpOptions options)
    : _A(A), _options(std::move(options)), _alpha_bar(_options.alpha_bar)
{
  check_solver_options("Mpgp", _options.rtol, _options.gamma, _options.max_iterations, _options.alpha_bar,
                       _options.power_iterations, _options.gradient_refresh);
}

/// The iterate of one solve and its work vectors: x in Omega, g = Ax - b, the direction p and
/// q = A p, and the report counting the steps.
struct Mpgp::SolveState
{
  SolveState(const la::VectorSpace& space, const Vector& b, const SeparableConstraints& set, Vector& x)
      : space(space), b(b), set(set), x(x)
  {
  }

  /// phi, beta and phi~ at x, and their sums.
  GradientSplit split(double alpha_bar)
  {
    free_gradient(set, x, g, phi);
    chopped_gradient(set, x, g, beta);
    reduced_free_gradient(set, x, phi, alpha_bar, reduced);
    const auto sums = la::reduce_sum<4>(space, [&](Index i, double* sum) {
      sum[0] += phi[i] * phi[i];
      sum[1] += beta[i] * beta[i];
      sum[2] += reduced[i] * phi[i];
      sum[3] += x[i] * (g[i] - b[i]);
    });
    return {sums[0], sums[1], sums[2], 0.5 * sums[3]};
  }

  const la::VectorSpace& space;
  const Vector& b;
  const SeparableConstraints& set;
  Vector& x;
  Vector g, p, q, phi, beta, reduced, y, z, x_old, g_old, curvature;
  QpReport report;
  RitzEstimate ritz;
  MprgpStep step = MprgpStep::start;
};

QpReport Mpgp::solve(const Vector& b, const SeparableConstraints& set, Vector& x, Vector* gradient)
{
  const auto start_time = std::chrono::steady_clock::now();
  check_input(_A, b, set, x);
  std::unique_ptr<la::SerialSpace> serial;
  const la::VectorSpace& space = _A.space() ? *_A.space() : *(serial = std::make_unique<la::SerialSpace>(_A.size()));
  SolveState s(space, b, set, x);
  auto finish = [&](bool converged, std::string reason) {
    if (gradient)
      *gradient = s.g;
    s.report.ritz = s.ritz.longest_run();
    s.report.converged = converged;
    s.report.reason = std::move(reason);
    s.report.seconds = seconds_since(start_time);
    return s.report;
  };
  if (space.max(static_cast<double>(_A.size())) == 0.0)
    return finish(true, "empty problem");
  if (_alpha_bar == 0.0)
    if (std::optional<std::string> failure = estimate_alpha_bar(_A, _options.power_iterations, s.report, _alpha_bar))
      return finish(false, std::move(*failure));

  const Vector x_given = gradient ? x : Vector();
  project(set, x);
  if (given_gradient_holds(space, gradient, x_given, x))
    s.g = *gradient;
  else
    refresh_gradient(s);
  const double b_norm = la::norm(space, b);
  const double tolerance = _options.rtol * (b_norm > 0.0 ? b_norm : 1.0);
  direction(s, s.p);
  for (;;)
  {
    const GradientSplit split = s.split(_alpha_bar);
    const double gp_norm = std::sqrt(split.free_norm2 + split.chopped_norm2);
    s.report.projected_gradient_norm = gp_norm;
    s.report.cost = split.cost;
    const MprgpIterate iterate{
        s.report.iterations, s.step, gp_norm, std::sqrt(split.free_norm2), std::sqrt(split.chopped_norm2), split.cost};
    if (_options.monitor)
      _options.monitor(iterate);
    if (log::enabled(log::Level::iterations))
      log_iterate("mpgp", iterate, tolerance, static_cast<bool>(_options.stop));
    if (std::optional<SolveStop> stop =
            stopping_test(_options.stop, _options.max_iterations, s.report, x, s.g, gp_norm, tolerance, b_norm))
      return finish(stop->converged, std::move(stop->reason));

    const double gamma2 = _options.gamma * _options.gamma;
    const std::optional<std::string> failure = split.chopped_norm2 <= gamma2 * split.reduced_free_dot_free
        ? cg_or_expansion_step(s, split.cost)
        : proportioning_step(s);
    if (failure)
      return finish(false, *failure);
    ++s.report.iterations;
    if (s.report.iterations % _options.gradient_refresh == 0)
      refresh_gradient(s);
  }
}

void Mpgp::refresh_gradient(SolveState& s) const
{
  _A.apply(s.x, s.g);
  s.g -= s.b;
  ++s.report.hessian_multiplications;
}

void Mpgp::direction(SolveState& s, Vector& out) const
{
  free_gradient(s.set, s.x, s.g, out);
  if (!_options.preconditioner)
    return;
  // z = D_F M D_F phi with D_F the orthogonal projector onto the face; out is in the face.
  _options.preconditioner->apply(out, s.z);
  project_onto_face(s.set, s.x, s.z);
  out.swap(s.z);
}

std::optional<std::string> Mpgp::cg_or_expansion_step(SolveState& s, double cost)
{
  // q = (A + K) p with K the curvature nu/r of the active discs (disc_curvature): along a
  // circle f has that curvature too. K p = 0 unless p moves an active disc.
  _A.apply(s.p, s.q);
  ++s.report.hessian_multiplications;
  if (!s.set.discs.empty())
  {
    disc_curvature(s.set, s.x, s.g, s.curvature);
    s.q += s.curvature.cwiseProduct(s.p);
  }
  const Vector& p = s.p;
  const Vector& q = s.q;
  const Vector& g = s.g;
  const auto [pq, gp] = la::reduce_sum<2>(s.space, [&](Index i, double* sum) {
    sum[0] += p[i] * q[i];
    sum[1] += g[i] * p[i];
  });
  if (!(pq > 0.0))
    return "operator is not positive definite on the search direction: p'Ap = " + format_number(pq) +
        " <= 0 at iteration " + std::to_string(s.report.iterations);
  const double alpha_cg = gp / pq;
  Index blocking = -1;
  const double alpha_f = max_feasible_step(s.space, s.set, s.x, s.p, false, blocking);
  const bool on_circles = moves_along_circles(s.space, s.set, s.x, s.p);
  // A NaN alpha_cg takes the CG branch and is caught by the finiteness test.
  if (!(alpha_cg > alpha_f))
    cg_step(s, alpha_cg, pq, on_circles, cost);
  else
    expansion_step(s, alpha_f, blocking, on_circles, cost);
  return std::nullopt;
}

void Mpgp::cg_step(SolveState& s, double alpha_cg, double pq, bool on_circles, double cost)
{
  // alpha_cg <= alpha_f keeps x in Omega up to round-off, which the projection removes; on an
  // active disc the projection takes the step onto the circle, where the recursive gradient
  // no longer holds: g is recomputed and the step kept only if f did not increase.
  if (on_circles)
  {
    s.x_old = s.x;
    s.g_old = s.g;
  }
  s.x -= alpha_cg * s.p;
  project(s.set, s.x);
  if (!on_circles)
    s.g -= alpha_cg * s.q;
  else
  {
    refresh_gradient(s);
    if (quadratic_cost(s.space, s.x, s.g, s.b) > cost + 1e-12 * std::abs(cost))
    {
      s.x.swap(s.x_old);
      s.g.swap(s.g_old);
      gradient_projection_step(s, cost);
      return;
    }
  }
  direction(s, s.phi);
  const double beta = la::dot(s.space, s.phi, s.q) / pq;
  s.p = s.phi - beta * s.p;
  if (on_circles) // the old direction was tangent to the circles at the old x
    project_onto_face(s.set, s.x, s.p);
  s.ritz.cg_step(alpha_cg, -beta);
  ++s.report.cg_steps;
  s.step = MprgpStep::cg;
}

void Mpgp::expansion_step(SolveState& s, double alpha_f, Index blocking, bool on_circles, double cost)
{
  // Feasible half step x_h = P(x - alpha_f p), the blocking bound reached exactly (a blocking
  // disc ends within round-off of its circle, active by disc_tolerance); g_h = g - alpha_f q;
  // then y = P(x_h - alpha_bar phi(x_h)) and g = g_h + A (y - x_h), the arithmetic per
  // component of Mprgp's standard expansion. When p moves along circles, g_h is only the
  // model's (q = (A + K) p), and g is updated from the start: g + A (y - x).
  s.x_old = s.x;
  s.g_old = s.g;
  s.x -= alpha_f * s.p;
  project(s.set, s.x);
  if (blocking >= 0 && std::isfinite(bound_reached(s.set, blocking, s.p[blocking])))
    s.x[blocking] = bound_reached(s.set, blocking, s.p[blocking]);
  s.g -= alpha_f * s.q;
  free_gradient(s.set, s.x, s.g, s.phi);
  if (!on_circles)
  {
    s.x_old = s.x;
    s.g_old = s.g;
  }
  s.x -= _alpha_bar * s.phi;
  project(s.set, s.x);
  s.y = s.x - s.x_old;
  _A.apply(s.y, s.q);
  ++s.report.hessian_multiplications;
  s.g = s.g_old + s.q;
  // f is monotone only for alpha_bar <= 2/||A||, and the power estimate is from below; the
  // step along circles is monotone only to second order: replaced if f increased.
  if (quadratic_cost(s.space, s.x, s.g, s.b) > cost + 1e-12 * std::abs(cost))
  {
    if (on_circles)
    {
      s.x.swap(s.x_old);
      s.g.swap(s.g_old);
      gradient_projection_step(s, cost);
      return;
    }
    _alpha_bar *= 0.5;
  }
  direction(s, s.p);
  s.ritz.end_run();
  ++s.report.expansion_steps;
  s.step = MprgpStep::expansion;
}

std::optional<std::string> Mpgp::proportioning_step(SolveState& s)
{
  // beta releases bounded components from one bound and active discs inward; cut where one
  // reaches another bound or crosses its disc (f still decreases: a convex parabola along
  // beta, decreasing up to the line-search step).
  chopped_gradient(s.set, s.x, s.g, s.beta);
  _A.apply(s.beta, s.q);
  ++s.report.hessian_multiplications;
  const Vector& beta = s.beta;
  const Vector& q = s.q;
  const Vector& g = s.g;
  const auto [beta_q, g_beta] = la::reduce_sum<2>(s.space, [&](Index i, double* sum) {
    sum[0] += beta[i] * q[i];
    sum[1] += g[i] * beta[i];
  });
  if (!(beta_q > 0.0))
    return "operator is not positive definite on the search direction: beta'A beta = " + format_number(beta_q) +
        " <= 0 at iteration " + std::to_string(s.report.iterations);
  const double alpha = g_beta / beta_q;
  Index blocking = -1;
  const double alpha_f = max_feasible_step(s.space, s.set, s.x, s.beta, true, blocking);
  const bool cut = alpha > alpha_f;
  s.x -= (cut ? alpha_f : alpha) * s.beta;
  project(s.set, s.x);
  if (cut && blocking >= 0 && std::isfinite(bound_reached(s.set, blocking, s.beta[blocking])))
    s.x[blocking] = bound_reached(s.set, blocking, s.beta[blocking]);
  s.g -= (cut ? alpha_f : alpha) * s.q;
  direction(s, s.p);
  s.ritz.end_run();
  ++s.report.proportioning_steps;
  s.step = MprgpStep::proportioning;
  return std::nullopt;
}

void Mpgp::gradient_projection_step(SolveState& s, double cost)
{
  // Dostal & Kozubek's gradient projection step, monotone for alpha_bar <= 2/||A||: the
  // fallback of a step along circles that increased f.
  s.x_old = s.x;
  s.x -= _alpha_bar * s.g;
  project(s.set, s.x);
  s.y = s.x - s.x_old;
  _A.apply(s.y, s.q);
  ++s.report.hessian_multiplications;
  s.g += s.q;
  if (quadratic_cost(s.space, s.x, s.g, s.b) > cost + 1e-12 * std::abs(cost))
    _alpha_bar *= 0.5;
  direction(s, s.p);
  s.ritz.end_run();
  ++s.report.expansion_fallbacks;
  ++s.report.expansion_steps;
  s.step = MprgpStep::expansion;
}
} // namespace feticon::qp
