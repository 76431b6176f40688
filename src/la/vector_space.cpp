#include "la/vector_space.hpp"

#include <numeric>

namespace feticon::la
{
SerialSpace::SerialSpace(Index n) : _n(n), _blocks(1)
{
  _blocks[0].resize(static_cast<size_t>(n));
  std::iota(_blocks[0].begin(), _blocks[0].end(), Index{0});
}

void SerialSpace::combine(std::span<const double> partials, int k, double* totals) const
{
  for (int j = 0; j < k; ++j)
    totals[j] = partials[j];
}
} // namespace feticon::la
