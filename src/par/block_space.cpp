#include "par/block_space.hpp"

#include <limits>

namespace feticon::par
{
BlockSpace::BlockSpace(Communicator comm, std::vector<std::vector<la::Index>> blocks, std::vector<int64_t> global_index)
    : _comm(comm), _blocks(std::move(blocks)), _global_index(std::move(global_index))
{
}

void BlockSpace::combine(std::span<const double> partials, int k, double* totals) const
{
  // Gathered in rank order, which is global block order; added from 0 in that order.
  const std::vector<double> all = _comm.all_gather(std::vector<double>(partials.begin(), partials.end()));
  for (int j = 0; j < k; ++j)
    totals[j] = 0.0;
  for (size_t b = 0; b * k < all.size(); ++b)
    for (int j = 0; j < k; ++j)
      totals[j] += all[b * k + j];
}

std::pair<double, la::Index> BlockSpace::min_location(double value, la::Index local_index) const
{
  if (_comm.serial())
    return {value, local_index};
  const int64_t none = std::numeric_limits<int64_t>::max();
  const int64_t global = local_index >= 0 ? _global_index[local_index] : none;
  const std::vector<double> values = _comm.all_gather(std::vector<double>{value});
  const std::vector<int64_t> indices = _comm.all_gather(std::vector<int64_t>{global});
  size_t best = 0;
  for (size_t r = 1; r < values.size(); ++r)
    if (values[r] < values[best] || (values[r] == values[best] && indices[r] < indices[best]))
      best = r;
  const bool mine = static_cast<int>(best) == _comm.rank() && local_index >= 0;
  return {values[best], mine ? local_index : -1};
}
} // namespace feticon::par
