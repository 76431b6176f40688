#pragma once
/// Dense reference solvers for min 1/2 x'Ax - b'x s.t. x >= l (or l <= x <= u), independent of Mprgp.
///
/// Primal active-set method for strictly convex QPs (Nocedal & Wright 2006, Numerical
/// Optimization, 2nd ed., Algorithm 16.3), specialized to bounds: fix the working set W at
/// its bounds, minimize over the rest with a dense LDLT, step to the first blocking bound if
/// that minimizer is infeasible, otherwise release the bound with the most negative
/// multiplier g_j. It terminates finitely on nondegenerate problems and returns the minimizer
/// to round-off (the last subproblem is solved exactly by LDLT).

#include "la/types.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace feticon::test
{
inline la::Vector reference_bound_qp(const la::Matrix& A, const la::Vector& b, const la::Vector& lower)
{
  const la::Index n = b.size();
  la::Vector x = la::Vector::Zero(n).cwiseMax(lower);
  std::vector<bool> working(static_cast<std::size_t>(n));
  for (la::Index i = 0; i < n; ++i)
    working[i] = x[i] == lower[i];
  // Multipliers within round-off of zero are not released, to avoid cycling on them.
  const double scale = A.cwiseAbs().maxCoeff() * (1.0 + x.cwiseAbs().maxCoeff()) + b.cwiseAbs().maxCoeff();

  for (int iteration = 0; iteration < 100 * (n + 10); ++iteration)
  {
    std::vector<la::Index> free;
    for (la::Index i = 0; i < n; ++i)
      if (!working[i])
        free.push_back(i);
    // Subproblem: x_W = l_W, A_FF z_F = b_F - A_FW l_W.
    la::Vector z = x;
    for (la::Index i = 0; i < n; ++i)
      if (working[i])
        z[i] = lower[i];
    const auto m = static_cast<la::Index>(free.size());
    la::Matrix A_ff(m, m);
    la::Vector rhs(m);
    for (la::Index r = 0; r < m; ++r)
    {
      rhs[r] = b[free[r]];
      for (la::Index i = 0; i < n; ++i)
        if (working[i])
          rhs[r] -= A(free[r], i) * lower[i];
      for (la::Index c = 0; c < m; ++c)
        A_ff(r, c) = A(free[r], free[c]);
    }
    const la::Vector z_free = A_ff.ldlt().solve(rhs);
    for (la::Index r = 0; r < m; ++r)
      z[free[r]] = z_free[r];

    double step = 1.0;
    la::Index blocking = -1;
    for (const la::Index i : free)
      if (z[i] < lower[i])
      {
        const double t = (x[i] - lower[i]) / (x[i] - z[i]);
        if (t < step)
        {
          step = t;
          blocking = i;
        }
      }
    if (blocking >= 0)
    {
      // The clamp keeps round-off from putting another component below its bound.
      x = (x + step * (z - x)).cwiseMax(lower);
      x[blocking] = lower[blocking];
      working[blocking] = true;
      continue;
    }

    x = z;
    const la::Vector g = A * x - b;
    la::Index release = -1;
    double most_negative = -1e-14 * scale;
    for (la::Index i = 0; i < n; ++i)
      if (working[i] && g[i] < most_negative)
      {
        most_negative = g[i];
        release = i;
      }
    if (release < 0)
      return x;
    working[release] = false;
  }
  throw std::runtime_error("reference_bound_qp: no convergence (degenerate problem?)");
}

/// Dense reference solver for min 1/2 x'Ax - b'x s.t. l <= x <= u (l_i = -inf, u_i = +inf
/// and l_i = u_i allowed), independent of Mprgp: the primal active-set method above with a
/// working set of components held at their lower or their upper bound (Nocedal & Wright 2006,
/// Algorithm 16.3, with the bound constraints l_i <= x_i and x_i <= u_i as separate rows).
/// The multiplier of x_i = l_i is g_i (must be >= 0), of x_i = u_i it is -g_i (must be >= 0);
/// a fixed component (l_i = u_i) is never released.
inline la::Vector reference_box_qp(const la::Matrix& A, const la::Vector& b, const la::Vector& lower,
                                   const la::Vector& upper)
{
  enum class State
  {
    free,
    at_lower,
    at_upper
  };
  const la::Index n = b.size();
  la::Vector x = la::Vector::Zero(n).cwiseMax(lower).cwiseMin(upper);
  std::vector<State> state(static_cast<std::size_t>(n), State::free);
  for (la::Index i = 0; i < n; ++i)
    state[i] = x[i] == lower[i] ? State::at_lower : x[i] == upper[i] ? State::at_upper : State::free;
  const auto bound = [&](la::Index i) { return state[i] == State::at_lower ? lower[i] : upper[i]; };
  const double finite_x = x.cwiseAbs().maxCoeff();
  const double scale = A.cwiseAbs().maxCoeff() * (1.0 + finite_x) + b.cwiseAbs().maxCoeff();

  for (int iteration = 0; iteration < 100 * (n + 10); ++iteration)
  {
    std::vector<la::Index> free;
    for (la::Index i = 0; i < n; ++i)
      if (state[i] == State::free)
        free.push_back(i);
    // Subproblem: x_W at its bounds, A_FF z_F = b_F - A_FW x_W.
    la::Vector z = x;
    for (la::Index i = 0; i < n; ++i)
      if (state[i] != State::free)
        z[i] = bound(i);
    const auto m = static_cast<la::Index>(free.size());
    la::Matrix A_ff(m, m);
    la::Vector rhs(m);
    for (la::Index r = 0; r < m; ++r)
    {
      rhs[r] = b[free[r]];
      for (la::Index i = 0; i < n; ++i)
        if (state[i] != State::free)
          rhs[r] -= A(free[r], i) * z[i];
      for (la::Index c = 0; c < m; ++c)
        A_ff(r, c) = A(free[r], free[c]);
    }
    const la::Vector z_free = A_ff.ldlt().solve(rhs);
    for (la::Index r = 0; r < m; ++r)
      z[free[r]] = z_free[r];

    // The first bound on the segment from x to z.
    double step = 1.0;
    la::Index blocking = -1;
    State blocking_state = State::free;
    for (const la::Index i : free)
    {
      if (z[i] < lower[i] && (x[i] - lower[i]) / (x[i] - z[i]) < step)
      {
        step = (x[i] - lower[i]) / (x[i] - z[i]);
        blocking = i;
        blocking_state = State::at_lower;
      }
      if (z[i] > upper[i] && (upper[i] - x[i]) / (z[i] - x[i]) < step)
      {
        step = (upper[i] - x[i]) / (z[i] - x[i]);
        blocking = i;
        blocking_state = State::at_upper;
      }
    }
    if (blocking >= 0)
    {
      // The clamp keeps round-off from putting another component outside its bounds.
      x = (x + step * (z - x)).cwiseMax(lower).cwiseMin(upper);
      state[blocking] = blocking_state;
      x[blocking] = bound(blocking);
      continue;
    }

    x = z;
    const la::Vector g = A * x - b;
    la::Index release = -1;
    double most_negative = -1e-14 * scale;
    for (la::Index i = 0; i < n; ++i)
    {
      if (state[i] == State::free || lower[i] == upper[i])
        continue;
      const double multiplier = state[i] == State::at_lower ? g[i] : -g[i];
      if (multiplier < most_negative)
      {
        most_negative = multiplier;
        release = i;
      }
    }
    if (release < 0)
      return x;
    state[release] = State::free;
  }
  throw std::runtime_error("reference_box_qp: no convergence (degenerate problem?)");
}
} // namespace feticon::test
