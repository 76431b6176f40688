#include "qp/norm_estimate.hpp"

#include "common/error.hpp"

#include <cmath>
#include <memory>

namespace feticon::qp
{
NormEstimate estimate_norm(const la::LinearOperator& A, int max_iterations, double rtol, unsigned seed)
{
  const la::VectorSpace* space = A.space();
  FETICON_CHECK(max_iterations >= 1, "estimate_norm: max_iterations = " << max_iterations << " must be >= 1");
  FETICON_CHECK(rtol >= 0.0, "estimate_norm: rtol = " << rtol << " must be >= 0");
  NormEstimate estimate;
  const la::Index n = A.size();
  std::unique_ptr<la::SerialSpace> serial;
  if (!space)
    space = (serial = std::make_unique<la::SerialSpace>(n)).get();
  if (space->max(static_cast<double>(n)) == 0.0)
    return estimate;

  // Entry i of the start vector hashes (seed, global index i) with splitmix64, so the vector
  // is portable and the same however the entries are distributed over ranks.
  la::Vector v(n);
  for (la::Index i = 0; i < n; ++i)
  {
    uint64_t z =
        (static_cast<uint64_t>(seed) << 40) + static_cast<uint64_t>(space->global_index(i)) + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    v[i] = static_cast<double>(z >> 11) / 9007199254740992.0 - 0.5;
  }
  v /= la::norm(*space, v);

  la::Vector w;
  double previous = 0.0;
  for (int k = 0; k < max_iterations; ++k)
  {
    A.apply(v, w);
    ++estimate.applications;
    const auto [vw, ww] = la::reduce_sum<2>(*space, [&](la::Index i, double* s) {
      s[0] += v[i] * w[i];
      s[1] += w[i] * w[i];
    });
    estimate.value = vw;
    const double w_norm = std::sqrt(ww);
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
