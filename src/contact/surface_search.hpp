#pragma once
/// @file Candidate search for contact: which master faces may be near a query point
/// (ALGORITHMS.md section 4, "Search").
///
/// Each master face gets an axis-aligned bounding box (AABB) of its corners in the current
/// configuration, inflated by the search distance d_s. The boxes are hashed into a uniform bucket
/// grid (spatial hashing, Teschner et al. 2003): the grid cell (i, j, k) of edge h maps to bucket
/// hash(i, j, k) mod n_buckets, and every box is listed in the buckets of all cells it overlaps.
/// A query visits the one bucket of its cell and returns the boxes that contain the point, so it
/// costs O(boxes per cell) instead of O(all faces). Hash collisions only add boxes that the exact
/// containment test removes again.
///
/// Cell size: the mean largest edge of the (inflated) boxes, so a box spans about 2 cells per
/// axis; it is doubled while the boxes would need more than 64 bucket entries each on average
/// (a few huge boxes), which bounds the memory by O(n_boxes).
///
/// Usage:
///   std::vector<BoundingBox> boxes = ...;  // one per master face, inflated by d_s
///   const SurfaceSearch search(boxes);
///   std::vector<int32_t> faces;
///   search.candidates(x_s, faces);        // sorted ids of the boxes containing x_s

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Dense>

namespace feticon::contact
{
/// Axis-aligned box [lower, upper] (m). Empty (lower > upper) until a point is added.
struct BoundingBox
{
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Eigen::Vector3d& point)
  {
    lower = lower.cwiseMin(point);
    upper = upper.cwiseMax(point);
  }
  /// Moves every side out by `distance` (m).
  void inflate(double distance)
  {
    lower.array() -= distance;
    upper.array() += distance;
  }
  bool contains(const Eigen::Vector3d& point) const
  {
    return (point.array() >= lower.array()).all() && (point.array() <= upper.array()).all();
  }
  /// Whether the two closed boxes share at least a point.
  bool intersects(const BoundingBox& other) const
  {
    return (lower.array() <= other.upper.array()).all() && (other.lower.array() <= upper.array()).all();
  }
  /// Euclidean distance from `point` to the box, 0 inside (m).
  double distance(const Eigen::Vector3d& point) const
  {
    return (lower - point).cwiseMax(point - upper).cwiseMax(0.0).norm();
  }
};

/// Spatial hash of bounding boxes for point queries (see file comment).
class SurfaceSearch
{
public:
  /// @brief Hashes `boxes`; box k keeps the id k.
  /// @throws feticon::Error if a box is empty or not finite.
  explicit SurfaceSearch(std::vector<BoundingBox> boxes);

  /// @brief Ids of the boxes containing `point`, sorted ascending, into `ids` (cleared first).
  void candidates(const Eigen::Vector3d& point, std::vector<int32_t>& ids) const;
  /// Convenience overload of candidates() that allocates.
  std::vector<int32_t> candidates(const Eigen::Vector3d& point) const;
  /// @brief Ids of the boxes intersecting the box `query` (closed boxes: touching counts), sorted
  /// ascending, into `ids` (cleared first). Visits every bucket of the cells `query` overlaps, so
  /// it is meant for queries of about the size of the stored boxes (e.g. one slave face).
  void candidates(const BoundingBox& query, std::vector<int32_t>& ids) const;

  int32_t n_boxes() const { return static_cast<int32_t>(_boxes.size()); }
  const std::vector<BoundingBox>& boxes() const { return _boxes; }
  /// Edge length h of a grid cell (m).
  double cell_size() const { return _cell_size; }
  int64_t n_buckets() const { return static_cast<int64_t>(_offsets.size()) - 1; }
  /// Total (box, bucket) entries stored.
  int64_t n_entries() const { return static_cast<int64_t>(_entries.size()); }

private:
  std::array<int64_t, 3> cell_of(const Eigen::Vector3d& point) const;
  int64_t bucket_of(const std::array<int64_t, 3>& cell) const;

  std::vector<BoundingBox> _boxes;
  /// Box around all boxes; its lower corner is the grid origin.
  BoundingBox _bounds;
  double _cell_size = 1;
  /// Bucket b lists _entries[_offsets[b] .. _offsets[b + 1]) (compressed rows).
  std::vector<int64_t> _offsets{0};
  std::vector<int32_t> _entries;
};
} // namespace feticon::contact
