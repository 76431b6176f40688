#pragma once
/// @file HexMesh: nodes, hex8 cells, bodies, named node sets and named boundary-face sets.
///
/// Units: SI throughout feticon (m, N, Pa).
///
/// Cell node order is VTK's hexahedron order: nodes 0-3 on the face zeta = -1 and 4-7 on
/// zeta = +1, each face counter-clockwise seen from zeta = +1, i.e. reference coordinates
///   0 (-1,-1,-1) 1 (+1,-1,-1) 2 (+1,+1,-1) 3 (-1,+1,-1)
///   4 (-1,-1,+1) 5 (+1,-1,+1) 6 (+1,+1,+1) 7 (-1,+1,+1).
/// A boundary face is 4 node ids ordered so that (x1 - x0) x (x3 - x0) points out of its body.

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace feticon::mesh
{
using Cell = std::array<int32_t, 8>;
using Face = std::array<int32_t, 4>;

/// Local faces of a hex8 cell in VTK order, each oriented outward (see file comment).
inline constexpr std::array<std::array<int, 4>, 6> hex_faces = {{
    {0, 3, 2, 1}, // zeta = -1
    {4, 5, 6, 7}, // zeta = +1
    {0, 1, 5, 4}, // eta = -1
    {2, 3, 7, 6}, // eta = +1
    {0, 4, 7, 3}, // xi = -1
    {1, 2, 6, 5}, // xi = +1
}};

struct HexMesh
{
  /// Reference coordinates, one row per node (m).
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> nodes;
  std::vector<Cell> cells;
  /// Body index of every cell (into body_names). Bodies share no nodes.
  std::vector<int32_t> cell_body;
  std::vector<std::string> body_names;
  /// Named node sets (sorted, unique node ids).
  std::map<std::string, std::vector<int32_t>> node_sets;
  /// Named boundary-face sets, each face oriented outward from its body.
  std::map<std::string, std::vector<Face>> face_sets;

  int32_t n_nodes() const { return static_cast<int32_t>(nodes.rows()); }
  int32_t n_cells() const { return static_cast<int32_t>(cells.size()); }
  int32_t n_bodies() const { return static_cast<int32_t>(body_names.size()); }

  /// Node set by name; throws feticon::Error listing the available names if absent.
  const std::vector<int32_t>& node_set(const std::string& name) const;
  /// Face set by name; throws feticon::Error listing the available names if absent.
  const std::vector<Face>& face_set(const std::string& name) const;
  /// Sorted unique node ids of a face set.
  std::vector<int32_t> face_set_nodes(const std::string& name) const;
  /// Adds (or replaces) the node set `name` as the nodes of face set `faces_name`.
  void add_node_set_from_faces(const std::string& name, const std::string& faces_name);
};

/// Jacobian determinant of a cell's trilinear map at the cell centre (8 times the volume of
/// a parallelepiped); positive when the node order keeps the orientation. Mesh readers and
/// generators use it to reject inverted or degenerate cells.
/// The cells `cells` of `mesh` as a mesh of their own (a rank's piece of the output), nodes
/// renumbered in increasing mesh order; node sets are restricted to it, face sets dropped.
/// @param[out] node_of_local mesh node of every node of the piece
HexMesh submesh(const HexMesh& mesh, const std::vector<int32_t>& cells, std::vector<int32_t>& node_of_local);

double centre_jacobian_determinant(const HexMesh& mesh, const Cell& cell);
} // namespace feticon::mesh
