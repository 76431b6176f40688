#include "qp/norm_estimate.hpp"

#include "common/error.hpp"

#include <cmath>
#include <random>

namespace feticon::qp
{
NormEstimate estimate_norm(const la::LinearOperator& A, int max_iterations, double rtol,
                           unsigned seed)
{
  FETICON_CHECK(max_iterations >= 1,
                "estimate_norm: max_iterations = " << max_iterations << " must be >= 1");
  FETICON_CHECK(rtol >= 0.0, "estimate_norm: rtol = " << rtol << " must be >= 0");
  NormEstimate estimate;
  const la::Index n = A.size();
  if (n == 0)
    return estimate;

  // Raw mt19937 output is fixed by the standard (unlike std::uniform_real_distribution), so
  // the start vector, and with it alpha_bar and every MPRGP counter, is portable.
  std::mt19937 generator(seed);
  la::Vector v(n);
  for (la::Index i = 0; i < n; ++i)
    v[i] = static_cast<double>(generator()) / 4294967296.0 - 0.5;
  v /= v.norm();

  la::Vector w;
  double previous = 0.0;
  for (int k = 0; k < max_iterations; ++k)
  {
    A.apply(v, w);
    ++estimate.applications;
    estimate.value = v.dot(w);
    const double w_norm = w.norm();
    if (w_norm == 0.0 || !std::isfinite(w_norm))
      break;
    if (k > 0 && std::abs(estimate.value - previous) <= rtol * std::abs(estimate.value))
      break;
    previous = estimate.value;
    v = w / w_norm;
  }
  return estimate;
}
} // namespace feticon::qp
