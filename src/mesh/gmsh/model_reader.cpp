#include "mesh/gmsh/gmsh_operations.hpp"
#include "mesh/gmsh/gmsh_session.hpp"

#include "common/error.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace feticon::mesh
{
namespace
{
// Gmsh element types (Gmsh reference manual, "MSH file format": elm-type).
constexpr int gmsh_triangle = 2;
constexpr int gmsh_quadrangle = 3;
constexpr int gmsh_hexahedron = 5;

struct PhysicalGroup
{
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;
};

using GmshCell = std::array<std::size_t, 8>;
using SortedFace = std::array<int32_t, 4>;

struct SortedFaceHash
{
  std::size_t operator()(const SortedFace& face) const
  {
    std::size_t hash = 0;
    for (const int32_t id : face)
      hash = hash * 1000003u ^ static_cast<std::size_t>(id);
    return hash;
  }
};

/// The hexahedron faces with a given node set: the first (cell, local face) and how many.
struct FaceOwner
{
  int32_t cell = 0;
  int local_face = 0;
  int count = 0;
};

std::string element_type_name(int type)
{
  std::string name;
  int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
  std::vector<double> local_coordinates;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, n_nodes, local_coordinates, n_primary);
  return name + " (Gmsh type " + std::to_string(type) + ")";
}

std::string group_kind(int dim)
{
  static const std::array<const char*, 4> kinds = {"point", "curve", "surface", "volume"};
  return std::string("physical ") + kinds.at(dim);
}

/// All physical groups with their names and entities; checks names and emptiness.
std::vector<PhysicalGroup> read_groups(const std::string& where)
{
  gmsh::vectorpair dim_tags;
  gmsh::model::getPhysicalGroups(dim_tags);
  std::vector<PhysicalGroup> groups;
  std::map<std::string, std::pair<int, int>> seen;
  for (const auto& [dim, tag] : dim_tags)
  {
    PhysicalGroup group{dim, tag, "", {}};
    gmsh::model::getPhysicalName(dim, tag, group.name);
    FETICON_CHECK(!group.name.empty(),
                  where << ": " << group_kind(dim) << " " << tag
                        << " has no name; feticon refers to groups by name, e.g. Physical "
                           "Surface(\"load\") = {...}");
    const auto [it, inserted] = seen.emplace(group.name, std::pair{dim, tag});
    FETICON_CHECK(inserted,
                  where << ": physical name '" << group.name << "' is used twice (" << group_kind(it->second.first)
                        << " " << it->second.second << " and " << group_kind(dim) << " " << tag
                        << "); give every physical group its own name");
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, group.entities);
    groups.push_back(std::move(group));
  }
  FETICON_CHECK(std::any_of(groups.begin(), groups.end(), [](const PhysicalGroup& g) { return g.dim == 3; }),
                where << ": no 3D physical group; every body must be a Physical Volume(\"name\") "
                         "meshed with hexahedra");
  return groups;
}

/// Volume entities holding elements must belong to exactly one 3D group (one body).
void check_volume_entities(const std::vector<PhysicalGroup>& groups, const std::string& where)
{
  std::map<int, const PhysicalGroup*> body_of_entity;
  for (const PhysicalGroup& group : groups)
    if (group.dim == 3)
      for (const int entity : group.entities)
      {
        const auto [it, inserted] = body_of_entity.emplace(entity, &group);
        FETICON_CHECK(inserted,
                      where << ": volume " << entity << " is in two physical volumes, '" << it->second->name
                            << "' and '" << group.name << "'; a volume belongs to one body");
      }
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  for (const auto& [dim, entity] : volumes)
  {
    if (body_of_entity.contains(entity))
      continue;
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, dim, entity);
    FETICON_CHECK(types.empty(),
                  where << ": volume " << entity
                        << " has elements but is in no physical volume; add it to a body "
                           "(Physical Volume) or do not save it (Mesh.SaveAll = 0)");
  }
}

/// Hexahedra of the 3D group `group` as Gmsh node tags, with their Gmsh element tags.
void read_body_cells(const PhysicalGroup& group, const std::string& where, std::vector<GmshCell>& cells,
                     std::vector<std::size_t>& element_tags)
{
  const std::size_t n_before = cells.size();
  for (const int entity : group.entities)
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 3, entity);
    for (std::size_t t = 0; t < types.size(); ++t)
    {
      FETICON_CHECK(types[t] == gmsh_hexahedron,
                    where << ": physical volume '" << group.name << "' holds " << tags[t].size() << " elements of type "
                          << element_type_name(types[t])
                          << "; only 8-node hexahedra are supported; remesh with "
                             "Mesh.RecombineAll = 1 and transfinite volumes (or recombined "
                             "extrusions), first order");
      for (std::size_t e = 0; e < tags[t].size(); ++e)
      {
        GmshCell cell;
        std::copy_n(nodes[t].begin() + 8 * e, 8, cell.begin());
        cells.push_back(cell);
        element_tags.push_back(tags[t][e]);
      }
    }
  }
  FETICON_CHECK(cells.size() > n_before, where << ": physical volume '" << group.name << "' has no elements");
}

