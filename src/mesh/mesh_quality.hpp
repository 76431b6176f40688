#pragma once
/// @file Shape measures of a mesh: the worst aspect ratio and the extreme corner angles of
/// its cells, reported in summary.json so that a needle or a flattened cell is visible.

#include "mesh/mesh.hpp"

namespace feticon::mesh
{
struct MeshQuality
{
  double max_aspect_ratio = 0; ///< longest / shortest edge of a cell, worst cell
  double min_angle_deg = 0;    ///< smallest corner angle of a cell face (degrees)
  double max_angle_deg = 0;    ///< largest corner angle of a cell face (degrees)
};

/// @brief The measures over all cells.
/// @param in_plane true for a plane-strain hex8 layer: only the cells' z = min faces count
///   (their 4 edges and corners), since the layer thickness is no element size of the 2D
///   problem. 2D cells count their own edges and corners either way.
MeshQuality mesh_quality(const Mesh& mesh, bool in_plane);
} // namespace feticon::mesh
