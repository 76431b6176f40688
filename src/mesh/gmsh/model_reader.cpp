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
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace feticon::mesh
{
namespace
{
/// Gmsh's boundary element types (Gmsh reference manual, "MSH file format": elm-type) as the
/// face types of the cells' faces.
std::optional<FaceKind> face_kind_of_gmsh_type(int type)
{
  switch (type)
  {
  case 2:
    return FaceKind::tri3;
  case 3:
    return FaceKind::quad4;
  case 9:
    return FaceKind::tri6;
  case 16:
    return FaceKind::quad8;
  case 1:
    return FaceKind::line2;
  case 8:
    return FaceKind::line3;
  default:
    return std::nullopt;
  }
}

constexpr std::array<std::string_view, 6> face_kind_names = {"tri3", "tri6", "quad4", "quad8", "line2", "line3"};

struct PhysicalGroup
{
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;
};

/// A volume element: its type and Gmsh node tags in feticon's local order.
struct GmshCell
{
  CellKind kind;
  std::array<std::size_t, 20> tags;
  std::span<const std::size_t> nodes() const { return {tags.data(), static_cast<std::size_t>(cell_nodes(kind))}; }
};
/// A face's corners sorted, -1 after a triangle's three: the key that finds a face from any cell.
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

/// The cell faces with a given node set: the first (cell, local face) and how many.
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
  FETICON_CHECK(std::any_of(groups.begin(), groups.end(), [](const PhysicalGroup& g) { return g.dim >= 2; }),
                where << ": no 3D or 2D physical group; every body must be a Physical Volume(\"name\") "
                         "meshed with tetrahedra, hexahedra or prisms (or, in a 2D model, a Physical "
                         "Surface(\"name\") meshed with triangles or quadrangles)");
  return groups;
}

/// The model's dimension: 3 if it has a physical volume (the bodies) or a meshed volume, else 2
/// (the bodies are its physical surfaces, its face sets the physical curves).
int model_dimension(const std::vector<PhysicalGroup>& groups, const std::string& where)
{
  if (std::ranges::any_of(groups, [](const PhysicalGroup& g) { return g.dim == 3; }))
    return 3;
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3, -1);
  FETICON_CHECK(types.empty(),
                where << ": no 3D physical group, but volume elements; every body must be a Physical "
                         "Volume(\"name\") meshed with tetrahedra, hexahedra or prisms");
  return 2;
}

/// Entities of the model's dimension holding elements must belong to exactly one group of it
/// (one body).
void check_body_entities(const std::vector<PhysicalGroup>& groups, int dim, const std::string& where)
{
  const std::string entity_kind = dim == 3 ? "volume" : "surface";
  std::map<int, const PhysicalGroup*> body_of_entity;
  for (const PhysicalGroup& group : groups)
    if (group.dim == dim)
      for (const int entity : group.entities)
      {
        const auto [it, inserted] = body_of_entity.emplace(entity, &group);
        FETICON_CHECK(inserted,
                      where << ": " << entity_kind << " " << entity << " is in two " << group_kind(dim) << "s, '"
                            << it->second->name << "' and '" << group.name << "'; a " << entity_kind
                            << " belongs to one body");
      }
  gmsh::vectorpair entities;
  gmsh::model::getEntities(entities, dim);
  for (const auto& [entity_dim, entity] : entities)
  {
    if (body_of_entity.contains(entity))
      continue;
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, entity_dim, entity);
    FETICON_CHECK(types.empty(),
                  where << ": " << entity_kind << " " << entity << " has elements but is in no " << group_kind(dim)
                        << "; add it to a body or do not save it (Mesh.SaveAll = 0)");
  }
}

/// Twice the signed area of the corner polygon of a 2D cell in the x-y plane (> 0:
/// counter-clockwise).
double planar_orientation(const Mesh& mesh, const std::vector<int32_t>& cell, int n_corners)
{
  double area = 0;
  for (int k = 0; k < n_corners; ++k)
  {
    const auto a = mesh.nodes.row(cell[k]), b = mesh.nodes.row(cell[(k + 1) % n_corners]);
    area += a(0) * b(1) - b(0) * a(1);
  }
  return area;
}

