#include "qp/gradient_split.hpp"

namespace feticon::qp
{
double quadratic_cost(const la::VectorSpace& space, const la::Vector& x, const la::Vector& g, const la::Vector& b)
{
  return 0.5 * la::reduce_sum<1>(space, [&](la::Index i, double* sum) { sum[0] += x[i] * (g[i] - b[i]); })[0];
}
} // namespace feticon::qp
