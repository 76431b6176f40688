#include "mesh/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace feticon::mesh
{
MeshQuality mesh_quality(const HexMesh& mesh, bool in_plane)
{
  MeshQuality q;
  q.min_angle_deg = std::numeric_limits<double>::infinity();
  const int n_faces = in_plane ? 1 : 6; // hex_faces[0] is the zeta = -1 face
  for (const Cell& cell : mesh.cells)
  {
    double shortest = std::numeric_limits<double>::infinity(), longest = 0;
    for (int f = 0; f < n_faces; ++f)
      for (int k = 0; k < 4; ++k)
      {
        auto at = [&](int j) { return Eigen::Vector3d(mesh.nodes.row(cell[hex_faces[f][(k + j) % 4]])); };
        const Eigen::Vector3d to_next = at(1) - at(0), to_previous = at(3) - at(0);
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
