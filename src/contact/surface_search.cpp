#include "contact/surface_search.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

namespace feticon::contact
{
namespace
{
/// Average bucket entries per box allowed before the cell size is doubled.
constexpr int64_t max_entries_per_box = 64;

/// splitmix64 finalizer: spreads neighbouring cells over all buckets.
uint64_t mix(uint64_t key)
{
  key ^= key >> 30;
  key *= 0xbf58476d1ce4e5b9ULL;
  key ^= key >> 27;
  key *= 0x94d049bb133111ebULL;
  key ^= key >> 31;
  return key;
}

/// Number of grid cells a box overlaps for cell size h and grid origin `origin`; a double, so that
/// a first guess of h far too small cannot overflow the count.
double cells_overlapped(const BoundingBox& box, const Eigen::Vector3d& origin, double h)
{
  double count = 1;
  for (int axis = 0; axis < 3; ++axis)
    count *= std::floor((box.upper(axis) - origin(axis)) / h) - std::floor((box.lower(axis) - origin(axis)) / h) + 1;
  return count;
}
} // namespace

SurfaceSearch::SurfaceSearch(std::vector<BoundingBox> boxes) : _boxes(std::move(boxes))
{
  double extent_sum = 0;
  for (size_t k = 0; k < _boxes.size(); ++k)
  {
    const BoundingBox& box = _boxes[k];
    FETICON_CHECK(box.lower.allFinite() && box.upper.allFinite() && (box.lower.array() <= box.upper.array()).all(),
                  "surface search: bounding box " << k << " is empty or not finite (lower " << box.lower.transpose()
                                                  << ", upper " << box.upper.transpose() << ")");
    _bounds.extend(box.lower);
    _bounds.extend(box.upper);
    extent_sum += (box.upper - box.lower).maxCoeff();
  }
  if (_boxes.empty())
    return;
  const auto n_boxes = static_cast<int64_t>(_boxes.size());
  _cell_size = extent_sum / static_cast<double>(n_boxes);
  if (!(_cell_size > 0))
    _cell_size = std::max(1.0, (_bounds.upper - _bounds.lower).maxCoeff());

  // Grow the cells until the entries fit the memory bound (see file comment).
  double n_cell_entries = 0;
  while (true)
  {
    n_cell_entries = 0;
    for (const BoundingBox& box : _boxes)
      n_cell_entries += cells_overlapped(box, _bounds.lower, _cell_size);
    if (n_cell_entries <= static_cast<double>(max_entries_per_box * n_boxes))
      break;
    _cell_size *= 2;
  }

  const auto n_buckets = static_cast<int64_t>(std::bit_ceil(static_cast<uint64_t>(n_cell_entries)));
  // Two passes over the same cells: count, then fill. Boxes are visited in id order, so a box that
  // reaches a bucket twice (two of its cells collide) is the last entry there and is skipped, and
  // every bucket lists its boxes sorted.
  _offsets.assign(n_buckets + 1, 0); // sets n_buckets() for bucket_of()
  std::vector<int32_t> last_box(n_buckets, -1);
  auto for_each_bucket = [&](int32_t k, auto&& visit) {
    const std::array<int64_t, 3> lo = cell_of(_boxes[k].lower);
    const std::array<int64_t, 3> hi = cell_of(_boxes[k].upper);
    for (int64_t i = lo[0]; i <= hi[0]; ++i)
      for (int64_t j = lo[1]; j <= hi[1]; ++j)
        for (int64_t l = lo[2]; l <= hi[2]; ++l)
        {
          const int64_t bucket = bucket_of({i, j, l});
          if (last_box[bucket] != k)
          {
            last_box[bucket] = k;
            visit(bucket);
          }
        }
  };
  for (int32_t k = 0; k < static_cast<int32_t>(n_boxes); ++k)
    for_each_bucket(k, [&](int64_t bucket) { ++_offsets[bucket + 1]; });
  for (int64_t b = 0; b < n_buckets; ++b)
    _offsets[b + 1] += _offsets[b];
  _entries.resize(_offsets.back());
  std::fill(last_box.begin(), last_box.end(), -1);
  std::vector<int64_t> next(_offsets.begin(), _offsets.end() - 1);
  for (int32_t k = 0; k < static_cast<int32_t>(n_boxes); ++k)
    for_each_bucket(k, [&](int64_t bucket) { _entries[next[bucket]++] = k; });
}

std::array<int64_t, 3> SurfaceSearch::cell_of(const Eigen::Vector3d& point) const
{
  std::array<int64_t, 3> cell{};
  for (int axis = 0; axis < 3; ++axis)
    cell[axis] = static_cast<int64_t>(std::floor((point(axis) - _bounds.lower(axis)) / _cell_size));
  return cell;
}

int64_t SurfaceSearch::bucket_of(const std::array<int64_t, 3>& cell) const
{
  return static_cast<int64_t>(mix(static_cast<uint64_t>(cell[0]) * 73856093ULL +
                                  static_cast<uint64_t>(cell[1]) * 19349663ULL +
                                  static_cast<uint64_t>(cell[2]) * 83492791ULL) &
                              static_cast<uint64_t>(n_buckets() - 1));
}

void SurfaceSearch::candidates(const Eigen::Vector3d& point, std::vector<int32_t>& ids) const
{
  ids.clear();
  // Outside all boxes (this also keeps the cell indices of far points from overflowing).
  if (_boxes.empty() || !_bounds.contains(point))
    return;
  const int64_t bucket = bucket_of(cell_of(point));
  for (int64_t e = _offsets[bucket]; e < _offsets[bucket + 1]; ++e)
    if (_boxes[_entries[e]].contains(point))
      ids.push_back(_entries[e]);
}

void SurfaceSearch::candidates(const BoundingBox& query, std::vector<int32_t>& ids) const
{
  ids.clear();
  if (_boxes.empty() || !_bounds.intersects(query))
    return;
  // Clamp the query to the grid bounds: the cells outside hold no box, and the clamp keeps the
  // cell indices of a huge query from overflowing.
  const std::array<int64_t, 3> lo = cell_of(query.lower.cwiseMax(_bounds.lower));
  const std::array<int64_t, 3> hi = cell_of(query.upper.cwiseMin(_bounds.upper));
  for (int64_t i = lo[0]; i <= hi[0]; ++i)
    for (int64_t j = lo[1]; j <= hi[1]; ++j)
      for (int64_t k = lo[2]; k <= hi[2]; ++k)
      {
        const int64_t bucket = bucket_of({i, j, k});
        for (int64_t e = _offsets[bucket]; e < _offsets[bucket + 1]; ++e)
          if (_boxes[_entries[e]].intersects(query))
            ids.push_back(_entries[e]);
      }
  // A box spanning several visited cells (or reached through hash collisions) appears repeatedly.
  std::ranges::sort(ids);
  const auto duplicates = std::ranges::unique(ids);
  ids.erase(duplicates.begin(), duplicates.end());
}

std::vector<int32_t> SurfaceSearch::candidates(const Eigen::Vector3d& point) const
{
  std::vector<int32_t> ids;
  candidates(point, ids);
  return ids;
}
} // namespace feticon::contact
