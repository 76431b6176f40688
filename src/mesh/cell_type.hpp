#pragma once
/// @file The cell types feticon knows and their topology (issue 38): node count, reference
/// node coordinates, faces as local node lists with their own face type, and the numbers and
/// names other formats give them. The shape functions and quadrature of each type are in
/// fem/reference_element.hpp.
///
/// Node order is CalculiX's / Abaqus's (C3D8, C3D4, C3D10, C3D20, C3D6): corners first, then
/// the edge midpoints of quadratic cells in the order of `edges`. VTK's differs for wedge6
/// (vtk_to_local), Gmsh's for the edge nodes of tet10 and hex20 (gmsh_to_local). Each face
/// lists its corners first, counter-clockwise seen from outside the cell (so that
/// (x1 - x0) x (x2 - x0) points out of the cell for a triangle, (x1 - x0) x (x3 - x0) for a
/// quadrilateral), then its edge midpoints in the order of its edges (c0 c1, c1 c2, ...).

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace feticon::mesh
{
enum class CellKind : uint8_t
{
  hex8,
  tet4,
  tet10,
  hex20,
  wedge6,
  // 2D cells in the x-y plane (CalculiX's CPE*, CPS*, CAX*; the planar formulation is the
  // mesh's, mesh::Planar).
  tri3,
  quad4,
  tri6,
  quad8
};
inline constexpr std::array<CellKind, 9> all_cell_kinds = {CellKind::hex8,  CellKind::tet4,   CellKind::tet10,
                                                           CellKind::hex20, CellKind::wedge6, CellKind::tri3,
                                                           CellKind::quad4, CellKind::tri6,   CellKind::quad8};
inline constexpr std::array<CellKind, 5> solid_cell_kinds = {CellKind::hex8, CellKind::tet4, CellKind::tet10,
                                                             CellKind::hex20, CellKind::wedge6};
inline constexpr std::array<CellKind, 4> planar_cell_kinds = {CellKind::tri3, CellKind::quad4, CellKind::tri6,
                                                              CellKind::quad8};

enum class FaceKind : uint8_t
{
  tri3,
  tri6,
  quad4,
  quad8,
  // The edges of 2D cells: corners first, then the midpoint (line3); ordered so that
  // (x1 - x0) x e_z points out of the body.
  line2,
  line3
};

/// Corners of a face type (2, 3 or 4) and all its nodes (2, 3, 4, 6 or 8).
constexpr int face_corners(FaceKind kind)
{
  constexpr std::array<int, 6> corners = {3, 3, 4, 4, 2, 2};
  return corners[static_cast<size_t>(kind)];
}
constexpr int face_nodes(FaceKind kind)
{
  constexpr std::array<int, 6> nodes = {3, 6, 4, 8, 2, 3};
  return nodes[static_cast<size_t>(kind)];
}
/// An edge of a 2D cell (line2, line3).
constexpr bool is_line(FaceKind kind) { return kind == FaceKind::line2 || kind == FaceKind::line3; }

struct CellFace
{
  FaceKind kind;
  std::vector<int> nodes; ///< local node numbers, corners first, outward (see file comment)
};

struct CellType
{
  CellKind kind;
  std::string_view name; ///< "hex8", "tet10", ...
  int n_nodes = 0;       ///< all nodes
  int n_corners = 0;     ///< the vertices (the linear cell's nodes)
  int order = 1;         ///< polynomial order of the geometry and the shape functions
  int dimension = 3;     ///< 3: a solid; 2: a cell in the x-y plane (reference nodes at zeta = 0)
  std::vector<std::array<double, 3>> reference_nodes; ///< per local node, in the reference cell
  std::vector<std::array<int, 2>> edges;              ///< corner pairs; quadratic cells' edge nodes in this order
  std::vector<CellFace> faces; ///< outward, in the order of the format's face numbers (S1, S2, ...)
  int vtk_type = 0;            ///< VTK_HEXAHEDRON 12, VTK_TETRA 10, ...
  int gmsh_type = 0;           ///< Gmsh's element type (5 hex8, 4 tet4, 11 tet10, 17 hex20, 6 prism)
  /// Gmsh's node k is local node gmsh_to_local[k].
  std::vector<int> gmsh_to_local;
  std::vector<std::string_view> calculix_names; ///< the element names of a CalculiX / Abaqus deck
  /// VTK's node k is local node vtk_to_local[k].
  std::vector<int> vtk_to_local;
};

/// Node count of a cell type (cell_type(kind).n_nodes, without the table lookup).
constexpr int cell_nodes(CellKind kind)
{
  constexpr std::array<int, 9> nodes = {8, 4, 10, 20, 6, 3, 4, 6, 8};
  return nodes[static_cast<size_t>(kind)];
}
/// Whether `kind` is a 2D cell (tri3, quad4, tri6, quad8).
constexpr bool is_planar(CellKind kind) { return kind >= CellKind::tri3; }

/// The table entry of `kind`.
const CellType& cell_type(CellKind kind);
/// The cell type of a CalculiX / Abaqus element name (case as in the deck, upper), or nullptr.
/// A 2D cell's name (CPE4, CPS8R, CAX6, ...) also gives its planar formulation (mesh::Planar).
const CellType* cell_type_of_calculix_name(std::string_view name);
/// The cell type of a Gmsh element type number, or nullptr.
const CellType* cell_type_of_gmsh_type(int gmsh_type);
} // namespace feticon::mesh
