#include "qp/separable_constraints.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace feticon::qp
{
namespace
{
using la::Index;
using la::Vector;

using la::infinity;

void check_bounds(const SeparableConstraints& set, Index n, const char* who)
{
  FETICON_CHECK(set.lower.size() == n,
                who << ": the lower bound has size " << set.lower.size() << " but the operator has size " << n);
  FETICON_CHECK(set.upper.size() == n,
                who << ": the upper bound has size " << set.upper.size() << " but the operator has size " << n);
  for (Index i = 0; i < n; ++i)
  {
    FETICON_CHECK(!std::isnan(set.lower[i]) && set.lower[i] != infinity,
                  who << ": lower bound l[" << i << "] = " << set.lower[i] << "; bounds must be finite or -inf");
    FETICON_CHECK(!std::isnan(set.upper[i]) && set.upper[i] != -infinity,
                  who << ": upper bound u[" << i << "] = " << set.upper[i] << "; bounds must be finite or +inf");
    FETICON_CHECK(set.lower[i] <= set.upper[i],
                  who << ": empty box at component " << i << ": l[" << i << "] = " << set.lower[i] << " > u[" << i
                      << "] = " << set.upper[i] << "; bounds need l <= u");
  }
}

void check_disc_component(const SeparableConstraints& set, Index component, std::size_t k, Index n,
                          std::vector<int>& owner, const char* who)
{
  FETICON_CHECK(component >= 0 && component < n,
                who << ": disc " << k << " names component " << component << ", outside [0, " << n << ")");
  FETICON_CHECK(owner[component] < 0,
                who << ": component " << component << " is in disc " << owner[component] << " and in disc " << k
                    << "; a component belongs to one disc at most");
  FETICON_CHECK(std::isinf(set.lower[component]) && std::isinf(set.upper[component]),
                who << ": component " << component << " of disc " << k << " has the bounds [" << set.lower[component]
                    << ", " << set.upper[component] << "]; a disc component takes no bounds (-inf, +inf)");
  owner[component] = static_cast<int>(k);
}

/// ||(a, b)||.
double pair_norm(double a, double b) { return std::hypot(a, b); }

/// x_d - c_d: the pair relative to the disc's centre (exactly x_d for a centre at 0).
struct Offset
{
  double i, j;
};
Offset offset(const Disc& disc, const Vector& x) { return {x[disc.i] - disc.centre_i, x[disc.j] - disc.centre_j}; }
} // namespace

void check_separable_constraints(const SeparableConstraints& set, Index n, const char* who)
{
  check_bounds(set, n, who);
  std::vector<int> owner(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < set.discs.size(); ++k)
  {
    const Disc& disc = set.discs[k];
    FETICON_CHECK(std::isfinite(disc.radius) && disc.radius >= 0.0,
                  who << ": disc " << k << " (components " << disc.i << ", " << disc.j << ") has radius " << disc.radius
                      << "; a radius is finite and >= 0");
    FETICON_CHECK(std::isfinite(disc.centre_i) && std::isfinite(disc.centre_j),
                  who << ": disc " << k << " (components " << disc.i << ", " << disc.j << ") has the centre ("
                      << disc.centre_i << ", " << disc.centre_j << "); a centre is finite");
    FETICON_CHECK(disc.i != disc.j,
                  who << ": disc " << k << " names component " << disc.i << " twice; a disc joins two components");
    check_disc_component(set, disc.i, k, n, owner, who);
    check_disc_component(set, disc.j, k, n, owner, who);
  }
}

bool disc_is_active(const Disc& disc, const Vector& x)
{
  const Offset d = offset(disc, x);
  return pair_norm(d.i, d.j) >= disc.radius * (1.0 - disc_tolerance);
}

void project(const SeparableConstraints& set, Vector& x)
{
  x = x.cwiseMax(set.lower).cwiseMin(set.upper);
  for (const Disc& disc : set.discs)
  {
    const Offset d = offset(disc, x);
    const double norm = pair_norm(d.i, d.j);
    if (norm > disc.radius)
    {
      const double scale = disc.radius / norm; // 0 for radius 0
      x[disc.i] = disc.centre_i + scale * d.i;
      x[disc.j] = disc.centre_j + scale * d.j;
    }
  }
}

bool is_feasible(const SeparableConstraints& set, const Vector& x)
{
  if ((x.array() < set.lower.array()).any() || (x.array() > set.upper.array()).any())
    return false;
  return std::all_of(set.discs.begin(), set.discs.end(), [&](const Disc& disc) {
    const Offset d = offset(disc, x);
    return pair_norm(d.i, d.j) <= disc.radius * (1.0 + disc_tolerance);
  });
}

void project_onto_face(const SeparableConstraints& set, const Vector& x, Vector& v)
{
  // Disc components have infinite bounds, so the bound test calls them free.
  v = ((x.array() > set.lower.array()) && (x.array() < set.upper.array())).select(v, 0.0);
  for (const Disc& disc : set.discs)
  {
    if (!disc_is_active(disc, x))
      continue;
    const Offset d = offset(disc, x);
    const double norm = pair_norm(d.i, d.j);
    if (disc.radius == 0.0 || norm == 0.0)
    {
      v[disc.i] = v[disc.j] = 0.0;
      continue;
    }
    const double n_i = d.i / norm;
    const double n_j = d.j / norm;
    const double normal = n_i * v[disc.i] + n_j * v[disc.j];
    v[disc.i] -= normal * n_i;
    v[disc.j] -= normal * n_j;
  }
}

void free_gradient(const SeparableConstraints& set, const Vector& x, const Vector& g, Vector& phi)
{
  phi = g;
  project_onto_face(set, x, phi);
}

void chopped_gradient(const SeparableConstraints& set, const Vector& x, const Vector& g, Vector& beta)
{
  beta.resize(x.size());
  for (Index i = 0; i < x.size(); ++i)
  {
    const bool above_lower = x[i] > set.lower[i];
    const bool below_upper = x[i] < set.upper[i];
    if (above_lower)
      beta[i] = below_upper ? 0.0 : std::max(g[i], 0.0);
    else
      beta[i] = below_upper ? std::min(g[i], 0.0) : 0.0;
  }
  for (const Disc& disc : set.discs)
  {
    const Offset d = offset(disc, x);
    const double norm = pair_norm(d.i, d.j);
    if (disc.radius == 0.0 || norm == 0.0 || !disc_is_active(disc, x))
      continue; // a fixed pair, or inactive: beta = 0
    const double n_i = d.i / norm;
    const double n_j = d.j / norm;
    const double inward = std::max(n_i * g[disc.i] + n_j * g[disc.j], 0.0);
    beta[disc.i] = inward * n_i;
    beta[disc.j] = inward * n_j;
  }
}

bool moves_along_a_circle(const SeparableConstraints& set, const Vector& x, const Vector& p)
{
  return std::any_of(set.discs.begin(), set.discs.end(), [&](const Disc& disc) {
    return disc.radius > 0.0 && (p[disc.i] != 0.0 || p[disc.j] != 0.0) && disc_is_active(disc, x);
  });
}

void reduced_free_gradient(const SeparableConstraints& set, const Vector& x, const Vector& phi, double alpha,
                           Vector& reduced)
{
  reduced.resize(x.size());
  for (Index i = 0; i < x.size(); ++i)
    reduced[i] =
        std::min((x[i] - set.lower[i]) / alpha, std::max((x[i] - set.upper[i]) / alpha, phi[i])); // phi_i on discs
  for (const Disc& disc : set.discs)
  {
    const Offset d = offset(disc, x);
    const double y_i = d.i - alpha * phi[disc.i];
    const double y_j = d.j - alpha * phi[disc.j];
    const double norm = pair_norm(y_i, y_j);
    if (norm <= disc.radius)
      continue; // the step stays in the disc: phi~ = phi
    const double scale = disc.radius / norm;
    reduced[disc.i] = (d.i - scale * y_i) / alpha;
    reduced[disc.j] = (d.j - scale * y_j) / alpha;
  }
}

void disc_curvature(const SeparableConstraints& set, const Vector& x, const Vector& g, Vector& curvature)
{
  curvature = Vector::Zero(x.size());
  for (const Disc& disc : set.discs)
  {
    const Offset d = offset(disc, x);
    const double norm = pair_norm(d.i, d.j);
    if (disc.radius == 0.0 || norm == 0.0 || !disc_is_active(disc, x))
      continue;
    const double nu = std::max(-(d.i * g[disc.i] + d.j * g[disc.j]) / norm, 0.0);
    curvature[disc.i] = curvature[disc.j] = nu / norm;
  }
}

double max_bound_step(const SeparableConstraints& set, const Vector& x, const Vector& p, Index& blocking)
{
  double alpha = infinity;
  blocking = -1;
  for (Index i = 0; i < x.size(); ++i)
  {
    double step = infinity;
    if (p[i] > 0.0 && std::isfinite(set.lower[i]))
      step = (x[i] - set.lower[i]) / p[i];
    else if (p[i] < 0.0 && std::isfinite(set.upper[i]))
      step = (x[i] - set.upper[i]) / p[i];
    if (step < alpha)
    {
      alpha = step;
      blocking = i;
    }
  }
  return alpha;
}

double max_disc_step(const SeparableConstraints& set, const Vector& x, const Vector& p, bool include_active,
                     Index& blocking)
{
  double alpha = infinity;
  blocking = -1;
  for (const Disc& disc : set.discs)
  {
    if (!include_active && disc_is_active(disc, x))
      continue;
    // ||x - t p||^2 = r^2:  a t^2 - 2 c_xp t + c = 0 with c <= 0 at a feasible x; the
    // positive root in the form without cancellation.
    const double a = p[disc.i] * p[disc.i] + p[disc.j] * p[disc.j];
    if (a == 0.0)
      continue;
    const Offset d = offset(disc, x);
    const double c_xp = d.i * p[disc.i] + d.j * p[disc.j];
    const double c = std::min(d.i * d.i + d.j * d.j - disc.radius * disc.radius, 0.0);
    const double root = std::sqrt(c_xp * c_xp - a * c);
    const double step = c_xp >= 0.0 ? (c_xp + root) / a : -c / (root - c_xp);
    if (step < alpha)
    {
      alpha = step;
      blocking = disc.i;
    }
  }
  return alpha;
}
} // namespace feticon::qp
