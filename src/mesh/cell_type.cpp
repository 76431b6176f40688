#include "mesh/cell_type.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <stdexcept>

namespace feticon::mesh
{
namespace
{
using Corners = std::vector<int>;

Eigen::Vector3d point(const CellType& type, int node)
{
  const auto& p = type.reference_nodes[node];
  return {p[0], p[1], p[2]};
}

/// The local node in the middle of the edge (a, b), or -1 for a linear cell.
int edge_node(const CellType& type, int a, int b)
{
  if (type.order == 1)
    return -1;
  for (size_t e = 0; e < type.edges.size(); ++e)
    if ((type.edges[e][0] == a && type.edges[e][1] == b) || (type.edges[e][0] == b && type.edges[e][1] == a))
      return type.n_corners + static_cast<int>(e);
  throw std::logic_error("cell_type: a face edge that is no cell edge");
}

/// The faces from their corners as a format lists them (CalculiX lists them with the normal
/// into the cell): each turned outward in the reference cell, its edge nodes appended.
void add_faces(CellType& type, const std::vector<Corners>& faces)
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int a = 0; a < type.n_corners; ++a)
    centre += point(type, a) / type.n_corners;
  for (Corners corners : faces)
  {
    const Eigen::Vector3d x0 = point(type, corners[0]);
    const Eigen::Vector3d normal = (point(type, corners[1]) - x0).cross(point(type, corners[corners.size() - 1]) - x0);
    Eigen::Vector3d face_centre = Eigen::Vector3d::Zero();
    for (int c : corners)
      face_centre += point(type, c) / static_cast<double>(corners.size());
    if (normal.dot(face_centre - centre) < 0)
      std::reverse(corners.begin() + 1, corners.end());
    CellFace face{corners.size() == 3 ? FaceKind::tri3 : FaceKind::quad4, corners};
    if (type.order == 2)
    {
      face.kind = corners.size() == 3 ? FaceKind::tri6 : FaceKind::quad8;
      for (size_t k = 0; k < corners.size(); ++k)
        face.nodes.push_back(edge_node(type, corners[k], corners[(k + 1) % corners.size()]));
    }
    type.faces.push_back(std::move(face));
  }
}

/// Edge midpoints of a quadratic cell's reference nodes, after its corners.
void add_edge_nodes(CellType& type)
{
  for (const auto& [a, b] : type.edges)
  {
    const Eigen::Vector3d m = 0.5 * (point(type, a) + point(type, b));
    type.reference_nodes.push_back({m.x(), m.y(), m.z()});
  }
}

const std::vector<std::array<double, 3>> hex_corners = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                                        {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
const std::vector<std::array<int, 2>> hex_edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
/// CalculiX's faces S1..S6 of C3D8 / C3D20 (1-based in its manual: 1-2-3-4, 5-8-7-6, 1-5-6-2,
/// 2-6-7-3, 3-7-8-4, 4-8-5-1).
const std::vector<Corners> hex_calculix_faces = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                                                 {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
const std::vector<std::array<double, 3>> tet_corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<std::array<int, 2>> tet_edges = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
/// C3D4 / C3D10: 1-2-3, 1-4-2, 2-4-3, 3-4-1.
const std::vector<Corners> tet_calculix_faces = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};

std::vector<int> identity(int n)
{
  std::vector<int> out(n);
  for (int i = 0; i < n; ++i)
    out[i] = i;
  return out;
}

CellType make_hex8()
{
  CellType t{.kind = CellKind::hex8,
             .name = "hex8",
             .n_nodes = 8,
             .n_corners = 8,
             .order = 1,
             .reference_nodes = hex_corners,
             .edges = hex_edges,
             .faces = {},
             .vtk_type = 12,
             .gmsh_type = 5,
             .gmsh_to_local = identity(8),
             .calculix_names = {"C3D8", "C3D8R", "C3D8I"},
             .vtk_to_local = identity(8)};
  add_faces(t, hex_calculix_faces);
  return t;
}

CellType make_hex20()
{
  // Gmsh's hexahedron edges: 01 03 04 12 15 23 26 37 45 47 56 67 (its node 8 + k on edge k).
  CellType t{.kind = CellKind::hex20,
             .name = "hex20",
             .n_nodes = 20,
             .n_corners = 8,
             .order = 2,
             .reference_nodes = hex_corners,
             .edges = hex_edges,
             .faces = {},
             .vtk_type = 25,
             .gmsh_type = 17,
             .gmsh_to_local = {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 16, 9, 17, 10, 18, 19, 12, 15, 13, 14},
             .calculix_names = {"C3D20", "C3D20R"},
             .vtk_to_local = identity(20)};
  add_edge_nodes(t);
  add_faces(t, hex_calculix_faces);
  return t;
}

CellType make_tet4()
{
  CellType t{.kind = CellKind::tet4,
             .name = "tet4",
             .n_nodes = 4,
             .n_corners = 4,
             .order = 1,
             .reference_nodes = tet_corners,
             .edges = tet_edges,
             .faces = {},
             .vtk_type = 10,
             .gmsh_type = 4,
             .gmsh_to_local = identity(4),
             .calculix_names = {"C3D4"},
             .vtk_to_local = identity(4)};
  add_faces(t, tet_calculix_faces);
  return t;
}

CellType make_tet10()
{
  // Gmsh's tetrahedron edges: 01 12 20 30 32 31: its nodes 8 and 9 are ours 9 and 8.
  CellType t{.kind = CellKind::tet10,
             .name = "tet10",
             .n_nodes = 10,
             .n_corners = 4,
             .order = 2,
             .reference_nodes = tet_corners,
             .edges = tet_edges,
             .faces = {},
             .vtk_type = 24,
             .gmsh_type = 11,
             .gmsh_to_local = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8},
             .calculix_names = {"C3D10"},
             .vtk_to_local = identity(10)};
  add_edge_nodes(t);
  add_faces(t, tet_calculix_faces);
  return t;
}