/// Bodies, nodes and cells from the 3D groups.
/// @return the local node id of every Gmsh node tag used by a hexahedron
std::unordered_map<std::size_t, int32_t> read_cells(const std::vector<PhysicalGroup>& groups, const std::string& where,
                                                    HexMesh& mesh)
{
  std::vector<GmshCell> gmsh_cells;
  std::vector<std::size_t> element_tags;
  for (const PhysicalGroup& group : groups)
    if (group.dim == 3)
    {
      read_body_cells(group, where, gmsh_cells, element_tags);
      mesh.body_names.push_back(group.name);
      mesh.cell_body.resize(gmsh_cells.size(), mesh.n_bodies() - 1);
    }

  // Node ids body by body, by increasing Gmsh tag, so each body's nodes are one range.
  std::unordered_map<std::size_t, int32_t> body_of_node;
  std::vector<std::vector<std::size_t>> body_nodes(mesh.body_names.size());
  for (std::size_t c = 0; c < gmsh_cells.size(); ++c)
    for (const std::size_t tag : gmsh_cells[c])
    {
      const int32_t body = mesh.cell_body[c];
      const auto [it, inserted] = body_of_node.emplace(tag, body);
      FETICON_CHECK(it->second == body,
                    where << ": bodies '" << mesh.body_names[it->second] << "' and '" << mesh.body_names[body]
                          << "' share Gmsh node " << tag
                          << "; bodies must be separate meshes (do not fragment or Coherence "
                             "volumes of different bodies)");
      if (inserted)
        body_nodes[body].push_back(tag);
    }
  const std::size_t n_nodes = body_of_node.size();
  constexpr auto max_local_id = static_cast<std::size_t>(std::numeric_limits<int32_t>::max());
  FETICON_CHECK(n_nodes <= max_local_id && gmsh_cells.size() <= max_local_id,
                where << ": " << n_nodes << " nodes and " << gmsh_cells.size() << " cells exceed int32 local ids");
  std::unordered_map<std::size_t, int32_t> local_id;
  local_id.reserve(n_nodes);
  for (std::vector<std::size_t>& tags : body_nodes)
  {
    std::sort(tags.begin(), tags.end());
    for (const std::size_t tag : tags)
      local_id.emplace(tag, static_cast<int32_t>(local_id.size()));
  }

  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, -1, -1, false, false);
  mesh.nodes.resize(static_cast<Eigen::Index>(n_nodes), 3);
  std::vector<bool> found(n_nodes, false);
  for (std::size_t n = 0; n < node_tags.size(); ++n)
    if (const auto it = local_id.find(node_tags[n]); it != local_id.end())
    {
      for (int d = 0; d < 3; ++d)
        mesh.nodes(it->second, d) = coordinates[3 * n + d];
      found[it->second] = true;
    }
  FETICON_CHECK(std::all_of(found.begin(), found.end(), [](bool f) { return f; }),
                where << ": hexahedra use nodes that the file does not define (corrupt file?)");

  mesh.cells.reserve(gmsh_cells.size());
  for (std::size_t c = 0; c < gmsh_cells.size(); ++c)
  {
    Cell cell;
    for (int a = 0; a < 8; ++a)
      cell[a] = local_id.at(gmsh_cells[c][a]);
    Cell sorted = cell;
    std::sort(sorted.begin(), sorted.end());
    FETICON_CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end(),
                  where << ": hexahedron (Gmsh element " << element_tags[c] << ") of body '"
                        << mesh.body_names[mesh.cell_body[c]] << "' repeats a node (degenerate)");
    mesh.cells.push_back(cell);
    // Distinct nodes at one place collapse an edge: the centre's Jacobian can stay positive,
    // but the cell is degenerate (its aspect ratio infinite).
    constexpr int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    double shortest = std::numeric_limits<double>::infinity(), longest = 0;
    for (const auto& e : edges)
    {
      const double length = (mesh.nodes.row(cell[e[0]]) - mesh.nodes.row(cell[e[1]])).norm();
      shortest = std::min(shortest, length);
      longest = std::max(longest, length);
    }
    FETICON_CHECK(shortest > 1e-9 * longest,
                  where << ": hexahedron (Gmsh element " << element_tags[c] << ") of body '"
                        << mesh.body_names[mesh.cell_body[c]] << "' has an edge of length " << shortest
                        << " (coincident nodes; degenerate)");
    const double det = centre_jacobian_determinant(mesh, cell);
    FETICON_CHECK(det > 0,
                  where << ": hexahedron (Gmsh element " << element_tags[c] << ") of body '"
                        << mesh.body_names[mesh.cell_body[c]] << "' is inverted or flat (Jacobian determinant " << det
                        << " at its centre); check the volume's orientation");
  }
  return local_id;
}

