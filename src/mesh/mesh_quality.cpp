#include "mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace feticon::mesh
{
MeshQuality mesh_quality(const Mesh& mesh, bool in_plane)
{
  MeshQuality q;
  q.min_angle_deg = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < mesh.cells.size(); ++c)
  {
    const std::span<const int32_t> cell = mesh.cells[c];
    const CellType& type = cell_type(mesh.cells.kind(c));
    // A hex8's face S1 is its zeta = -1 face, the plane-strain section.
    const size_t n_faces = in_plane ? 1 : type.faces.size();
    double shortest = std::numeric_limits<double>::infinity(), longest = 0;
    for (size_t f = 0; f < n_faces; ++f)
      for (int k = 0, m = face_corners(type.faces[f].kind); k < m; ++k)
      {
        auto at = [&](int j) { return Eigen::Vector3d(mesh.nodes.row(cell[type.faces[f].nodes[(k + j) % m]])); };
        const Eigen::Vector3d to_next = at(1) - at(0), to_previous = at(m - 1) - at(0);
        shortest = std::min(shortest, to_next.norm());
        longest = std::max(longest, to_next.norm());
        const double angle = std::atan2(to_next.cross(to_previous).norm(), to_next.dot(to_previous)) * 180 / M_PI;
        q.min_angle_deg = std::min(q.min_angle_deg, angle);
        q.max_angle_deg = std::max(q.max_angle_deg, angle);
      }
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, longest / shortest);
  }
  if (mesh.cells.empty())
    q.min_angle_deg = 0;
  return q;
}
} // namespace feticon::mesh