CellType make_wedge6()
{
  // Triangle (0,0), (1,0), (0,1) in (xi, eta) at zeta = -1 (nodes 0-2) and +1 (3-5), as Gmsh's
  // prism and CalculiX's C3D6 (faces 1-2-3, 4-5-6, 1-2-5-4, 2-3-6-5, 3-1-4-6). VTK's wedge has
  // its first triangle the other way round (normal away from the second).
  CellType t{.kind = CellKind::wedge6,
             .name = "wedge6",
             .n_nodes = 6,
             .n_corners = 6,
             .order = 1,
             .reference_nodes = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}},
             .edges = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}},
             .faces = {},
             .vtk_type = 13,
             .gmsh_type = 6,
             .gmsh_to_local = identity(6),
             .calculix_names = {"C3D6"},
             .vtk_to_local = {0, 2, 1, 3, 5, 4}};
  add_faces(t, {{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}});
  return t;
}

/// A 2D cell: corners counter-clockwise in the x-y plane, then the midpoints of the edges
/// c0 c1, c1 c2, ... (CalculiX's CPE3/4/6/8, Gmsh's and VTK's order); face (edge) k is CalculiX's
/// S(k+1) / P(k+1): corners k, k + 1, then its midpoint, so (x1 - x0) x e_z points outward.
CellType make_planar(CellKind kind, std::string_view name, int corners, int order, int vtk_type, int gmsh_type,
                     std::vector<std::string_view> calculix_names)
{
  static const std::vector<std::array<double, 3>> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  static const std::vector<std::array<double, 3>> quad = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const int n_nodes = order == 1 ? corners : 2 * corners;
  CellType t{.kind = kind,
             .name = name,
             .n_nodes = n_nodes,
             .n_corners = corners,
             .order = order,
             .dimension = 2,
             .reference_nodes = corners == 3 ? tri : quad,
             .edges = {},
             .faces = {},
             .vtk_type = vtk_type,
             .gmsh_type = gmsh_type,
             .gmsh_to_local = identity(n_nodes),
             .calculix_names = std::move(calculix_names),
             .vtk_to_local = identity(n_nodes)};
  for (int k = 0; k < corners; ++k)
  {
    t.edges.push_back({k, (k + 1) % corners});
    CellFace face{order == 1 ? FaceKind::line2 : FaceKind::line3, {k, (k + 1) % corners}};
    if (order == 2)
      face.nodes.push_back(corners + k);
    t.faces.push_back(std::move(face));
  }
  if (order == 2)
    add_edge_nodes(t);
  return t;
}

const std::array<CellType, 9>& table()
{
  // CalculiX's reduced-integration variants of the linear cells (C3D8R, CPE4R, ...) carry the
  // full rule here: one point with hourglass control is a different element, the full rule
  // the nearest we have (docs/elements.md).
  static const std::array<CellType, 9> types = {
      make_hex8(),
      make_tet4(),
      make_tet10(),
      make_hex20(),
      make_wedge6(),
      make_planar(CellKind::tri3, "tri3", 3, 1, 5, 2, {"CPE3", "CPS3", "CAX3"}),
      make_planar(CellKind::quad4, "quad4", 4, 1, 9, 3, {"CPE4", "CPS4", "CAX4", "CPE4R", "CPS4R", "CAX4R"}),
      make_planar(CellKind::tri6, "tri6", 3, 2, 22, 9, {"CPE6", "CPS6", "CAX6"}),
      make_planar(CellKind::quad8, "quad8", 4, 2, 23, 16, {"CPE8", "CPS8", "CAX8", "CPE8R", "CPS8R", "CAX8R"})};
  return types;
}
} // namespace

const CellType& cell_type(CellKind kind) { return table()[static_cast<size_t>(kind)]; }

const CellType* cell_type_of_calculix_name(std::string_view name)
{
  for (const CellType& t : table())
    if (std::ranges::find(t.calculix_names, name) != t.calculix_names.end())
      return &t;
  return nullptr;
}

const CellType* cell_type_of_gmsh_type(int gmsh_type)
{
  for (const CellType& t : table())
    if (t.gmsh_type == gmsh_type)
      return &t;
  return nullptr;
}
} // namespace feticon::mesh