/// A 2D cell clockwise in the x-y plane, counter-clockwise: corners c0, c_(n-1), ..., c1 and
/// the edge nodes of the reversed edges (Gmsh orients a surface's cells by its normal, which
/// need not be +z).
void make_counter_clockwise(std::vector<int32_t>& cell, const CellType& type)
{
  const int n = type.n_corners;
  const std::vector<int32_t> old = cell;
  for (int k = 1; k < n; ++k)
    cell[k] = old[n - k];
  if (type.n_nodes > n) // edge node k joins corners k and k + 1
    for (int k = 0; k < n; ++k)
      cell[n + k] = old[n + (n - 1 - k)];
}

/// The cells of the body group `group` (3D: a physical volume; 2D: a physical surface) as Gmsh
/// node tags, with their Gmsh element tags.
void read_body_cells(const PhysicalGroup& group, const std::string& where, std::vector<GmshCell>& cells,
                     std::vector<std::size_t>& element_tags)
{
  const std::size_t n_before = cells.size();
  for (const int entity : group.entities)
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, group.dim, entity);
    for (std::size_t t = 0; t < types.size(); ++t)
    {
      const CellType* type = cell_type_of_gmsh_type(types[t]);
      FETICON_CHECK(type && type->dimension == group.dim,
                    where << ": " << group_kind(group.dim) << " '" << group.name << "' holds " << tags[t].size()
                          << " elements of type " << element_type_name(types[t])
                          << (group.dim == 3
                                  ? "; feticon reads 4- and 10-node tetrahedra, 8- and 20-node hexahedra and 6-node "
                                    "prisms (for 20-node hexahedra set Mesh.SecondOrderIncomplete = 1)"
                                  : "; a 2D body is 3- or 6-node triangles and 4- or 8-node quadrangles (for 8-node "
                                    "quadrangles set Mesh.SecondOrderIncomplete = 1)"));
      const std::size_t n = static_cast<std::size_t>(type->n_nodes);
      for (std::size_t e = 0; e < tags[t].size(); ++e)
      {
        GmshCell cell{type->kind, {}};
        for (std::size_t k = 0; k < n; ++k)
          cell.tags[type->gmsh_to_local[k]] = nodes[t][n * e + k];
        cells.push_back(cell);
        element_tags.push_back(tags[t][e]);
      }
    }
  }
  FETICON_CHECK(cells.size() > n_before,
                where << ": " << group_kind(group.dim) << " '" << group.name << "' has no elements");
}

/// The cells, in feticon's node ids, after checks: no repeated node, no collapsed edge, a
/// positive Jacobian at the centre (2D cells turned counter-clockwise first).
void add_checked_cells(const std::vector<GmshCell>& gmsh_cells, const std::vector<std::size_t>& element_tags,
                       const std::unordered_map<std::size_t, int32_t>& local_id, const std::string& where, Mesh& mesh)
{
  mesh.cells.reserve(gmsh_cells.size(), gmsh_cells.size() * 8);
  std::vector<int32_t> cell, sorted;
  for (std::size_t c = 0; c < gmsh_cells.size(); ++c)
  {
    const CellType& type = cell_type(gmsh_cells[c].kind);
    cell.clear();
    for (const std::size_t tag : gmsh_cells[c].nodes())
      cell.push_back(local_id.at(tag));
    const auto name = [&] {
      return std::string(type.name) + " (Gmsh element " + std::to_string(element_tags[c]) + ") of body '" +
          mesh.body_names[mesh.cell_body[c]] + "'";
    };
    sorted = cell;
    std::sort(sorted.begin(), sorted.end());
    FETICON_CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end(),
                  where << ": " << name() << " repeats a node (degenerate)");
    if (type.dimension == 2 && planar_orientation(mesh, cell, type.n_corners) < 0)
      make_counter_clockwise(cell, type);
    mesh.cells.add(type.kind, cell);
    // Distinct nodes at one place collapse an edge: the centre's Jacobian can stay positive,
    // but the cell is degenerate (its aspect ratio infinite).
    double shortest = std::numeric_limits<double>::infinity(), longest = 0;
    for (const auto& e : type.edges)
    {
      const double length = (mesh.nodes.row(cell[e[0]]) - mesh.nodes.row(cell[e[1]])).norm();
      shortest = std::min(shortest, length);
      longest = std::max(longest, length);
    }
    FETICON_CHECK(shortest > 1e-9 * longest,
                  where << ": " << name() << " has an edge of length " << shortest
                        << " (coincident nodes; degenerate)");
    const double det = centre_jacobian_determinant(mesh, static_cast<int32_t>(c));
    FETICON_CHECK(det > 0,
                  where << ": " << name() << " is inverted or flat (Jacobian determinant " << det
                        << " at its centre); check the volume's orientation");
  }
}

