#include "mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace feticon::mesh
{
namespace
{
/// The corner polygons of a cell whose edges and angles count: a 2D cell's corners (counter-
/// clockwise), a 3D cell's faces (or, in_plane, its face S1, the zeta = -1 face of a hex8 layer).
std::vector<std::vector<int32_t>> corner_polygons(const CellType& type, std::span<const int32_t> cell, bool in_plane)
{
  if (type.dimension == 2)
    return {std::vector<int32_t>(cell.begin(), cell.begin() + type.n_corners)};
  std::vector<std::vector<int32_t>> out;
  const size_t n_faces = in_plane ? 1 : type.faces.size();
  for (size_t f = 0; f < n_faces; ++f)
  {
    std::vector<int32_t>& polygon = out.emplace_back();
    for (int k = 0; k < face_corners(type.faces[f].kind); ++k)
      polygon.push_back(cell[type.faces[f].nodes[k]]);
  }
  return out;
}

/// The corners' points without those that repeat the previous one (a collapsed edge: a quad
/// used as a triangle, as decks do), so that the polygon's edges and angles are those of the
/// shape the cell has, not a zero length and a zero angle.
std::vector<Eigen::Vector3d> without_collapsed_edges(const Mesh& mesh, const std::vector<int32_t>& corners)
{
  std::vector<Eigen::Vector3d> points;
  double perimeter = 0;
  for (size_t k = 0; k < corners.size(); ++k)
    perimeter += (mesh.nodes.row(corners[(k + 1) % corners.size()]) - mesh.nodes.row(corners[k])).norm();
  for (size_t k = 0; k < corners.size(); ++k)
  {
    const Eigen::Vector3d x = mesh.nodes.row(corners[k]).transpose();
    if (points.empty() || (x - points.back()).norm() > 1e-12 * perimeter)
      points.push_back(x);
  }
  if (points.size() > 1 && (points.back() - points.front()).norm() <= 1e-12 * perimeter)
    points.pop_back();
  return points;
}
} // namespace

MeshQuality mesh_quality(const Mesh& mesh, bool in_plane)
{
  MeshQuality q;
  q.min_angle_deg = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < mesh.cells.size(); ++c)
  {
    double shortest = std::numeric_limits<double>::infinity(), longest = 0;
    for (const std::vector<int32_t>& corners : corner_polygons(cell_type(mesh.cells.kind(c)), mesh.cells[c], in_plane))
    {
      const std::vector<Eigen::Vector3d> polygon = without_collapsed_edges(mesh, corners);
      const auto m = static_cast<int>(polygon.size());
      for (int k = 0; k < m; ++k)
      {
        auto at = [&](int j) { return polygon[(k + j) % m]; };
        const Eigen::Vector3d to_next = at(1) - at(0), to_previous = at(m - 1) - at(0);
        shortest = std::min(shortest, to_next.norm());
        longest = std::max(longest, to_next.norm());
        const double angle = std::atan2(to_next.cross(to_previous).norm(), to_next.dot(to_previous)) * 180 / M_PI;
        q.min_angle_deg = std::min(q.min_angle_deg, angle);
        q.max_angle_deg = std::max(q.max_angle_deg, angle);
      }
    }
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, longest / shortest);
  }
  if (mesh.cells.empty())
    q.min_angle_deg = 0;
  return q;
}
} // namespace feticon::mesh
