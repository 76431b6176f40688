#pragma once
/// @file A hex8 mesh as a mesh of another cell type on the same nodes and geometry: each hexahedron
/// split into Kuhn's six tetrahedra about its diagonal 0-6 (tet4, tet10) or two wedges split
/// along its face diagonals 0-2 and 4-6 (wedge6), or kept whole (hex20); quadratic cells get a
/// node in the middle of every (straight) edge, shared by the cells of that edge. Face sets
/// become the new cells' boundary faces inside each old face, outward; node sets are kept and
/// gain the edge nodes between two of their nodes.
///
/// The splits meet conformingly between neighbouring hexahedra when their local orders agree
/// across shared faces, as in the structured blocks of box.hpp and the octant balls of
/// hertz3d (their local frames are consistently oriented). Used to run the verification cases
/// and the benchmarks on every cell type with the meshes the hex8 code already makes.

#include "mesh/mesh.hpp"

#include <functional>

namespace feticon::mesh
{
/// Where the node of the edge between two nodes goes (m): the midpoint of the straight edge
/// unless a caller puts it on a curved surface.
using EdgeNodePlacement = std::function<Eigen::Vector3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b)>;

/// @brief The hex8 mesh `hex` converted to cells of type `kind` (see file comment).
/// @param place the edge nodes of quadratic cells (default: edge midpoints)
/// @throws feticon::Error if `hex` has cells other than hex8.
Mesh convert_hex8_mesh(const Mesh& hex, CellKind kind, const EdgeNodePlacement& place = {});
} // namespace feticon::mesh
