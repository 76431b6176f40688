#include "qp/mprgp.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/timer.hpp"
#include "qp/gradient_split.hpp"
#include "qp/ritz_estimate.hpp"
#include "qp/solve_stop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace feticon::qp
{
namespace
{
using la::Index;
using la::Vector;

using la::infinity;

/// The feasible set l <= x <= u. A null `upper` means u = +infinity everywhere; the
/// lower-bound-only solve then runs the arithmetic of the original algorithm (the vector
/// clamps to u are skipped, and every per-component test with u = +infinity reduces to it).
struct Box
{
  const Vector& lower;
  const Vector* upper;

  double upper_at(Index i) const { return upper ? (*upper)[i] : infinity; }
  /// l_i < x_i < u_i.
  bool is_free(Index i, double x_i) const { return x_i > lower[i] && x_i < upper_at(i); }
  /// x_i clamped into [l_i, u_i].
  double clamp(Index i, double x_i) const { return std::min(std::max(x_i, lower[i]), upper_at(i)); }
  /// The bound a step along -p reaches at component i: l_i if p_i > 0, u_i if p_i < 0.
  double bound_reached(Index i, double p_i) const { return p_i > 0.0 ? lower[i] : upper_at(i); }
  /// x clamped into the box.
  void project(Vector& x) const
  {
    x = x.cwiseMax(lower);
    if (upper)
      x = x.cwiseMin(*upper);
  }
  /// The chopped gradient component: min(g_i, 0) at x_i = l_i < u_i, max(g_i, 0) at
  /// x_i = u_i > l_i, 0 where x_i is free or fixed (l_i = u_i).
  double chopped(Index i, double x_i, double g_i) const
  {
    const bool above_lower = x_i > lower[i];
    const bool below_upper = x_i < upper_at(i);
    if (above_lower)
      return below_upper ? 0.0 : std::max(g_i, 0.0);
    return below_upper ? std::min(g_i, 0.0) : 0.0;
  }
};

GradientSplit split_gradient(const la::VectorSpace& space, const Vector& x, const Vector& g, const Vector& b,
                             const Box& box, double alpha_bar)
{
  const Vector& lower = box.lower;
  const auto s = la::reduce_sum<4>(space, [&](Index i, double* sum) {
    if (box.is_free(i, x[i]))
    {
      // phi~_i: with u_i = +inf the inner max is g_i, as in the lower-bound algorithm.
      const double reduced =
          std::min((x[i] - lower[i]) / alpha_bar, std::max((x[i] - box.upper_at(i)) / alpha_bar, g[i]));
      sum[0] += g[i] * g[i];
      sum[2] += reduced * g[i];
    }
    else if (const double beta = box.chopped(i, x[i], g[i]); beta != 0.0)
      sum[1] += beta * beta;
    sum[3] += x[i] * (g[i] - b[i]);
  });
  return {s[0], s[1], s[2], 0.5 * s[3]};
}

/// phi: g on the free set, 0 on the active set.
void free_gradient(const Vector& x, const Vector& g, const Box& box, Vector& phi)
{
  if (box.upper)
    phi = ((x.array() > box.lower.array()) && (x.array() < box.upper->array())).select(g, 0.0);
  else
    phi = (x.array() > box.lower.array()).select(g, 0.0);
}

/// beta: the chopped gradient (Box::chopped), 0 on the free set.
void chopped_gradient(const Vector& x, const Vector& g, const Box& box, Vector& beta)
{
  if (!box.upper)
  {
    beta = (x.array() > box.lower.array()).select(0.0, g.cwiseMin(0.0));
    return;
  }
  beta.resize(x.size());
  for (Index i = 0; i < x.size(); ++i)
    beta[i] = box.chopped(i, x[i], g[i]);
}

/// Largest step along -p that keeps l <= x - alpha p <= u, and the component that blocks it
/// (-1 if none does, or if it is on another rank).
double feasible_step(const la::VectorSpace& space, const Vector& x, const Vector& p, const Box& box, Index& blocking)
{
  const Vector& lower = box.lower;
  double alpha = infinity;
  blocking = -1;
  for (Index i = 0; i < x.size(); ++i)
  {
    double step = infinity;
    if (p[i] > 0.0 && std::isfinite(lower[i]))
      step = (x[i] - lower[i]) / p[i];
    else if (p[i] < 0.0 && box.upper && std::isfinite((*box.upper)[i]))
      step = (x[i] - (*box.upper)[i]) / p[i];
    if (step < alpha)
    {
      alpha = step;
      blocking = i;
    }
  }
  const auto [global_alpha, local_blocking] = space.min_location(alpha, blocking);
  blocking = local_blocking;
  return global_alpha;
}

void check_upper(const Vector& lower, const Vector& upper, Index n)
{
  FETICON_CHECK(upper.size() == n,
                "Mprgp::solve: the upper bound has size " << upper.size() << " but the operator has size " << n);
  for (Index i = 0; i < n; ++i)
  {
    FETICON_CHECK(!std::isnan(upper[i]) && upper[i] != -infinity,
                  "Mprgp::solve: upper bound u[" << i << "] = " << upper[i] << "; bounds must be finite or +inf");
    FETICON_CHECK(lower[i] <= upper[i],
                  "Mprgp::solve: empty box at component " << i << ": l[" << i << "] = " << lower[i] << " > u[" << i
                                                          << "] = " << upper[i] << "; bounds need l <= u");
  }
}

void check_input(const la::LinearOperator& A, const Vector& b, const Vector& lower, const Vector* upper,
                 const Vector& x)
{
  const Index n = A.size();
  FETICON_CHECK(b.size() == n, "Mprgp::solve: b has size " << b.size() << " but the operator has size " << n);
  FETICON_CHECK(lower.size() == n,
                "Mprgp::solve: the lower bound has size " << lower.size() << " but the operator has size " << n);
  FETICON_CHECK(x.size() == n,
                "Mprgp::solve: the initial guess has size " << x.size() << " but the operator has size " << n);
  for (Index i = 0; i < n; ++i)
  {
    FETICON_CHECK(std::isfinite(b[i]),
                  "Mprgp::solve: b[" << i << "] = " << b[i] << " is not finite; check the right-hand side");
    FETICON_CHECK(!std::isnan(lower[i]) && lower[i] != infinity,
                  "Mprgp::solve: lower bound l[" << i << "] = " << lower[i] << "; bounds must be finite or -inf");
    FETICON_CHECK(std::isfinite(x[i]), "Mprgp::solve: initial guess x[" << i << "] = " << x[i] << " is not finite");
  }
  if (upper)
    check_upper(lower, *upper, n);
}

} // namespace

const char* to_string(MprgpStep step)
{
  switch (step)
  {
  case MprgpStep::start:
    return "start";
  case MprgpStep::cg:
    return "cg";
  case MprgpStep::expansion:
    return "expansion";
  case MprgpStep::proportioning:
    return "proportioning";
  }
  return "unknown";
}

Mprgp::Mprgp(const la::LinearOperator& A, MprgpOptions options)
    : _A(A), _options(std::move(options)), _alpha_bar(_options.alpha_bar)
{
  check_solver_options("Mprgp", _options.rtol, _options.gamma, _options.max_iterations, _options.alpha_bar,
                       _options.power_iterations, _options.gradient_refresh);
}

MprgpExpansion expansion_from_name(const std::string& name)
{
  FETICON_CHECK(name == "std" || name == "projcg", "MPRGP expansion '" << name << "' is unknown: use std or projcg");
  return name == "std" ? MprgpExpansion::standard : MprgpExpansion::projected_cg;
}

/// The iterate of one solve and its work vectors (ALGORITHMS.md section 5): l <= x <= u, the
/// gradient g = Ax - b, the direction p and q = A p, and the report counting the steps.
struct Mprgp::SolveState
{
  SolveState(const la::VectorSpace& space, const Vector& b, const Box& box, Vector& x)
      : space(space), b(b), box(box), x(x)
  {
  }

  const la::VectorSpace& space;
  const Vector& b;
  const Box box;
  Vector& x;
  Vector g, p, q, phi, beta, y, z, x_old, g_old;
  QpReport report;
  RitzEstimate ritz;
  MprgpStep step = MprgpStep::start;
};

QpReport Mprgp::solve(const Vector& b, const Vector& lower, Vector& x) { return solve_box(b, lower, nullptr, x); }

QpReport Mprgp::solve(const Vector& b, const Vector& lower, const Vector& upper, Vector& x)
{
  return solve_box(b, lower, &upper, x);
}

QpReport Mprgp::solve(const Vector& b, const SeparableConstraints& set, Vector& x, Vector* gradient)
{
  FETICON_CHECK(set.discs.empty(),
                "Mprgp::solve: MPRGP takes bounds only, not the " << set.discs.size()
                                                                  << " discs of this QP (use MPGP)");
  return solve_box(b, set.lower, set.upper.size() > 0 ? &set.upper : nullptr, x, gradient);
}

QpReport Mprgp::solve_box(const Vector& b, const Vector& lower, const Vector* upper, Vector& x, Vector* gradient)
{
  const auto start_time = std::chrono::steady_clock::now();
  check_input(_A, b, lower, upper, x);
  std::unique_ptr<la::SerialSpace> serial;
  const la::VectorSpace& space = _A.space() ? *_A.space() : *(serial = std::make_unique<la::SerialSpace>(_A.size()));
  const Box box{lower, upper};
  SolveState s(space, b, box, x);
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
  box.project(x);
  if (given_gradient_holds(space, gradient, x_given, x))
    s.g = *gradient;
  else
    refresh_gradient(s);

  const double b_norm = la::norm(space, b);
  const double tolerance = _options.rtol * (b_norm > 0.0 ? b_norm : 1.0);
  direction(s, s.p);

  for (;;)
  {
    const GradientSplit split = split_gradient(space, x, s.g, b, box, _alpha_bar);
    const double cost = split.cost;
    const double gp_norm = std::sqrt(split.free_norm2 + split.chopped_norm2);
    s.report.projected_gradient_norm = gp_norm;
    s.report.cost = cost;
    const MprgpIterate iterate{
        s.report.iterations, s.step, gp_norm, std::sqrt(split.free_norm2), std::sqrt(split.chopped_norm2), cost};
    if (_options.monitor)
      _options.monitor(iterate);
    if (log::enabled(log::Level::iterations))
      log_iterate("mprgp", iterate, tolerance, static_cast<bool>(_options.stop));

    if (std::optional<SolveStop> stop =
            stopping_test(_options.stop, _options.max_iterations, s.report, x, s.g, gp_norm, tolerance, b_norm))
      return finish(stop->converged, std::move(stop->reason));

    const double gamma2 = _options.gamma * _options.gamma;
    const std::optional<std::string> failure = split.chopped_norm2 <= gamma2 * split.reduced_free_dot_free
        ? cg_or_expansion_step(s, cost)
        : proportioning_step(s);
    if (failure)
      return finish(false, *failure);
    ++s.report.iterations;

    if (s.report.iterations % _options.gradient_refresh == 0)
      refresh_gradient(s);
  }
}

void Mprgp::refresh_gradient(SolveState& s) const
{
  _A.apply(s.x, s.g);
  s.g -= s.b;
  ++s.report.hessian_multiplications;
}

void Mprgp::direction(SolveState& s, Vector& out) const
{
  // Search direction in the current face: the free gradient, preconditioned in the face.
  free_gradient(s.x, s.g, s.box, out);
  if (!_options.preconditioner)
    return;
  _options.preconditioner->apply(out, s.z);
  for (Index i = 0; i < s.z.size(); ++i)
    if (!s.box.is_free(i, s.x[i]))
      s.z[i] = 0.0;
  out.swap(s.z);
}

std::optional<std::string> Mprgp::cg_or_expansion_step(SolveState& s, double cost)
{
  // Proportional x: CG direction p in the current face.
  _A.apply(s.p, s.q);
  ++s.report.hessian_multiplications;
  const Vector& p = s.p;
  const Vector& q = s.q;
  const Vector& g = s.g;
  const auto [pq, gp] = la::reduce_sum<2>(s.space, [&](Index i, double* sum) {
    sum[0] += p[i] * q[i];
    sum[1] += g[i] * p[i];
  });
  if (!(pq > 0.0))
    return "operator is not positive definite on the search direction: "
           "p'Ap = " +
        format_number(pq) + " <= 0 at iteration " + std::to_string(s.report.iterations);
  const double alpha_cg = gp / pq;
  Index blocking = -1;
  const double alpha_f = feasible_step(s.space, s.x, s.p, s.box, blocking);
  // A NaN alpha_cg takes the CG branch and is caught by the finiteness test.
  if (!(alpha_cg > alpha_f))
    cg_step(s, alpha_cg, pq);
  else
    expansion_step(s, alpha_cg, alpha_f, blocking, cost);
  return std::nullopt;
}

void Mprgp::cg_step(SolveState& s, double alpha_cg, double pq) const
{
  // CG step. alpha_cg <= alpha_f keeps x feasible up to round-off, which the clamp
  // removes so that l <= x <= u holds exactly.
  s.x -= alpha_cg * s.p;
  s.box.project(s.x);
  s.g -= alpha_cg * s.q;
  direction(s, s.phi);
  const double beta = la::dot(s.space, s.phi, s.q) / pq;
  s.p = s.phi - beta * s.p;
  s.ritz.cg_step(alpha_cg, -beta); // the standard PCG coefficient is -beta
  ++s.report.cg_steps;
  s.step = MprgpStep::cg;
}

void Mprgp::expansion_step(SolveState& s, double alpha_cg, double alpha_f, Index blocking, double cost)
{
  bool done = false;
  if (_options.expansion == MprgpExpansion::projected_cg)
    done = projected_cg_expansion(s, alpha_cg, cost);
  if (!done)
    standard_expansion(s, alpha_f, blocking, cost);
  direction(s, s.p);
  s.ritz.end_run();
  ++s.report.expansion_steps;
  s.step = MprgpStep::expansion;
}

bool Mprgp::projected_cg_expansion(SolveState& s, double alpha_cg, double cost) const
{
  // P(x - alpha_cg p) with the gradient recomputed (the projection moves x off p).
  s.x_old = s.x;
  s.x = (s.x - alpha_cg * s.p).cwiseMax(s.box.lower);
  if (s.box.upper)
    s.x = s.x.cwiseMin(*s.box.upper);
  s.g_old.swap(s.g);
  _A.apply(s.x, s.g);
  s.g -= s.b;
  ++s.report.hessian_multiplications;
  const bool done = quadratic_cost(s.space, s.x, s.g, s.b) <= cost + 1e-12 * std::abs(cost);
  if (!done) // back to x and the standard step from there (q = A p still holds)
  {
    s.x.swap(s.x_old);
    s.g.swap(s.g_old);
    ++s.report.expansion_fallbacks;
  }
  return done;
}

void Mprgp::standard_expansion(SolveState& s, double alpha_f, Index blocking, double cost)
{
  // Feasible half step to the blocking bound, then the projected gradient step
  // y = P(x - alpha_bar phi) = x - alpha_bar phi~ (the identity of ALGORITHMS.md
  // section 5); the projection puts active components exactly on l. One pass over
  // the vectors instead of six (bench: on a cheap operator MPRGP is bound by its own
  // vector traffic), with the same arithmetic per component (P the clamp into [l, u]):
  //   x_h = P(x - alpha_f p) (x_h = the bound reached at the blocking component),
  //   g_h = g - alpha_f q,  phi = free part of g_h,  y = P(x_h - alpha_bar phi),
  // and the step y - x_h for the gradient update g = g_h + A (y - x_h).
  Vector& x = s.x;
  Vector& g = s.g;
  const Box& box = s.box;
  s.y.resize(x.size());
  for (Index i = 0; i < x.size(); ++i)
  {
    const double x_half = i == blocking ? box.bound_reached(i, s.p[i]) : box.clamp(i, x[i] - alpha_f * s.p[i]);
    const double g_half = g[i] - alpha_f * s.q[i];
    const double phi_i = box.is_free(i, x_half) ? g_half : 0.0;
    const double y_i = box.clamp(i, x_half - _alpha_bar * phi_i);
    s.y[i] = y_i - x_half;
    x[i] = y_i;
    g[i] = g_half;
  }
  _A.apply(s.y, s.q);
  ++s.report.hessian_multiplications;
  g += s.q;
  // f is monotone only for alpha_bar <= 2/||A||, and the power estimate of ||A|| is
  // from below; the margin ignores round-off of the cost evaluation.
  if (quadratic_cost(s.space, x, g, s.b) > cost + 1e-12 * std::abs(cost))
    _alpha_bar *= 0.5;
}

std::optional<std::string> Mprgp::proportioning_step(SolveState& s) const
{
  // Proportioning step along beta: releases active components whose gradient points
  // into the box.
  chopped_gradient(s.x, s.g, s.box, s.beta);
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
    return "operator is not positive definite on the search direction: "
           "beta'A beta = " +
        format_number(beta_q) + " <= 0 at iteration " + std::to_string(s.report.iterations);
  const double alpha = g_beta / beta_q;
  // beta moves each component it releases away from one bound; with two finite bounds the
  // step may reach the other. It is then cut there, which still decreases f (a convex
  // parabola along beta, decreasing up to alpha). Without upper bounds beta_i <= 0 moves
  // only up, never blocked: the test and its reduction are skipped.
  Index blocking = -1;
  const double alpha_f = s.box.upper ? feasible_step(s.space, s.x, s.beta, s.box, blocking) : infinity;
  if (!(alpha > alpha_f))
  {
    s.x -= alpha * s.beta;
    if (s.box.upper) // round-off at alpha = alpha_f
      s.box.project(s.x);
    s.g -= alpha * s.q;
  }
  else
  {
    s.x -= alpha_f * s.beta;
    s.box.project(s.x);
    if (blocking >= 0)
      s.x[blocking] = s.box.bound_reached(blocking, s.beta[blocking]);
    s.g -= alpha_f * s.q;
  }
  direction(s, s.p);
  s.ritz.end_run();
  ++s.report.proportioning_steps;
  s.step = MprgpStep::proportioning;
  return std::nullopt;
}
} // namespace feticon::qp
