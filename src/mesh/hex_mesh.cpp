#include "mesh/hex_mesh.hpp"

#include "common/error.hpp"

#include <algorithm>

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

const std::vector<int32_t>& HexMesh::node_set(const std::string& name) const
{
  auto it = node_sets.find(name);
  FETICON_CHECK(it != node_sets.end(),
                "unknown node set '" << name << "'; the mesh has: " << available_names(node_sets));
  return it->second;
}

const std::vector<Face>& HexMesh::face_set(const std::string& name) const
{
  auto it = face_sets.find(name);
  FETICON_CHECK(it != face_sets.end(),
                "unknown face set '" << name << "'; the mesh has: " << available_names(face_sets));
  return it->second;
}

std::vector<int32_t> HexMesh::face_set_nodes(const std::string& name) const
{
  std::vector<int32_t> ids;
  for (const Face& face : face_set(name))
    ids.insert(ids.end(), face.begin(), face.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

double centre_jacobian_determinant(const HexMesh& mesh, const Cell& cell)
{
  // Reference corners in VTK order (hex_mesh.hpp); at the centre dN_a/dxi_d = s_ad / 8.
  static constexpr int corner_signs[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d)
      jacobian.col(d) += 0.125 * corner_signs[a][d] * mesh.nodes.row(cell[a]).transpose();
  return jacobian.determinant();
}

void HexMesh::add_node_set_from_faces(const std::string& name, const std::string& faces_name)
{
  node_sets[name] = face_set_nodes(faces_name);
}
HexMesh submesh(const HexMesh& mesh, const std::vector<int32_t>& cells, std::vector<int32_t>& node_of_local)
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
  HexMesh piece;
  piece.body_names = mesh.body_names;
  piece.nodes.resize(static_cast<Eigen::Index>(node_of_local.size()), 3);
  for (size_t k = 0; k < node_of_local.size(); ++k)
    piece.nodes.row(static_cast<Eigen::Index>(k)) = mesh.nodes.row(node_of_local[k]);
  for (const int32_t c : cells)
  {
    Cell cell;
    for (int a = 0; a < 8; ++a)
      cell[a] = local_of_node[mesh.cells[c][a]];
    piece.cells.push_back(cell);
    piece.cell_body.push_back(mesh.cell_body[c]);
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