/// Face sets (and node sets of the same names) from the 2D groups.
void read_face_sets(const std::vector<PhysicalGroup>& groups, const std::string& where,
                    const std::unordered_map<std::size_t, int32_t>& local_id, HexMesh& mesh)
{
  std::unordered_map<SortedFace, FaceOwner, SortedFaceHash> owners;
  owners.reserve(6 * mesh.cells.size());
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (int f = 0; f < 6; ++f)
    {
      SortedFace key;
      for (int k = 0; k < 4; ++k)
        key[k] = mesh.cells[c][hex_faces[f][k]];
      std::sort(key.begin(), key.end());
      FaceOwner& owner = owners[key];
      if (owner.count++ == 0)
        owner = {c, f, 1};
    }

  for (const PhysicalGroup& group : groups)
  {
    if (group.dim != 2)
      continue;
    std::vector<Face>& faces = mesh.face_sets[group.name];
    for (const int entity : group.entities)
    {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, 2, entity);
      for (std::size_t t = 0; t < types.size(); ++t)
      {
        FETICON_CHECK(types[t] == gmsh_quadrangle,
                      where << ": physical surface '" << group.name << "' holds " << tags[t].size()
                            << " elements of type " << element_type_name(types[t])
                            << (types[t] == gmsh_triangle ? "; its volumes must be hexahedra, so recombine the surface "
                                                            "(Mesh.RecombineAll = 1)"
                                                          : "; only 4-node quadrangles (faces of hex8) are supported"));
        for (std::size_t e = 0; e < tags[t].size(); ++e)
        {
          SortedFace key;
          bool on_cells = true;
          for (int k = 0; k < 4; ++k)
          {
            const auto it = local_id.find(nodes[t][4 * e + k]);
            on_cells = on_cells && it != local_id.end();
            key[k] = on_cells ? it->second : -1;
          }
          std::sort(key.begin(), key.end());
          const auto owner = on_cells ? owners.find(key) : owners.end();
          FETICON_CHECK(owner != owners.end(),
                        where << ": quadrangle (Gmsh element " << tags[t][e] << ") of physical surface '" << group.name
                              << "' is not a face of any hexahedron of a body; the surface must "
                                 "bound a physical volume and share its mesh");
          FETICON_CHECK(owner->second.count == 1,
                        where << ": quadrangle (Gmsh element " << tags[t][e] << ") of physical surface '" << group.name
                              << "' lies between two hexahedra; face sets must be on "
                              << "the boundary of a body");
          const Cell& cell = mesh.cells[owner->second.cell];
          const auto& local = hex_faces[owner->second.local_face];
          faces.push_back({cell[local[0]], cell[local[1]], cell[local[2]], cell[local[3]]});
        }
      }
    }
    FETICON_CHECK(!faces.empty(), where << ": physical surface '" << group.name << "' has no elements");
    mesh.add_node_set_from_faces(group.name, group.name);
  }
}

/// Node sets from the 0D and 1D groups.
void read_node_sets(const std::vector<PhysicalGroup>& groups, const std::string& where,
                    const std::unordered_map<std::size_t, int32_t>& local_id, HexMesh& mesh)
{
  for (const PhysicalGroup& group : groups)
  {
    if (group.dim > 1)
      continue;
    std::vector<std::size_t> tags;
    std::vector<double> coordinates;
    gmsh::model::mesh::getNodesForPhysicalGroup(group.dim, group.tag, tags, coordinates);
    FETICON_CHECK(!tags.empty(), where << ": " << group_kind(group.dim) << " '" << group.name << "' has no nodes");
    std::vector<int32_t>& ids = mesh.node_sets[group.name];
    for (const std::size_t tag : tags)
    {
      const auto it = local_id.find(tag);
      FETICON_CHECK(it != local_id.end(),
                    where << ": Gmsh node " << tag << " of " << group_kind(group.dim) << " '" << group.name
                          << "' is not a node of any hexahedron of a body");
      ids.push_back(it->second);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
}

HexMesh read_open_model(const std::string& where)
{
  const std::vector<PhysicalGroup> groups = read_groups(where);
  check_volume_entities(groups, where);
  HexMesh mesh;
  const std::unordered_map<std::size_t, int32_t> local_id = read_cells(groups, where, mesh);
  read_face_sets(groups, where, local_id, mesh);
  read_node_sets(groups, where, local_id, mesh);
  return mesh;
}

/// Gmsh messages may span lines; feticon errors are one line.
std::string one_line(std::string text)
{
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}
} // namespace

HexMesh read_model_with_gmsh(const std::filesystem::path& path, const std::string& where)
{
  const char* stage = "opening";
  try
  {
    GmshSession session;
    gmsh::open(path.string());
    stage = "reading the model of";
    return read_open_model(where);
  }
  catch (const Error&)
  {
    throw;
  }
  catch (const std::string& message)
  {
    // Gmsh 4.8 throws its error message as a std::string (General.AbortOnError = 2).
    throw Error(where + ": Gmsh failed " + stage + " it (truncated or corrupt file?): " + one_line(message));
  }
  catch (const std::exception& exception)
  {
    throw Error(where + ": Gmsh failed " + stage + " it: " + one_line(exception.what()));
  }
  catch (...)
  {
    throw Error(where + ": Gmsh failed " + stage + " it (unknown error; truncated or corrupt?)");
  }
}
} // namespace feticon::mesh
