#pragma once
/// Dense reference solver for min 1/2 x'Ax - b'x s.t. x >= l, independent of Mprgp.
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
} // namespace feticon::test