/// Bodies, nodes and cells from the groups of the model's dimension `dim`.
/// @return the local node id of every Gmsh node tag used by a cell
std::unordered_map<std::size_t, int32_t> read_cells(const std::vector<PhysicalGroup>& groups, int dim,
                                                    const std::string& where, Mesh& mesh)
{
  std::vector<GmshCell> gmsh_cells;
  std::vector<std::size_t> element_tags;
  for (const PhysicalGroup& group : groups)
    if (group.dim == dim)
    {
      read_body_cells(group, where, gmsh_cells, element_tags);
      mesh.body_names.push_back(group.name);
      mesh.cell_body.resize(gmsh_cells.size(), mesh.n_bodies() - 1);
    }

  // Node ids body by body, by increasing Gmsh tag, so each body's nodes are one range (a node
  // bodies share, the sections of one connected mesh, in the range of the first body).
  std::unordered_map<std::size_t, int32_t> body_of_node;
  std::vector<std::vector<std::size_t>> body_nodes(mesh.body_names.size());
  for (std::size_t c = 0; c < gmsh_cells.size(); ++c)
    for (const std::size_t tag : gmsh_cells[c].nodes())
      if (body_of_node.emplace(tag, mesh.cell_body[c]).second)
        body_nodes[mesh.cell_body[c]].push_back(tag);
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
                where << ": cells use nodes that the file does not define (corrupt file?)");
  if (dim == 2)
    for (int32_t n = 0; n < mesh.n_nodes(); ++n)
      FETICON_CHECK(mesh.nodes(n, 2) == 0,
                    where << ": no 3D physical group, so a 2D model, whose cells lie in the "
                             "plane z = 0; node "
                          << n << " of its cells is at z = " << mesh.nodes(n, 2));

  add_checked_cells(gmsh_cells, element_tags, local_id, where, mesh);
  return local_id;
}

