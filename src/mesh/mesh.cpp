#include "mesh/mesh.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <map>
#include <numbers>

namespace feticon::mesh
{
namespace
{
template <class Map>
std::string available_names(const Map& map)
{
  std::string names;
  for (const auto& [name, value] : map)
    names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "(none)" : names;
}
} // namespace

const std::vector<int32_t>& Mesh::node_set(const std::string& name) const
{
  auto it = node_sets.find(name);
  FETICON_CHECK(it != node_sets.end(),
                "unknown node set '" << name << "'; the mesh has: " << available_names(node_sets));
  return it->second;
}

const std::vector<Face>& Mesh::face_set(const std::string& name) const
{
  auto it = face_sets.find(name);
  FETICON_CHECK(it != face_sets.end(),
                "unknown face set '" << name << "'; the mesh has: " << available_names(face_sets));
  return it->second;
}

std::vector<int32_t> Mesh::face_set_nodes(const std::string& name) const
{
  std::vector<int32_t> ids;
  for (const Face& face : face_set(name))
    ids.insert(ids.end(), face.begin(), face.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

double Planar::measure(const Eigen::Vector3d& x) const
{
  switch (kind)
  {
  case PlanarKind::none:
    return 1;
  case PlanarKind::plane_strain:
  case PlanarKind::plane_stress:
    return thickness;
  case PlanarKind::axisymmetric:
    return 2 * std::numbers::pi * x(0);
  }
  return 1;
}

bool Mesh::any_axisymmetric() const
{
  if (body_planar.empty())
    return planar.kind == PlanarKind::axisymmetric;
  return std::ranges::any_of(body_planar, [](const Planar& p) { return p.kind == PlanarKind::axisymmetric; });
}

void Mesh::set_body_planar(std::vector<Planar> per_body)
{
  FETICON_CHECK(std::ssize(per_body) == n_bodies() && !per_body.empty(),
                "set_body_planar: " << per_body.size() << " formulations for " << n_bodies() << " bodies");
  planar = per_body.front();
  body_planar = std::move(per_body);
  planar_body_of_node.assign(static_cast<size_t>(n_nodes()), -1);
  for (int32_t c = 0; c < n_cells(); ++c)
    for (const int32_t n : cells[c])
      if (planar_body_of_node[n] < 0)
        planar_body_of_node[n] = cell_body[c];
  for (int32_t& body : planar_body_of_node)
    body = std::max(body, 0); // a node without cells (a reference node) takes the first body's
}

std::string_view planar_name(PlanarKind kind)
{
  constexpr std::array<std::string_view, 4> names = {"3D", "plane strain", "plane stress", "axisymmetric"};
  return names[static_cast<size_t>(kind)];
}

std::vector<SharedBodies> bodies_sharing_nodes(const Mesh& mesh)
{
  // The body of every node's first cell, and the other bodies of the few nodes that have some.
  std::vector<int32_t> first_body(mesh.n_nodes(), -1);
  std::map<int32_t, std::vector<int32_t>> other_bodies;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (const int32_t n : mesh.cells[c])
    {
      const int32_t body = mesh.cell_body[c];
      if (first_body[n] < 0)
        first_body[n] = body;
      else if (first_body[n] != body)
      {
        std::vector<int32_t>& others = other_bodies[n];
        if (std::find(others.begin(), others.end(), body) == others.end())
          others.push_back(body);
      }
    }
  std::map<std::pair<int32_t, int32_t>, int32_t> first_node;
  for (auto& [n, bodies] : other_bodies)
  {
    bodies.push_back(first_body[n]);
    for (size_t i = 0; i < bodies.size(); ++i)
      for (size_t j = i + 1; j < bodies.size(); ++j)
        first_node.emplace(std::minmax(bodies[i], bodies[j]), n); // n increases: the first stays
  }
  std::vector<SharedBodies> shared;
  for (const auto& [bodies, node] : first_node)
    shared.push_back({bodies.first, bodies.second, node});
  return shared;
}

double centre_jacobian_determinant(const Mesh& mesh, int32_t c)
{
  const std::span<const int32_t> cell = mesh.cells[c];
  const auto x = [&](int a) -> Eigen::Vector3d { return mesh.nodes.row(cell[a]).transpose(); };
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
  switch (mesh.cells.kind(c))
  {
  case CellKind::hex8:
  case CellKind::hex20:
  {
    // Reference corners in VTK order (mesh.hpp); at the centre dN_a/dxi_d = s_ad / 8. The
    // corners of a hex20 suffice for its orientation.
    static constexpr int corner_signs[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    for (int a = 0; a < 8; ++a)
      for (int d = 0; d < 3; ++d)
        jacobian.col(d) += 0.125 * corner_signs[a][d] * x(a);
    break;
  }
  case CellKind::tet4:
  case CellKind::tet10:
    jacobian << x(1) - x(0), x(2) - x(0), x(3) - x(0);
    break;
  case CellKind::tri3:
  case CellKind::tri6:
    // A 2D cell's third direction is e_z: positive when its corners run counter-clockwise.
    jacobian << x(1) - x(0), x(2) - x(0), Eigen::Vector3d::UnitZ();
    break;
  case CellKind::quad4:
  case CellKind::quad8:
    jacobian << 0.5 * (x(1) - x(0) + x(2) - x(3)), 0.5 * (x(3) - x(0) + x(2) - x(1)), Eigen::Vector3d::UnitZ();
    break;
  case CellKind::wedge6:
    // The linear wedge's derivatives at (1/3, 1/3, 0) (cell_type.hpp's reference wedge).
    jacobian << 0.5 * (x(1) - x(0) + x(4) - x(3)), 0.5 * (x(2) - x(0) + x(5) - x(3)),
        (x(3) - x(0) + x(4) - x(1) + x(5) - x(2)) / 6.0;
    break;
  }
  return jacobian.determinant();
}

void CellList::add(CellKind kind, std::span<const int32_t> nodes)
{
  FETICON_ASSERT(static_cast<int>(nodes.size()) == cell_nodes(kind), "cell node count");
  _kinds.push_back(kind);
  _nodes.insert(_nodes.end(), nodes.begin(), nodes.end());
  _offsets.push_back(static_cast<int64_t>(_nodes.size()));
}

void CellList::reserve(size_t n_cells, size_t n_node_entries)
{
  _kinds.reserve(n_cells);
  _offsets.reserve(n_cells + 1);
  _nodes.reserve(n_node_entries);
}

bool CellList::all_of_kind(CellKind kind) const
{
  return std::ranges::all_of(_kinds, [kind](CellKind k) { return k == kind; });
}

std::string describe_cells(const CellList& cells)
{
  std::array<size_t, all_cell_kinds.size()> count{};
  for (size_t c = 0; c < cells.size(); ++c)
    ++count[static_cast<size_t>(cells.kind(c))];
  std::string types;
  const bool one_type = std::ranges::count(count, 0u) == static_cast<std::ptrdiff_t>(count.size()) - 1;
  for (const CellKind kind : all_cell_kinds)
    if (const size_t n = count[static_cast<size_t>(kind)]; n > 0)
      types +=
          (types.empty() ? "" : ", ") + (one_type ? "" : std::to_string(n) + " ") + std::string(cell_type(kind).name);
  return std::to_string(cells.size()) + " cells (" + types + ")";
}

Face::Face(FaceKind face_kind, std::span<const int32_t> face_nodes) : kind(face_kind)
{
  FETICON_ASSERT(static_cast<int>(face_nodes.size()) == mesh::face_nodes(face_kind), "face node count");
  std::ranges::copy(face_nodes, nodes.begin());
}

std::array<int32_t, 4> sorted_corners(const Face& face)
{
  std::array<int32_t, 4> key{-1, -1, -1, -1};
  std::copy_n(face.begin(), face.n_corners(), key.begin());
  std::sort(key.begin(), key.end());
  return key;
}

Face cell_face(CellKind kind, std::span<const int32_t> cell_nodes, int k)
{
  const CellFace& local = cell_type(kind).faces[k];
  Face face;
  face.kind = local.kind;
  for (size_t a = 0; a < local.nodes.size(); ++a)
    face.nodes[a] = cell_nodes[local.nodes[a]];
  return face;
}

void Mesh::add_node_set_from_faces(const std::string& name, const std::string& faces_name)
{
  node_sets[name] = face_set_nodes(faces_name);
}
Mesh submesh(const Mesh& mesh, const std::vector<int32_t>& cells, std::vector<int32_t>& node_of_local)
{
  std::vector<int32_t> local_of_node(mesh.n_nodes(), -1);
  for (const int32_t c : cells)
    for (const int32_t n : mesh.cells[c])
      local_of_node[n] = 0;
  node_of_local.clear();
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
    if (local_of_node[n] == 0)
    {
      local_of_node[n] = static_cast<int32_t>(node_of_local.size());
      node_of_local.push_back(n);
    }
  Mesh piece;
  piece.body_names = mesh.body_names;
  piece.planar = mesh.planar;
  piece.body_planar = mesh.body_planar;
  piece.nodes.resize(static_cast<Eigen::Index>(node_of_local.size()), 3);
  for (size_t k = 0; k < node_of_local.size(); ++k)
    piece.nodes.row(static_cast<Eigen::Index>(k)) = mesh.nodes.row(node_of_local[k]);
  if (!mesh.body_planar.empty())
    for (const int32_t n : node_of_local)
      piece.planar_body_of_node.push_back(mesh.planar_body_of_node[n]);
  std::vector<int32_t> cell;
  for (const int32_t c : cells)
  {
    cell.clear();
    for (const int32_t n : mesh.cells[c])
      cell.push_back(local_of_node[n]);
    piece.cells.add(mesh.cells.kind(c), cell);
    piece.cell_body.push_back(mesh.cell_body[c]);
    if (!mesh.reduced_integration.empty())
      piece.reduced_integration.push_back(mesh.reduced_integration[c]);
  }
  for (const auto& [name, ids] : mesh.node_sets)
  {
    std::vector<int32_t>& local = piece.node_sets[name];
    for (const int32_t n : ids)
      if (local_of_node[n] >= 0)
        local.push_back(local_of_node[n]);
  }
  return piece;
}
} // namespace feticon::mesh
