#pragma once
/// @file Mesh: nodes, cells of the types of mesh/cell_type.hpp, bodies, named node sets and
/// named boundary-face sets.
///
/// Units: SI throughout feticon (m, N, Pa).
///
/// A cell is its type and its nodes in the type's local order (CalculiX's, cell_type.hpp); for
/// hex8 that is also VTK's hexahedron order, nodes 0-3 on the face zeta = -1 and 4-7 on
/// zeta = +1, each face counter-clockwise seen from zeta = +1:
///   0 (-1,-1,-1) 1 (+1,-1,-1) 2 (+1,+1,-1) 3 (-1,+1,-1)
///   4 (-1,-1,+1) 5 (+1,-1,+1) 6 (+1,+1,+1) 7 (-1,+1,+1).
/// Cells of several types live in one CellList: the node lists back to back with offsets, as
/// VTK's and DOLFINx's adjacency lists, so a hex8 mesh pays 9 bytes a cell for the generality.
/// A boundary face is its face type and its nodes, corners first, ordered so that
/// (x1 - x0) x (x_last corner - x0) points out of its body, then its edge nodes (quadratic faces).

#include "mesh/cell_type.hpp"

#include <array>
#include <cstdint>
#include <iterator>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace feticon::mesh
{
/// Cells of any types: cell c is kind(c) with the nodes (*this)[c].
class CellList
{
public:
  /// Appends a cell; nodes.size() must be the type's node count.
  void add(CellKind kind, std::span<const int32_t> nodes);
  void reserve(size_t n_cells, size_t n_node_entries);

  std::span<const int32_t> operator[](size_t c) const
  {
    return {_nodes.data() + _offsets[c], static_cast<size_t>(_offsets[c + 1] - _offsets[c])};
  }
  std::span<int32_t> nodes_of(size_t c)
  {
    return {_nodes.data() + _offsets[c], static_cast<size_t>(_offsets[c + 1] - _offsets[c])};
  }
  CellKind kind(size_t c) const { return _kinds[c]; }
  size_t size() const { return _kinds.size(); }
  bool empty() const { return _kinds.empty(); }
  /// Node entries of all cells together.
  size_t n_node_entries() const { return _nodes.size(); }
  /// Whether every cell is of type `kind` (true for an empty list).
  bool all_of_kind(CellKind kind) const;

  bool operator==(const CellList& other) const = default;

  class Iterator
  {
  public:
    using iterator_category = std::input_iterator_tag;
    using value_type = std::span<const int32_t>;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = std::span<const int32_t>;

    Iterator(const CellList* list, size_t c) : _list(list), _c(c) {}
    std::span<const int32_t> operator*() const { return (*_list)[_c]; }
    Iterator& operator++()
    {
      ++_c;
      return *this;
    }
    Iterator operator++(int)
    {
      Iterator before = *this;
      ++_c;
      return before;
    }
    bool operator==(const Iterator& other) const = default;

  private:
    const CellList* _list;
    size_t _c;
  };
  Iterator begin() const { return {this, 0}; }
  Iterator end() const { return {this, size()}; }

private:
  std::vector<CellKind> _kinds;
  std::vector<int64_t> _offsets{0};
  std::vector<int32_t> _nodes;
};

/// A boundary face: its type and nodes (see file comment). Converts from the four corners of a
/// quad4, the form hex8 meshes build.
struct Face
{
  FaceKind kind = FaceKind::quad4;
  std::array<int32_t, 8> nodes{};

  Face() = default;
  Face(int32_t a, int32_t b, int32_t c, int32_t d) : nodes{a, b, c, d} {}
  Face(FaceKind face_kind, std::span<const int32_t> face_nodes);

  int size() const { return face_nodes(kind); }
  int n_corners() const { return face_corners(kind); }
  int32_t operator[](int a) const { return nodes[a]; }
  int32_t& operator[](int a) { return nodes[a]; }
  const int32_t* begin() const { return nodes.data(); }
  const int32_t* end() const { return nodes.data() + size(); }
  int32_t* begin() { return nodes.data(); }
  int32_t* end() { return nodes.data() + size(); }
  bool operator==(const Face& other) const = default;
};

/// The nodes of one hex8 cell, the form the structured generators build.
using Hex8Nodes = std::array<int32_t, 8>;

/// Local faces of a hex8 cell in VTK order, each oriented outward (see file comment).
inline constexpr std::array<std::array<int, 4>, 6> hex_faces = {{
    {0, 3, 2, 1}, // zeta = -1
    {4, 5, 6, 7}, // zeta = +1
    {0, 1, 5, 4}, // eta = -1
    {2, 3, 7, 6}, // eta = +1
    {0, 4, 7, 3}, // xi = -1
    {1, 2, 6, 5}, // xi = +1
}};

/// A face's corners sorted, -1 after a triangle's three: the same key from every cell that has
/// the face, whatever its node order there (partition graphs, readers, the export).
std::array<int32_t, 4> sorted_corners(const Face& face);

/// Face `k` (cell_type(kind).faces order, CalculiX's S1, S2, ...) of a cell, outward.
Face cell_face(CellKind kind, std::span<const int32_t> cell_nodes, int k);

/// The cells by type, e.g. "1230 cells (tet10)" or "800 cells (720 hex8, 80 wedge6)".
std::string describe_cells(const CellList& cells);

/// How a mesh of 2D cells (mesh/cell_type.hpp: in the x-y plane, u_z eliminated) stands for a
/// solid: plane strain (eps_zz = 0) or plane stress (sigma_zz = 0) of a slab `thickness` thick,
/// or a solid of revolution about the y axis (x = r, y = the axial coordinate; the hoop strain
/// u_r / r), whose loads, forces and reactions are those of the whole circle (2 pi r per unit
/// length of its generating curve), as CalculiX's for CAX cells.
enum class PlanarKind : uint8_t
{
  none, ///< a 3D mesh
  plane_strain,
  plane_stress,
  axisymmetric
};
struct Planar
{
  PlanarKind kind = PlanarKind::none;
  double thickness = 1; ///< plane strain and plane stress (m); CalculiX's default 1

  /// The out-of-plane measure at point x: the thickness, or 2 pi x(0) in axisymmetry (m); 1 for
  /// a 3D mesh. A volume is an area times it, an area a length times it.
  double measure(const Eigen::Vector3d& x) const;
  bool operator==(const Planar& other) const = default;
};
/// "plane strain", "plane stress", "axisymmetric", "3D".
std::string_view planar_name(PlanarKind kind);

struct Mesh
{
  /// Reference coordinates, one row per node (m).
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> nodes;
  CellList cells;
  /// Body index of every cell (into body_names). Bodies may share nodes: a connected mesh of
  /// several materials is several bodies glued at the nodes of their interfaces, as subdomains
  /// are (a deck's sections; a problem file's bodies of sections).
  std::vector<int32_t> cell_body;
  std::vector<std::string> body_names;
  /// Named node sets (sorted, unique node ids).
  std::map<std::string, std::vector<int32_t>> node_sets;
  /// Named boundary-face sets, each face oriented outward from its body.
  std::map<std::string, std::vector<Face>> face_sets;
  /// Per cell: integrated with the reduced rule (hex20: CalculiX's C3D20R, 2x2x2 Gauss points;
  /// fem/reference_element.hpp). Empty when no cell is.
  std::vector<char> reduced_integration;
  /// The formulation of the 2D cells (all cells are 2D when kind != none, none are otherwise);
  /// every body's unless body_planar says otherwise.
  Planar planar = {};
  /// Per body, when the bodies of a 2D model differ (a deck mixing CPS or CPE cells with CAX
  /// cells, or sections of several thicknesses); empty when every body is `planar`. Plane and
  /// axisymmetric bodies in one model exchange forces as in CalculiX (solidsections.f: beside
  /// CAX cells a plane section's thickness is that of the full circle, as the axisymmetric
  /// bodies' forces are), so nothing is scaled.
  std::vector<Planar> body_planar;
  /// With body_planar: per node, the body whose formulation the edges through it take (that of
  /// its first cell). Set with body_planar by set_body_planar.
  std::vector<int32_t> planar_body_of_node;

  /// Whether cell `cell` is integrated with the reduced rule.
  bool reduced(int32_t cell) const { return !reduced_integration.empty() && reduced_integration[cell] != 0; }

  int32_t n_nodes() const { return static_cast<int32_t>(nodes.rows()); }
  /// The unknowns of a node: 2 for a 2D mesh (u_z eliminated), 3 otherwise (a plane-strain hex
  /// layer counts its eliminated u_z, as it always has).
  int dofs_per_node() const { return planar.kind == PlanarKind::none ? 3 : 2; }
  int32_t n_cells() const { return static_cast<int32_t>(cells.size()); }
  int32_t n_bodies() const { return static_cast<int32_t>(body_names.size()); }
  const Planar& planar_of_body(int32_t body) const { return body_planar.empty() ? planar : body_planar[body]; }
  const Planar& planar_of_cell(int32_t cell) const { return planar_of_body(cell_body[cell]); }
  const Planar& planar_of_node(int32_t node) const
  {
    return body_planar.empty() ? planar : body_planar[planar_body_of_node[node]];
  }
  /// Whether some body is axisymmetric (a subdomain or model with one keeps the axial
  /// translation of its rigid motions only).
  bool any_axisymmetric() const;
  /// Sets body_planar (one per body, all 2D) and planar_body_of_node from the cells; `planar`
  /// becomes the first body's.
  void set_body_planar(std::vector<Planar> per_body);

  /// Node set by name; throws feticon::Error listing the available names if absent.
  const std::vector<int32_t>& node_set(const std::string& name) const;
  /// Face set by name; throws feticon::Error listing the available names if absent.
  const std::vector<Face>& face_set(const std::string& name) const;
  /// Sorted unique node ids of a face set.
  std::vector<int32_t> face_set_nodes(const std::string& name) const;
  /// Adds (or replaces) the node set `name` as the nodes of face set `faces_name`.
  void add_node_set_from_faces(const std::string& name, const std::string& faces_name);
};

/// The cells `cells` of `mesh` as a mesh of their own (a rank's piece of the output), nodes
/// renumbered in increasing mesh order; node sets are restricted to it, face sets dropped.
/// @param[out] node_of_local mesh node of every node of the piece
Mesh submesh(const Mesh& mesh, const std::vector<int32_t>& cells, std::vector<int32_t>& node_of_local);

/// Two bodies that share nodes, and the first (lowest) node they share.
struct SharedBodies
{
  int32_t first_body;
  int32_t second_body; ///< > first_body
  int32_t node;
};
/// Every pair of bodies that share nodes, ordered by (first_body, second_body).
std::vector<SharedBodies> bodies_sharing_nodes(const Mesh& mesh);

/// Jacobian determinant of a cell's map at the centre of its reference cell; positive when the
/// node order keeps the orientation (for hex8, 8 times the volume of a parallelepiped). Mesh
/// readers and generators use it to reject inverted or degenerate cells.
double centre_jacobian_determinant(const Mesh& mesh, int32_t cell);
} // namespace feticon::mesh
