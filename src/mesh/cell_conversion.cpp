#include "mesh/cell_conversion.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace feticon::mesh
{
namespace
{
/// Kuhn's six tetrahedra about the diagonal 0-6, and two wedges split along 0-2 (local hex8
/// nodes; each positively oriented in a positively oriented hexahedron).
const std::vector<std::vector<int>> kuhn_tets = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                                 {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
const std::vector<std::vector<int>> wedges = {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 4, 6, 7}};
const std::vector<std::vector<int>> whole = {{0, 1, 2, 3, 4, 5, 6, 7}};

/// Edge midpoint nodes, one per edge, appended to the node array.
class EdgeNodes
{
public:
  EdgeNodes(Mesh& mesh, const EdgeNodePlacement& place) : _mesh(mesh), _place(place) {}
  int32_t at(int32_t a, int32_t b)
  {
    const auto key = std::minmax(a, b);
    const auto [it, fresh] = _ids.emplace(key, static_cast<int32_t>(_points.size()) + _mesh.n_nodes());
    if (fresh)
    {
      const Eigen::Vector3d x_a = _mesh.nodes.row(a).transpose(), x_b = _mesh.nodes.row(b).transpose();
      _points.push_back(_place ? _place(x_a, x_b) : Eigen::Vector3d(0.5 * (x_a + x_b)));
    }
    return it->second;
  }
  /// Appends the new nodes to the mesh.
  void finish()
  {
    const int32_t n = _mesh.n_nodes();
    _mesh.nodes.conservativeResize(n + static_cast<Eigen::Index>(_points.size()), 3);
    for (size_t k = 0; k < _points.size(); ++k)
      _mesh.nodes.row(n + static_cast<Eigen::Index>(k)) = _points[k].transpose();
  }
  const std::map<std::pair<int32_t, int32_t>, int32_t>& ids() const { return _ids; }

private:
  Mesh& _mesh;
  const EdgeNodePlacement& _place;
  std::map<std::pair<int32_t, int32_t>, int32_t> _ids;
  std::vector<Eigen::Vector3d> _points;
};

/// The new cells' faces that lie inside each old face of the sets.
void convert_face_sets(const Mesh& hex, Mesh& out)
{
  std::map<std::array<int32_t, 4>, std::pair<Face, int>> faces;
  for (int32_t c = 0; c < out.n_cells(); ++c)
    for (size_t k = 0; k < cell_type(out.cells.kind(c)).faces.size(); ++k)
    {
      const Face face = cell_face(out.cells.kind(c), out.cells[c], static_cast<int>(k));
      auto [it, fresh] = faces.emplace(sorted_corners(face), std::pair{face, 0});
      ++it->second.second;
    }
  // Boundary faces by their smallest corner, to find those inside an old face quickly.
  std::multimap<int32_t, const Face*> boundary;
  for (const auto& [key, face_count] : faces)
    if (face_count.second == 1)
      boundary.emplace(
          *std::ranges::min_element(face_count.first.begin(), face_count.first.begin() + face_count.first.n_corners()),
          &face_count.first);
  for (const auto& [name, old_faces] : hex.face_sets)
  {
    std::vector<Face>& converted = out.face_sets[name];
    for (const Face& old : old_faces)
    {
      const std::set<int32_t> corners(old.begin(), old.end());
      for (const int32_t first : corners)
        for (auto [it, end] = boundary.equal_range(first); it != end; ++it)
          if (std::all_of(it->second->begin(), it->second->begin() + it->second->n_corners(),
                          [&](int32_t n) { return corners.contains(n); }))
            converted.push_back(*it->second);
    }
  }
}
} // namespace

Mesh convert_hex8_mesh(const Mesh& hex, CellKind kind, const EdgeNodePlacement& place)
{
  FETICON_CHECK(hex.cells.all_of_kind(CellKind::hex8), "convert_hex8_mesh: the mesh has cells other than hex8");
  Mesh out;
  out.nodes = hex.nodes;
  out.body_names = hex.body_names;
  out.node_sets = hex.node_sets;
  const CellType& type = cell_type(kind);
  const auto& parts = kind == CellKind::tet4 || kind == CellKind::tet10 ? kuhn_tets
      : kind == CellKind::wedge6                                        ? wedges
                                                                        : whole;
  EdgeNodes edge_nodes(out, place);
  std::vector<int32_t> cell;
  for (int32_t c = 0; c < hex.n_cells(); ++c)
    for (const std::vector<int>& part : parts)
    {
      cell.clear();
      for (const int local : part)
        cell.push_back(hex.cells[c][local]);
      if (type.order == 2)
        for (const auto& [a, b] : type.edges)
          cell.push_back(edge_nodes.at(cell[a], cell[b]));
      out.cells.add(kind, cell);
      out.cell_body.push_back(hex.cell_body[c]);
    }
  edge_nodes.finish();
  // Node sets gain the edge nodes between two of their nodes (a support on a face holds the
  // face's edge nodes too).
  for (auto& [name, ids] : out.node_sets)
  {
    const std::set<int32_t> members(ids.begin(), ids.end());
    for (const auto& [edge, id] : edge_nodes.ids())
      if (members.contains(edge.first) && members.contains(edge.second))
        ids.push_back(id);
    std::ranges::sort(ids);
  }
  convert_face_sets(hex, out);
  return out;
}
} // namespace feticon::mesh