/// Face sets (and node sets of the same names) from the groups one dimension below the
/// model's `dim`: surfaces of a 3D model, curves (edges) of a 2D one.
void read_face_sets(const std::vector<PhysicalGroup>& groups, int dim, const std::string& where,
                    const std::unordered_map<std::size_t, int32_t>& local_id, Mesh& mesh)
{
  std::unordered_map<SortedFace, FaceOwner, SortedFaceHash> owners;
  owners.reserve(6 * mesh.cells.size());
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
  {
    for (int f = 0; f < static_cast<int>(cell_type(mesh.cells.kind(c)).faces.size()); ++f)
    {
      FaceOwner& owner = owners[sorted_corners(cell_face(mesh.cells.kind(c), mesh.cells[c], f))];
      if (owner.count++ == 0)
        owner = {c, f, 1};
    }
  }

  const std::string kind_of_group = group_kind(dim - 1);
  for (const PhysicalGroup& group : groups)
  {
    if (group.dim != dim - 1)
      continue;
    std::vector<Face>& faces = mesh.face_sets[group.name];
    for (const int entity : group.entities)
    {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, dim - 1, entity);
      for (std::size_t t = 0; t < types.size(); ++t)
      {
        const std::optional<FaceKind> kind = face_kind_of_gmsh_type(types[t]);
        FETICON_CHECK(kind && is_line(*kind) == (dim == 2),
                      where << ": " << kind_of_group << " '" << group.name << "' holds " << tags[t].size()
                            << " elements of type " << element_type_name(types[t])
                            << (dim == 3 ? "; faces of cells are 3- or 6-node triangles and 4- or 8-node quadrangles"
                                         : "; edges of 2D cells are 2- or 3-node lines"));
        const auto n = static_cast<std::size_t>(face_nodes(*kind));
        for (std::size_t e = 0; e < tags[t].size(); ++e)
        {
          // The element's corners as a linear face of their own, for their key.
          Face corners;
          corners.kind = is_line(*kind) ? FaceKind::line2 : face_corners(*kind) == 3 ? FaceKind::tri3 : FaceKind::quad4;
          bool on_cells = true;
          for (int k = 0; k < face_corners(*kind); ++k)
          {
            const auto it = local_id.find(nodes[t][n * e + k]);
            on_cells = on_cells && it != local_id.end();
            corners[k] = on_cells ? it->second : -1;
          }
          const auto owner = on_cells ? owners.find(sorted_corners(corners)) : owners.end();
          const std::string element = std::string(face_kind_names[static_cast<size_t>(*kind)]) + " (Gmsh element " +
              std::to_string(tags[t][e]) + ") of " + kind_of_group + " '" + group.name + "'";
          FETICON_CHECK(owner != owners.end(),
                        where << ": " << element << " is not a face of any cell of a body; the "
                              << (dim == 3 ? "surface" : "curve") << " must bound a " << group_kind(dim)
                              << " and share its mesh");
          FETICON_CHECK(owner->second.count == 1,
                        where << ": " << element
                              << " lies between two cells; face sets must be on the boundary of a body");
          const int32_t c = owner->second.cell;
          const Face face = cell_face(mesh.cells.kind(c), mesh.cells[c], owner->second.local_face);
          FETICON_CHECK(face.kind == *kind,
                        where << ": " << element << " is a face of a " << cell_type(mesh.cells.kind(c)).name
                              << " cell, whose faces are " << face_kind_names[static_cast<size_t>(face.kind)]
                              << "; mesh surfaces and volumes at the same order");
          faces.push_back(face);
        }
      }
    }
    FETICON_CHECK(!faces.empty(), where << ": " << kind_of_group << " '" << group.name << "' has no elements");
    mesh.add_node_set_from_faces(group.name, group.name);
  }
}

/// Node sets from the groups two or more dimensions below the model's `dim`.
void read_node_sets(const std::vector<PhysicalGroup>& groups, int dim, const std::string& where,
                    const std::unordered_map<std::size_t, int32_t>& local_id, Mesh& mesh)
{
  for (const PhysicalGroup& group : groups)
  {
    if (group.dim > dim - 2)
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
                          << "' is not a node of any cell of a body");
      ids.push_back(it->second);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
}

/// Gmsh messages may span lines; feticon errors are one line.
std::string one_line(std::string text)
{
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}
} // namespace

Mesh read_open_model(const std::string& where)
{
  const std::vector<PhysicalGroup> groups = read_groups(where);
  const int dim = model_dimension(groups, where);
  check_body_entities(groups, dim, where);
  Mesh mesh;
  const std::unordered_map<std::size_t, int32_t> local_id = read_cells(groups, dim, where, mesh);
  read_face_sets(groups, dim, where, local_id, mesh);
  read_node_sets(groups, dim, where, local_id, mesh);
  return mesh;
}

Mesh read_model_with_gmsh(const std::filesystem::path& path, const std::string& where)
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
