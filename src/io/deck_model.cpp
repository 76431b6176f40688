/// The fem::Problem of an input deck: nodes that elements use, bodies as the connected
/// components of the element graph, a material per body from the solid sections, surfaces as
/// outward face sets, supports and loads per step as the stages of the load history.

#include "common/error.hpp"
#include "fem/node_frames.hpp"
#include "io/deck.hpp"
#include "io/deck_couplings.hpp"
#include "io/deck_data.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>

namespace feticon::io
{
namespace
{
/// CalculiX's C3D8 face Sk (k = 1..6) as the index of mesh::hex_faces with the same nodes
/// (CalculiX manual, C3D8: S1 = 1-2-3-4, S2 = 5-8-7-6, S3 = 1-5-6-2, S4 = 2-6-7-3,
/// S5 = 3-7-8-4, S6 = 4-8-5-1), so that the face comes out oriented outward.
constexpr std::array<int, 7> hex_face_of_calculix = {-1, 0, 1, 2, 5, 3, 4};

/// The first corner of a hex8 cell where the trilinear map's Jacobian (the triple product of
/// the three edges there, in the reference directions) is below 1e-10 of the centre's `centre`
/// (8 x volume), or -1. The centre test alone passes a cell with a repeated node.
int first_degenerate_corner(const mesh::Mesh& mesh, std::span<const int32_t> cell, double centre)
{
  static constexpr int sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int a = 0; a < 8; ++a)
  {
    Eigen::Matrix3d edges;
    for (int d = 0; d < 3; ++d)
      for (int b = 0; b < 8; ++b)
        if (b != a && sign[b][(d + 1) % 3] == sign[a][(d + 1) % 3] && sign[b][(d + 2) % 3] == sign[a][(d + 2) % 3])
          edges.col(d) = sign[a][d] * (mesh.nodes.row(cell[a]) - mesh.nodes.row(cell[b])).transpose();
    if (!(edges.determinant() > 1e-10 * centre / 8))
      return a;
  }
  return -1;
}

/// The local position of a node repeated in a cell's node list, or -1: a collapsed cell.
int first_repeated_node(std::span<const int32_t> cell)
{
  for (size_t a = 1; a < cell.size(); ++a)
    for (size_t b = 0; b < a; ++b)
      if (cell[a] == cell[b])
        return static_cast<int>(a);
  return -1;
}

/// Face count of cell c (6 for hex8, 4 for tetrahedra, 5 for wedges).
int n_cell_faces(const mesh::Mesh& mesh, int32_t c)
{
  return static_cast<int>(mesh::cell_type(mesh.cells.kind(c)).faces.size());
}

/// The outward face `k` (0-based) of cell c: hex8's in mesh::hex_faces order and node order, as
/// hex8 decks were read before cells had types; other types in cell_type.hpp's (CalculiX's)
/// order.
mesh::Face local_face(const mesh::Mesh& mesh, int32_t c, int k)
{
  const std::span<const int32_t> cell = mesh.cells[c];
  if (mesh.cells.kind(c) != mesh::CellKind::hex8)
    return mesh::cell_face(mesh.cells.kind(c), cell, k);
  const auto& local = mesh::hex_faces[k];
  return {cell[local[0]], cell[local[1]], cell[local[2]], cell[local[3]]};
}

/// CalculiX's face S`calculix_face` (1-based) of cell c, outward.
mesh::Face face_nodes(const mesh::Mesh& mesh, int32_t c, int calculix_face)
{
  if (mesh.cells.kind(c) == mesh::CellKind::hex8)
    return local_face(mesh, c, hex_face_of_calculix[calculix_face]);
  return local_face(mesh, c, calculix_face - 1);
}

std::string step_name(const DeckStep& step, size_t k)
{
  return "step " + std::to_string(k + 1) + " (" + step.where + ")";
}

/// Union-find over nodes: cells that share a node are one body.
class Components
{
public:
  explicit Components(int32_t n) : _parent(n) { std::iota(_parent.begin(), _parent.end(), 0); }
  int32_t find(int32_t a)
  {
    while (_parent[a] != a)
      a = _parent[a] = _parent[_parent[a]];
    return a;
  }
  void join(int32_t a, int32_t b) { _parent[find(a)] = find(b); }

private:
  std::vector<int32_t> _parent;
};

class ModelBuilder
{
public:
  ModelBuilder(DeckData& data, Deck& deck) : _d(data), _deck(deck.info), _p(deck.problem) {}

  void build()
  {
    _reference = deck_reference_nodes(_d, label_of());
    nodes_and_cells();
    pretension_sections();
    bodies_and_materials();
    sets_and_surfaces();
    contact_pairs();
    ties();
    _p.couplings = deck_couplings(_d, _reference, _p.mesh, _deck.element_sets, mesh_of_fn(), label_of());
    node_frames();
    load_stages();
    undriven_reference_supports();
    initial_temperatures();
    amplitudes();
    equations();
  }

private:
  /// The nodes elements use, renumbered in reading order; cells in mesh numbering.
  void nodes_and_cells()
  {
    const int32_t n_read = static_cast<int32_t>(_d.node_labels.size());
    _mesh_node.assign(n_read, -1);
    for (const std::span<const int32_t> cell : _d.cells)
      for (int32_t n : cell)
        _mesh_node[n] = 0;
    int32_t count = 0;
    for (int32_t& m : _mesh_node)
      if (m == 0)
        m = count++;
    const auto cell_less_references =
        std::ranges::count_if(_reference.of_node, [&](const auto& entry) { return _mesh_node[entry.first] < 0; });
    if (count + cell_less_references < n_read)
      _d.warn(std::to_string(n_read - count - cell_less_references) +
              " nodes of the deck belong to no element and are no reference node; supports on them are "
              "not used");
    mesh::Mesh& mesh = _p.mesh;
    // The label tables are done with: free them before the mesh arrays are formed.
    _d.node_index = {};
    _d.element_index = {};
    // Nodes in reading order, compacted in place (m <= n), so no second node array is held.
    for (int32_t n = 0; n < n_read; ++n)
      if (const int32_t m = _mesh_node[n]; m >= 0 && m != n)
        _d.coordinates.row(m) = _d.coordinates.row(n);
    if (_d.coordinates.rows() != count)
      _d.coordinates.conservativeResize(count, 3);
    mesh.nodes = std::move(_d.coordinates);
    if (count == n_read) // mesh numbering is reading numbering: read_label() takes the moved labels
      _deck.node_labels = std::move(_d.node_labels);
    else
    {
      _deck.node_labels.resize(count);
      for (int32_t n = 0; n < n_read; ++n)
        if (const int32_t m = _mesh_node[n]; m >= 0)
          _deck.node_labels[m] = _d.node_labels[n];
    }
    mesh.cells = std::move(_d.cells);
    if (std::ranges::any_of(_d.reduced_integration, [](char r) { return r != 0; }))
      mesh.reduced_integration = std::move(_d.reduced_integration);
    for (size_t c = 0; c < mesh.cells.size(); ++c)
    {
      for (int32_t& n : mesh.cells.nodes_of(c))
        n = _mesh_node[n];
      const mesh::CellType& type = mesh::cell_type(mesh.cells.kind(c));
      // hex8's corner test below names a repeated node where the map degenerates.
      const int repeated = type.kind == mesh::CellKind::hex8 ? -1 : first_repeated_node(mesh.cells[c]);
      FETICON_CHECK(repeated < 0,
                    "element " << _d.element_labels[c] << " repeats its node "
                               << _deck.node_labels[mesh.cells[c][repeated]] << ": a collapsed "
                               << type.calculix_names.front() << " is not implemented");
      const double det = mesh::centre_jacobian_determinant(mesh, static_cast<int32_t>(c));
      FETICON_CHECK(det > 0,
                    "element " << _d.element_labels[c] << " is inverted or degenerate (Jacobian " << det
                               << " at its centre): its nodes are not in " << type.calculix_names.front() << " order");
      if (type.kind != mesh::CellKind::hex8)
        continue;
      const int corner = first_degenerate_corner(mesh, mesh.cells[c], det);
      FETICON_CHECK(corner < 0,
                    "element " << _d.element_labels[c] << " is degenerate at its node "
                               << _deck.node_labels[mesh.cells[c][corner]] << " (a repeated node, "
                               << "or edges there that span no volume): a collapsed C3D8 is not implemented");
    }
    _deck.element_labels = std::move(_d.element_labels);
    if (count == n_read)
      _mesh_node =
          std::vector<int32_t>(); // the identity: mesh_of() needs no table (and "= {}" would keep the capacity)
  }

  /// *PRE-TENSION SECTION (fem/coupling.hpp): the nodes of each section's faces doubled and the
  /// cells whose faces make it connected to the new nodes, as CalculiX's pretensionsections.f
  /// does (new nodes numbered after the deck's largest); the pairs kept as the node sets
  /// coupling_N_nodes and coupling_N_partners, in pair order, for deck_couplings. Before the
  /// bodies are found: a section through a bolt makes it two bodies that its rows join.
  void pretension_sections()
  {
    mesh::Mesh& mesh = _p.mesh;
    for (size_t j = 0; j < _d.couplings.size(); ++j)
    {
      const DeckCoupling& c = _d.couplings[j];
      if (c.kind != fem::CouplingKind::pretension)
        continue;
      const auto it = _d.surfaces.find(c.surface);
      FETICON_CHECK(it != _d.surfaces.end(), c.name << ": SURFACE=" << c.surface << " names no *SURFACE");
      FETICON_CHECK(!it->second.node_based,
                    c.name << ": SURFACE=" << c.surface << " is a node surface; a pretension section is element faces");
      FETICON_CHECK(mesh_of(c.ref_node) < 0,
                    c.name << ": NODE " << read_label(c.ref_node)
                           << " belongs to an element; the reference node must be its own");
      std::vector<std::pair<int32_t, mesh::Face>> faces; // all of them before any cell changes
      for (const DeckFace& f : it->second.faces)
      {
        FETICON_CHECK(f.face <= n_cell_faces(mesh, f.cell),
                      c.name << ": face S" << f.face << " of element " << _deck.element_labels[f.cell] << " has "
                             << n_cell_faces(mesh, f.cell) << " faces");
        faces.emplace_back(f.cell, face_nodes(mesh, f.cell, f.face));
      }
      std::map<int32_t, int32_t> partner;
      for (const auto& [cell, face] : faces)
        for (const int32_t n : face)
        {
          const auto [p, added] = partner.emplace(n, mesh.n_nodes() + static_cast<int32_t>(partner.size()));
          for (int32_t& m : mesh.cells.nodes_of(static_cast<size_t>(cell)))
            if (m == n)
              m = p->second;
        }
      add_partner_nodes(partner, j);
    }
  }

  void add_partner_nodes(const std::map<int32_t, int32_t>& partner, size_t coupling)
  {
    mesh::Mesh& mesh = _p.mesh;
    const int32_t first = mesh.n_nodes();
    mesh.nodes.conservativeResize(first + std::ssize(partner), 3);
    // After every deck label, cell-less nodes' included (CalculiX's nk + 1, ...).
    const int64_t label = *std::ranges::max_element(_d.node_labels.empty() ? _deck.node_labels : _d.node_labels);
    _deck.node_labels.resize(static_cast<size_t>(first) + partner.size());
    std::vector<int32_t>& olds = mesh.node_sets["coupling_" + std::to_string(coupling + 1) + "_nodes"];
    std::vector<int32_t>& news = mesh.node_sets["coupling_" + std::to_string(coupling + 1) + "_partners"];
    for (const auto& [old_node, new_node] : partner)
    {
      mesh.nodes.row(new_node) = mesh.nodes.row(old_node);
      // Labels in the order the faces met the nodes, as CalculiX numbers its new nodes.
      _deck.node_labels[static_cast<size_t>(new_node)] = label + 1 + (new_node - first);
      olds.push_back(old_node);
      news.push_back(new_node);
      _partner_of.emplace(old_node, new_node);
    }
  }

  /// The deck label of a node in reading order.
  int64_t read_label(int32_t read_node) const
  {
    return _d.node_labels.empty() ? _deck.node_labels[read_node] : _d.node_labels[read_node];
  }

  /// The mesh node of a node in reading order, -1 if no element uses it.
  int32_t mesh_of(int32_t read_node) const { return _mesh_node.empty() ? read_node : _mesh_node[read_node]; }
  std::function<int32_t(int32_t)> mesh_of_fn() const
  {
    return [this](int32_t n) { return mesh_of(n); };
  }
  std::function<int64_t(int32_t)> label_of() const
  {
    return [this](int32_t n) { return read_label(n); };
  }

  int32_t mesh_node(int32_t read_node, const std::string& what) const
  {
    const int32_t m = mesh_of(read_node);
    FETICON_CHECK(m >= 0, what << " names node " << read_label(read_node) << ", which belongs to no element");
    return m;
  }

  void bodies_and_materials()
  {
    mesh::Mesh& mesh = _p.mesh;
    Components components(mesh.n_nodes());
    for (const std::span<const int32_t> cell : mesh.cells)
      for (size_t k = 1; k < cell.size(); ++k)
        components.join(cell[0], cell[k]);

    // The section of every cell, held in cell_body until the bodies replace it below (one
    // array of a million cells fewer at the peak of reading).
    std::vector<int32_t>& section_of_cell = mesh.cell_body;
    section_of_cell.assign(mesh.n_cells(), -1);
    for (size_t s = 0; s < _d.sections.size(); ++s)
    {
      const DeckSection& section = _d.sections[s];
      const auto set = _d.element_sets.find(section.elset);
      FETICON_CHECK(set != _d.element_sets.end(),
                    section.where.str() << ": *SOLID SECTION: no element set '" << section.elset << "' is defined");
      const auto material = _d.materials.find(section.material);
      FETICON_CHECK(material != _d.materials.end(),
                    section.where.str() << ": *SOLID SECTION: no material '" << section.material << "' is defined");
      FETICON_CHECK(material->second.young > 0,
                    section.where.str() << ": *SOLID SECTION: material '" << section.material
                                        << "' has no *ELASTIC (nor *HYPERELASTIC)");
      try
      {
        material->second.check("material '" + section.material + "'"); // e.g. a table that softens faster than 3 G
      }
      catch (const Error& e)
      {
        throw Error(section.where.str() + ": *SOLID SECTION: " + e.what());
      }
      // CalculiX's solidsections.f: a later section of an element replaces the earlier one
      // (metalforming.inp gives every C3D8 cell steel, then its sheet's cells another material).
      std::map<int32_t, int64_t> replaced; // earlier section -> cells it loses
      set->second.for_each([&](int32_t c) {
        if (section_of_cell[c] >= 0 && section_of_cell[c] != static_cast<int32_t>(s))
          ++replaced[section_of_cell[c]];
        section_of_cell[c] = static_cast<int32_t>(s);
      });
      for (const auto& [earlier, n] : replaced)
        _d.warn(section.where.str() + ": *SOLID SECTION gives " + std::to_string(n) + " element(s) of the section at " +
                _d.sections[earlier].where.str() + " another material; the later section holds, as in CalculiX");
    }

    // A body is the cells of one material and one 2D formulation (kind and thickness) in one
    // connected set of cells: a connected set of several is several bodies that share the
    // nodes of their interfaces (glued there as subdomains are).
    std::map<std::string, int64_t> material_index;
    for (const auto& [name, material] : _d.materials)
      material_index.emplace(name, static_cast<int64_t>(material_index.size()));
    std::vector<mesh::Planar> formulations;
    std::vector<int32_t> formulation_of_body;
    std::map<std::tuple<int32_t, int64_t, int32_t>, int32_t> body_of_part; // (component root, material, formulation)
    std::vector<int32_t> body_section;
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
    {
      const int32_t section = section_of_cell[c];
      FETICON_CHECK(section >= 0, "element " << _deck.element_labels[c] << " has no *SOLID SECTION (no material)");
      const int32_t formulation = cell_formulation(c, _d.sections[section], formulations);
      const auto part =
          std::tuple(components.find(mesh.cells[c][0]), material_index.at(_d.sections[section].material), formulation);
      const auto [it, added] = body_of_part.emplace(part, static_cast<int32_t>(body_section.size()));
      if (added)
      {
        body_section.push_back(section);
        formulation_of_body.push_back(formulation);
      }
      const int32_t body = it->second;
      mesh.cell_body[c] = body; // section_of_cell[c] is read above, not after
      // body_section holds -1 - s once the body spans several sections (s its first).
      if (body_section[body] >= 0 && body_section[body] != section)
        body_section[body] = -1 - body_section[body]; // the body spans several sections
    }
    // Names: the section's element set where one section makes the body, else BODY<k>.
    std::map<std::string, int> uses;
    std::vector<std::string> names(body_section.size());
    for (size_t b = 0; b < body_section.size(); ++b)
    {
      const int32_t s = body_section[b] >= 0 ? body_section[b] : -1 - body_section[b];
      names[b] = body_section[b] >= 0 ? _d.sections[s].elset : "BODY" + std::to_string(b + 1);
      ++uses[names[b]];
      _p.materials.push_back(_d.materials.at(_d.sections[s].material));
    }
    for (size_t b = 0; b < names.size(); ++b)
      mesh.body_names.push_back(uses[names[b]] > 1 ? names[b] + "_" + std::to_string(b + 1) : names[b]);
    planar_bodies(formulations, formulation_of_body);
  }

  /// The index in `formulations` of cell c's 2D formulation: its element type's kind and, in
  /// plane strain and plane stress, its section's thickness (CalculiX's default 1 where the
  /// section gives none); the 3D formulation for 3D cells.
  int32_t cell_formulation(int32_t c, const DeckSection& section, std::vector<mesh::Planar>& formulations) const
  {
    mesh::Planar planar{_d.cell_planar[static_cast<size_t>(c)], 1.0};
    if (planar.kind == mesh::PlanarKind::plane_strain || planar.kind == mesh::PlanarKind::plane_stress)
      planar.thickness = section.thickness > 0 ? section.thickness : 1.0;
    const auto found = std::ranges::find(formulations, planar);
    if (found != formulations.end())
      return static_cast<int32_t>(found - formulations.begin());
    formulations.push_back(planar);
    return static_cast<int32_t>(formulations.size() - 1);
  }

  /// The bodies' 2D formulations: one for the model where all bodies have the same, else one per
  /// body (mesh::Mesh::body_planar; a plane section's thickness beside CAX cells is per full
  /// circle, as CalculiX's solidsections.f has it).
  void planar_bodies(const std::vector<mesh::Planar>& formulations, const std::vector<int32_t>& formulation_of_body)
  {
    mesh::Mesh& mesh = _p.mesh;
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      if (_d.cell_planar[static_cast<size_t>(c)] == mesh::PlanarKind::axisymmetric)
        for (const int32_t n : mesh.cells[c])
          FETICON_CHECK(mesh.nodes(n, 0) >= 0,
                        "node " << _deck.node_labels[n] << " of CAX element " << _deck.element_labels[c]
                                << " lies at r = x = " << mesh.nodes(n, 0)
                                << " < 0: an axisymmetric body lies at x >= 0");
    if (formulations.size() == 1)
    {
      mesh.planar = formulations.front();
      return;
    }
    std::vector<mesh::Planar> per_body;
    for (const int32_t f : formulation_of_body)
      per_body.push_back(formulations[static_cast<size_t>(f)]);
    mesh.set_body_planar(std::move(per_body));
  }

  void sets_and_surfaces()
  {
    mesh::Mesh& mesh = _p.mesh;
    std::map<int32_t, int32_t> printed; // cell-less reference node -> index in reference_nodes
    for (const auto& [node, of] : _reference.of_node)
      if (mesh_of(node) < 0)
      {
        printed.emplace(node, static_cast<int32_t>(_deck.reference_nodes.size()));
        _deck.reference_nodes.push_back({read_label(node), of.first, of.second});
      }
    for (auto& [name, members] : _d.node_sets)
    {
      std::vector<int32_t> nodes;
      nodes.reserve(static_cast<size_t>(members.size()));
      members.for_each([&](int32_t n) {
        if (mesh_of(n) >= 0)
          nodes.push_back(mesh_of(n));
        else if (const auto it = printed.find(n); it != printed.end())
          _deck.reference_node_sets[name].push_back(it->second);
      });
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      members = {};
      mesh.node_sets[name] = std::move(nodes);
    }
    for (auto& [name, members] : _d.element_sets)
    {
      std::vector<int32_t> cells = members.expand();
      members = {};
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      _deck.element_sets[name] = std::move(cells);
    }
    for (const auto& [name, surface] : _d.surfaces)
    {
      std::vector<mesh::Face> faces;
      if (surface.node_based)
        faces = faces_of_node_surface(name, surface);
      else
        for (const DeckFace& f : surface.faces)
        {
          FETICON_CHECK(f.face <= n_cell_faces(mesh, f.cell),
                        surface.where.str() << ": *SURFACE " << name << " names face S" << f.face << " of element "
                                            << _deck.element_labels[f.cell] << ", which has "
                                            << n_cell_faces(mesh, f.cell) << " faces");
          faces.push_back(face_nodes(mesh, f.cell, f.face));
        }
      FETICON_CHECK(!faces.empty(), surface.where.str() << ": *SURFACE " << name << " has no faces");
      mesh.face_sets[name] = std::move(faces);
    }
  }

  /// The faces of a node surface: the boundary faces whose four nodes are all in it, and for a
  /// node on none of those (a single slave node) the boundary faces around it; then the
  /// node set `slave_nodes_NAME` restricts the contact rows to the surface's own nodes.
  std::vector<mesh::Face> faces_of_node_surface(const std::string& name, const DeckSurface& surface)
  {
    const mesh::Mesh& mesh = _p.mesh;
    std::vector<char> in_surface(mesh.n_nodes(), 0);
    for (int32_t n : surface.nodes)
      if (mesh_of(n) >= 0)
        in_surface[mesh_of(n)] = 1;
    std::map<std::array<int32_t, 4>, std::pair<mesh::Face, int>> candidates;
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      for (int k = 0; k < n_cell_faces(mesh, c); ++k)
      {
        const mesh::Face face = local_face(mesh, c, k);
        if (!std::all_of(face.begin(), face.end(), [&](int32_t n) { return in_surface[n] != 0; }))
          continue;
        auto [it, added] = candidates.emplace(mesh::sorted_corners(face), std::pair{face, 0});
        ++it->second.second;
      }
    std::vector<mesh::Face> faces;
    std::vector<char> covered(mesh.n_nodes(), 0);
    for (const auto& [key, face_count] : candidates)
      if (face_count.second == 1) // on the boundary: one cell has it
      {
        faces.push_back(face_count.first);
        for (int32_t n : face_count.first)
          covered[n] = 1;
      }
    std::vector<int32_t> nodes;
    bool restricted = false;
    for (int32_t n = 0; n < mesh.n_nodes(); ++n)
      if (in_surface[n])
      {
        nodes.push_back(n);
        restricted = restricted || !covered[n];
      }
    if (!restricted)
      return faces;
    // Boundary faces around the uncovered nodes: every cell face counted once is on the boundary.
    std::map<std::array<int32_t, 4>, std::pair<mesh::Face, int>> around;
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      for (int k = 0; k < n_cell_faces(mesh, c); ++k)
      {
        const mesh::Face face = local_face(mesh, c, k);
        auto [it, added] = around.emplace(mesh::sorted_corners(face), std::pair{face, 0});
        ++it->second.second;
      }
    for (const auto& [key, face_count] : around)
      if (face_count.second == 1 && !candidates.count(key) &&
          std::any_of(face_count.first.begin(), face_count.first.end(),
                      [&](int32_t n) { return in_surface[n] && !covered[n]; }))
        faces.push_back(face_count.first);
    _p.mesh.node_sets["slave_nodes_" + name] = std::move(nodes);
    _restricted_surfaces.insert(name);
    return faces;
  }

  /// Every *CONTACT PAIR with its interaction: Coulomb's mu of the interaction's *FRICTION
  /// (mu = 0: frictionless) and the pair's formulation (NODE TO SURFACE, CalculiX's default
  /// TYPE: node-to-segment; SURFACE TO SURFACE: mortar).
  /// The surface a slave `name` names: its node surface for node-to-surface rows where an
  /// element surface shares the name (CalculiX's allocont.f takes the node one first), else the
  /// one of that name.
  std::string slave_surface(const std::string& name, bool node_to_surface) const
  {
    return node_to_surface && _d.surfaces.count(node_surface_key(name)) ? node_surface_key(name) : name;
  }

  void contact_pairs()
  {
    std::set<std::string> used;
    for (const DeckContactPair& deck_pair : _d.pairs)
    {
      _contact_of_pair.push_back(-1);
      _tie_of_pair.push_back(-1);
      DeckContactPair pair = deck_pair;
      pair.slave = slave_surface(pair.slave, pair.node_to_surface);
      const std::string at = pair.where.str() + ": *CONTACT PAIR";
      FETICON_CHECK(_d.interactions.count(pair.interaction),
                    at << ": no *SURFACE INTERACTION '" << pair.interaction << "' is defined");
      for (const std::string& s : {pair.slave, pair.master})
        FETICON_CHECK(_d.surfaces.count(s), at << ": no *SURFACE '" << s << "' is defined");
      FETICON_CHECK(pair.slave != pair.master, at << ": slave and master are the same surface '" << pair.slave << "'");
      FETICON_CHECK(!_d.surfaces.at(pair.master).node_based,
                    at << ": master surface '" << pair.master << "' must be made of element faces (TYPE=ELEMENT)");
      const std::string slave_nodes = _restricted_surfaces.count(pair.slave) ? "slave_nodes_" + pair.slave : "";
      const fem::ContactFormulation formulation =
          pair.node_to_surface ? fem::ContactFormulation::node_to_segment : fem::ContactFormulation::mortar;
      used.insert(pair.interaction);
      // Tied in some step: a tie; not tied in some: a contact pair (both where *CHANGE SURFACE
      // BEHAVIOR turns one into the other: each is out of force where the other is in).
      bool tied_somewhere = false, contact_somewhere = false;
      for (size_t k = 0; k < _d.step_states.size(); ++k)
        (tied_in_step(pair.interaction, k) ? tied_somewhere : contact_somewhere) = true;
      if (tied_somewhere)
      {
        // A tied pair moves no node (a pair's ADJUST is a distance or a set; a tie's a flag).
        _tie_of_pair.back() = static_cast<int32_t>(_p.ties.size());
        _p.ties.push_back({pair.interaction, pair.slave, pair.master, slave_nodes, 0, false, formulation});
      }
      if (!contact_somewhere)
        continue;
      _contact_of_pair.back() = static_cast<int32_t>(_p.contacts.size());
      fem::ContactInteraction interaction{
          pair.interaction, law_of(pair.interaction, formulation, pair.slave), {}, formulation};
      if (const auto it = _d.frictions.find(pair.interaction); it != _d.frictions.end() && it->second.coefficient > 0)
        interaction.friction = {fem::FrictionModel::coulomb, it->second.coefficient, 0};
      FETICON_CHECK(pair.adjust_set.empty() || _p.mesh.node_sets.count(pair.adjust_set),
                    at << ": ADJUST=" << pair.adjust_set << " names no node set (nor a distance)");
      _p.contacts.push_back(
          {pair.slave, pair.master, slave_nodes, std::move(interaction), pair.adjust, pair.adjust_set});
    }
    for (const auto& [interaction, friction] : _d.frictions)
      if (!used.count(interaction))
        _d.warn("*FRICTION of interaction " + interaction + " (" + friction.where.str() +
                ") is not used: no *CONTACT PAIR takes that interaction");
  }

  /// Every *TIE: a node-based slave surface is tied node to segment (CalculiX's way), a surface
  /// of element faces by mortar.
  void ties()
  {
    for (const DeckTie& deck_tie : _d.ties)
    {
      DeckTie tie = deck_tie;
      tie.slave = slave_surface(tie.slave, true);
      const std::string at = tie.where.str() + ": *TIE " + tie.name;
      for (const std::string& s : {tie.slave, tie.master})
        FETICON_CHECK(_d.surfaces.count(s), at << ": no *SURFACE '" << s << "' is defined");
      FETICON_CHECK(tie.slave != tie.master, at << ": slave and master are the same surface '" << tie.slave << "'");
      // A cyclic symmetry tie may name its master side by nodes: the boundary faces of those
      // nodes are its faces (CalculiX triangulates them).
      FETICON_CHECK(tie.cyclic || !_d.surfaces.at(tie.master).node_based,
                    at << ": master surface '" << tie.master << "' must be made of element faces (TYPE=ELEMENT)");
      const bool node_based = _d.surfaces.at(tie.slave).node_based;
      FETICON_CHECK(!tie.cyclic || tie.symmetry,
                    at << ": a CYCLIC SYMMETRY tie needs its *CYCLIC SYMMETRY MODEL (the sectors and the axis)");
      // A cyclic tie's sides are turned copies of each other: no ADJUST, node to segment.
      _p.ties.push_back(
          {tie.name, tie.slave, tie.master, _restricted_surfaces.count(tie.slave) ? "slave_nodes_" + tie.slave : "",
           tie.position_tolerance, tie.adjust && !tie.cyclic,
           node_based || tie.cyclic ? fem::ContactFormulation::node_to_segment : fem::ContactFormulation::mortar,
           tie.symmetry});
    }
  }

  /// Supports as node sets grouped by their prescribed components and values.
  /// Supports as node sets grouped by their amplitude and their prescribed components and values.
  std::vector<fem::DirichletCondition> supports(const std::map<int64_t, DeckValue>& boundary, const std::string& prefix)
  {
    using Values = std::array<std::optional<double>, 3>;
    std::map<std::pair<std::string, int32_t>, Values> by_node;
    for (const auto& [dof, value] : boundary)
    {
      const int32_t m = mesh_of(dof / 3);
      if (m < 0 || _p.eliminated[dof % 3])
        continue;
      by_node[{value.amplitude, m}][dof % 3] = value.value;
    }
    std::map<std::pair<std::string, Values>, std::vector<int32_t>> groups;
    for (const auto& [key, values] : by_node)
      groups[{key.first, values}].push_back(key.second);
    std::vector<fem::DirichletCondition> out;
    for (auto& [key, nodes] : groups)
    {
      const std::string name = prefix + std::to_string(out.size() + 1);
      _p.mesh.node_sets[name] = std::move(nodes);
      out.push_back({name, key.second, key.first});
    }
    return out;
  }

  /// The forces in global components: a node with a frame (*TRANSFORM) has its force along
  /// its local axis, which may have up to three global components.
  std::vector<fem::NodalForce> nodal_forces(const std::map<int64_t, DeckValue>& cload, const std::string& what)
  {
    std::vector<fem::NodalForce> out;
    for (const auto& [dof, value] : cload)
    {
      if (const int32_t read = static_cast<int32_t>(dof / 3); mesh_of(read) < 0 && _reference.of_node.count(read))
        continue; // a reference node's (reference_values)
      const int32_t node = mesh_node(static_cast<int32_t>(dof / 3), what + ": *CLOAD");
      const int component = static_cast<int>(dof % 3);
      const int32_t frame = _p.frames.index_of(node);
      if (frame < 0)
      {
        out.push_back({node, component, value.value, value.amplitude});
        continue;
      }
      for (int g = 0; g < 3; ++g)
        if (const double e = _p.frames.axes[static_cast<size_t>(frame)](component, g); e != 0)
          out.push_back({node, g, value.value * e, value.amplitude});
    }
    return out;
  }

  /// The local systems of the nodes a *TRANSFORM names (the ones elements use), in node order.
  void node_frames()
  {
    std::vector<std::pair<int32_t, int32_t>> frames; // mesh node, transform
    for (const auto& [node, t] : _d.node_transform)
      if (const int32_t m = mesh_of(node); m >= 0)
        frames.emplace_back(m, t);
    std::ranges::sort(frames);
    for (const auto& [node, t] : frames)
    {
      const DeckTransform& transform = _d.transforms[static_cast<size_t>(t)];
      _p.frames.nodes.push_back(node);
      _p.frames.axes.push_back(
          transform.cylindrical ? fem::cylindrical_axes(transform.a, transform.b, _p.mesh.nodes.row(node).transpose())
                                : fem::rectangular_axes(transform.a, transform.b));
      FETICON_CHECK(_p.mesh.planar.kind == mesh::PlanarKind::none || std::abs(_p.frames.axes.back()(2, 2) - 1) < 1e-12,
                    transform.where.str() << ": *TRANSFORM: a 2D model takes rectangular systems whose z axis is the "
                                             "global z axis (as CalculiX)");
    }
  }

  /// Whether local component 3 of deck node `node` is u_z (no frame, or one that keeps z).
  bool third_component_is_z(int32_t node) const
  {
    const int32_t frame = _p.frames.index_of(mesh_of(node));
    return frame < 0 || std::abs(_p.frames.axes[static_cast<size_t>(frame)](2, 2) - 1) < 1e-14;
  }

  /// Pressures as face sets grouped by value and amplitude.
  std::vector<fem::FacePressure> pressures(const std::map<std::pair<int32_t, int>, DeckValue>& dload,
                                           const std::string& prefix)
  {
    std::map<DeckValue, std::vector<mesh::Face>> groups;
    for (const auto& [face, value] : dload)
    {
      FETICON_CHECK(face.second <= n_cell_faces(_p.mesh, face.first),
                    prefix << ": *DLOAD P" << face.second << " on element " << _deck.element_labels[face.first]
                           << ", which has " << n_cell_faces(_p.mesh, face.first) << " faces");
      groups[value].push_back(face_nodes(_p.mesh, face.first, face.second));
    }
    std::vector<fem::FacePressure> out;
    for (auto& [value, faces] : groups)
    {
      const std::string name = prefix + std::to_string(out.size() + 1);
      _p.mesh.face_sets[name] = std::move(faces);
      out.push_back({name, value.value, value.amplitude});
    }
    return out;
  }

  /// GRAV and CENTRIF loads, one per distinct load (its cells gathered).
  static std::vector<fem::BodyLoad> body_loads(const std::map<std::pair<int32_t, int>, DeckBodyLoad>& body)
  {
    std::map<std::tuple<int, std::array<double, 7>, std::string>, fem::BodyLoad> groups;
    for (const auto& [key, load] : body)
    {
      const auto& [cell, kind] = key;
      fem::BodyLoad& b = groups[{kind, load.values, load.amplitude}];
      const std::array<double, 7>& v = load.values;
      if (b.cells.empty())
      {
        b.where = load.where;
        b.amplitude = load.amplitude;
        b.kind = kind == 0 ? fem::BodyLoad::Kind::gravity : fem::BodyLoad::Kind::centrifugal;
        if (kind == 0)
          b.gravity = Eigen::Vector3d(v[0], v[1], v[2]);
        else
        {
          b.omega2 = v[0];
          b.point = Eigen::Vector3d(v[1], v[2], v[3]);
          b.axis = Eigen::Vector3d(v[4], v[5], v[6]);
        }
      }
      b.cells.push_back(cell);
    }
    std::vector<fem::BodyLoad> out;
    for (auto& [key, b] : groups)
      out.push_back(std::move(b));
    return out;
  }

  /// The temperatures of the nodes that belong to a cell (a node without one has no strain).
  std::vector<fem::NodalTemperature> temperatures(const std::map<int32_t, DeckValue>& given) const
  {
    std::vector<fem::NodalTemperature> out;
    for (const auto& [node, value] : given)
      if (const int32_t m = mesh_of(node); m >= 0)
      {
        out.push_back({m, value.value, value.amplitude});
        if (const auto p = _partner_of.find(m); p != _partner_of.end())
          out.push_back({p->second, value.value, value.amplitude});
      }
    return out;
  }

  /// Whether the pairs of `interaction` are tied in step k (0-based): the law a *CHANGE SURFACE
  /// BEHAVIOR gave it by then, else the model's.
  bool tied_in_step(const std::string& interaction, size_t k) const
  {
    const auto& changed = _d.step_states[k].tied;
    const auto it = changed.find(interaction);
    return it != changed.end() ? it->second : _d.tied_interactions.count(interaction) > 0;
  }

  /// The contact pairs and ties out of force in step k: those *MODEL CHANGE took out, those tied
  /// there, and the ties of pairs that are contact there.
  void pairs_out_of_force(size_t k, fem::Step& step) const
  {
    step.removed_contacts = removed_contacts(_d.step_states[k].removed_pairs);
    for (size_t p = 0; p < _d.pairs.size(); ++p)
    {
      const bool tied = tied_in_step(_d.pairs[p].interaction, k);
      if (tied && _contact_of_pair[p] >= 0)
        step.removed_contacts.push_back(_contact_of_pair[p]);
      if (!tied && _tie_of_pair[p] >= 0)
        step.removed_ties.push_back(_tie_of_pair[p]);
    }
    std::sort(step.removed_contacts.begin(), step.removed_contacts.end());
    step.removed_contacts.erase(std::unique(step.removed_contacts.begin(), step.removed_contacts.end()),
                                step.removed_contacts.end());
  }

  /// The contact law of `interaction` (hard if it has none): a linear law without a positive
  /// slope takes CalculiX's default, 50 times the E of the deck's first material.
  /// A node-to-face pair's law keeps its tension sigma_inf (fem::NormalLaw; none given: CalculiX's
  /// default, the first material's E / 70 000); a face-to-face pair's law is bilinear, its
  /// exponential law zero at contact (CalculiX's variants); on a node surface a node-to-face
  /// pair's pressure acts on the master face's area (fem::NormalLaw::on_master_face).
  fem::NormalLaw resolved(fem::NormalLaw law, fem::ContactFormulation formulation, const std::string& slave) const
  {
    law.on_master_face = law.kind != fem::NormalLawKind::hard &&
        formulation == fem::ContactFormulation::node_to_segment && _d.surfaces.at(slave).node_based;
    if (law.kind == fem::NormalLawKind::exponential)
      law.zero_at_contact = formulation != fem::ContactFormulation::node_to_segment;
    if (law.kind != fem::NormalLawKind::linear)
      return law;
    const bool defaults =
        law.slope == 0 || (formulation == fem::ContactFormulation::node_to_segment && law.sigma_inf <= 0);
    FETICON_CHECK(!defaults || !_d.first_material.empty(),
                  "a linear contact law without its slope K or tension sigma_inf and no *MATERIAL for CalculiX's "
                  "defaults (50 times and 1 / 70 000 of the first material's E)");
    const double young = defaults ? _d.materials.at(_d.first_material).young : 0.0;
    if (law.slope == 0)
      law.slope = 50 * young;
    if (formulation != fem::ContactFormulation::node_to_segment)
      law.sigma_inf = 0;
    else if (law.sigma_inf <= 0)
      law.sigma_inf = young / 70000;
    return law;
  }
  fem::NormalLaw law_of(const std::string& interaction, fem::ContactFormulation formulation,
                        const std::string& slave) const
  {
    const auto it = _d.laws.find(interaction);
    return it != _d.laws.end() ? resolved(it->second, formulation, slave) : fem::NormalLaw{};
  }

  /// The pairs whose interaction a *CHANGE SURFACE BEHAVIOR gave a contact law, with that law.
  std::vector<std::pair<int32_t, fem::NormalLaw>> changed_laws(const std::map<std::string, fem::NormalLaw>& laws) const
  {
    std::vector<std::pair<int32_t, fem::NormalLaw>> out;
    for (size_t p = 0; p < _p.contacts.size(); ++p)
      if (const auto it = laws.find(_p.contacts[p].interaction.name); it != laws.end())
        out.emplace_back(static_cast<int32_t>(p),
                         resolved(it->second, _p.contacts[p].interaction.formulation, _p.contacts[p].slave));
    return out;
  }

  /// The indices of the pairs *MODEL CHANGE took out (a name that is no pair is an error).
  /// The pairs whose interaction a *CHANGE FRICTION changed, with their friction (mu = 0:
  /// frictionless).
  std::vector<std::pair<int32_t, fem::Friction>> changed_friction(
      const std::map<std::string, DeckFriction>& frictions) const
  {
    std::vector<std::pair<int32_t, fem::Friction>> out;
    for (size_t p = 0; p < _p.contacts.size(); ++p)
      if (const auto it = frictions.find(_p.contacts[p].interaction.name); it != frictions.end())
        out.emplace_back(static_cast<int32_t>(p),
                         it->second.coefficient > 0
                             ? fem::Friction{fem::FrictionModel::coulomb, it->second.coefficient, 0}
                             : fem::Friction{});
    return out;
  }

  std::vector<int32_t> removed_contacts(const std::map<std::pair<std::string, std::string>, std::string>& removed) const
  {
    std::vector<int32_t> out;
    for (const auto& [names, where] : removed)
    {
      const auto it = std::find_if(_d.pairs.begin(), _d.pairs.end(), [&](const DeckContactPair& p) {
        return p.slave == names.first && p.master == names.second;
      });
      FETICON_CHECK(it != _d.pairs.end(),
                    where << ": *MODEL CHANGE: no *CONTACT PAIR has slave " << names.first << " and master "
                          << names.second);
      const int32_t contact = _contact_of_pair[it - _d.pairs.begin()];
      FETICON_CHECK(contact >= 0,
                    where << ": *MODEL CHANGE of the tied pair " << names.first << ", " << names.second
                          << " is not implemented by feticon (contact pairs only)");
      out.push_back(contact);
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  /// *INITIAL CONDITIONS, TYPE=TEMPERATURE; 0 where none is given (CalculiX's default).
  void initial_temperatures()
  {
    if (_d.initial_temperatures.empty())
      return;
    _p.initial_temperatures.assign(_p.mesh.n_nodes(), 0.0);
    for (const auto& [node, value] : _d.initial_temperatures)
      if (const int32_t m = mesh_of(node); m >= 0)
        _p.initial_temperatures[m] = value;
    for (const auto& [old_node, new_node] : _partner_of)
      _p.initial_temperatures[static_cast<size_t>(new_node)] = _p.initial_temperatures[static_cast<size_t>(old_node)];
  }

  /// Plane strain as CalculiX decks state it (feticon export writes it so): u_z = 0 on every
  /// node in every step is the eliminated component, not a support.
  bool every_node_fixes_z() const
  {
    for (const DeckLoadState& state : _d.step_states)
    {
      int32_t fixed = 0;
      std::vector<char> seen(_p.mesh.n_nodes(), 0);
      for (const auto& [dof, value] : state.boundary)
        if (dof % 3 == 2 && value.value == 0 && value.amplitude.empty() && mesh_of(dof / 3) >= 0 &&
            !seen[mesh_of(dof / 3)] && third_component_is_z(static_cast<int32_t>(dof / 3)))
        {
          seen[mesh_of(dof / 3)] = 1;
          ++fixed;
        }
      if (fixed != _p.mesh.n_nodes())
        return false;
    }
    return true;
  }

  void load_stages()
  {
    // A 2D model has no u_z; a 3D one given as one layer with u_z = 0 everywhere is plane strain.
    _p.eliminated = {false, false, _p.mesh.planar.kind != mesh::PlanarKind::none || every_node_fixes_z()};
    for (size_t k = 0; k < _d.step_states.size(); ++k)
    {
      const DeckLoadState& state = _d.step_states[k];
      const std::string name = step_name(_deck.steps[k], k);
      const std::string prefix = "step" + std::to_string(k + 1) + "_";
      fem::Step& step = k == 0 ? _p.steps.front() : _p.steps.emplace_back();
      step.dirichlet = supports(state.boundary, prefix + "support_");
      step.nodal_forces = nodal_forces(state.cload, name);
      step.reference_supports =
          reference_values(_d, _reference, state.boundary, state.boundary_rotation, true, mesh_of_fn(), label_of());
      step.reference_loads =
          reference_values(_d, _reference, state.cload, state.cload_moment, false, mesh_of_fn(), label_of());
      step.pressures = pressures(state.dload, prefix + "pressure_");
      step.body_loads = body_loads(state.body);
      step.temperatures = temperatures(state.temperature);
      pairs_out_of_force(k, step);
      step.changed_friction = changed_friction(state.frictions);
      step.changed_law = changed_laws(state.laws);
      step.time = _deck.steps[k].time;
      step.ramp = _deck.steps[k].ramp;
      // Step 1 takes the solver's load_steps, which a first *STATIC, DIRECT sets (--set may
      // change it, also for automatic increments: LoadHistory's default_first).
      if (k > 0)
        step.increments = _deck.steps[k].increments;
      step.automatic = _deck.steps[k].automatic;
    }
  }

  /// A support on a reference DOF its coupling does not drive holds nothing: say so once.
  void undriven_reference_supports()
  {
    if (_p.couplings.empty())
      return;
    const std::vector<fem::ReferenceDofs> reference = _p.reference_dofs();
    for (const fem::Step& step : _p.steps)
      for (const fem::ReferenceValue& r : step.reference_supports)
        if (reference[static_cast<size_t>(r.coupling)].value[r.dof].empty())
          _d.warn("*BOUNDARY on " + fem::describe_reference_dof(r.dof) + " of the reference node of " +
                  _p.couplings[static_cast<size_t>(r.coupling)].name +
                  " holds nothing: the coupling does not move it (a *DISTRIBUTING reference node stays where it "
                  "is, as in CalculiX; a *KINEMATIC one moves in the directions its coupled components see)");
  }

  static bool is_zero(const DeckValue& v) { return v.value == 0; }
  static bool is_zero(const DeckBodyLoad& b) { return b.values[0] == 0 && b.values[1] == 0 && b.values[2] == 0; }

  /// The *AMPLITUDEs the loads name; refuses a load that trades its ramp for an amplitude (or
  /// the reverse) from one step to the next, whose start CalculiX takes from the old value (a
  /// support held at 0 may take an amplitude).
  void amplitudes()
  {
    for (const auto& [name, where] : _d.amplitude_uses)
      FETICON_CHECK(_d.amplitudes.count(name), where << ": AMPLITUDE=" << name << " is not defined by any *AMPLITUDE");
    _p.amplitudes = _d.amplitudes;
    for (size_t k = 1; k < _d.step_states.size(); ++k)
    {
      const DeckLoadState &before = _d.step_states[k - 1], &now = _d.step_states[k];
      const auto check = [&](const auto& old_loads, const auto& new_loads, const char* keyword, auto describe) {
        for (const auto& [key, value] : new_loads)
        {
          const auto it = old_loads.find(key);
          FETICON_CHECK(it == old_loads.end() || it->second.amplitude.empty() == value.amplitude.empty() ||
                            is_zero(it->second),
                        step_name(_deck.steps[k], k)
                            << ": the " << keyword << " on " << describe(key) << " has "
                            << (value.amplitude.empty() ? "no amplitude" : "AMPLITUDE=" + value.amplitude)
                            << ", in the step before "
                            << (it->second.amplitude.empty() ? "none" : "AMPLITUDE=" + it->second.amplitude)
                            << ": feticon ramps a load without amplitude from the loads without amplitude "
                               "before it, so a load may not switch between the two");
        }
      };
      const auto dof = [&](int64_t d) {
        return "node " + std::to_string(read_label(static_cast<int32_t>(d / 3))) + ", degree of freedom " +
            std::to_string(d % 3 + 1);
      };
      const auto face = [&](const std::pair<int32_t, int>& f) {
        return "element " + std::to_string(_deck.element_labels[f.first]) + ", face " + std::to_string(f.second);
      };
      check(before.boundary, now.boundary, "*BOUNDARY", dof);
      check(before.cload, now.cload, "*CLOAD", dof);
      check(before.dload, now.dload, "*DLOAD", face);
      check(before.body, now.body, "*DLOAD", [&](const std::pair<int32_t, int>& b) {
        return "element " + std::to_string(_deck.element_labels[b.first]) + (b.second == 0 ? " (GRAV)" : " (CENTRIF)");
      });
    }
  }

  void equations()
  {
    for (fem::LinearEquation& eq : _d.equations)
    {
      for (auto& term : eq.terms)
        term.node = mesh_node(term.node, "*EQUATION");
      _p.equations.push_back(std::move(eq));
    }
  }

  DeckData& _d;
  DeckInfo& _deck;
  fem::Problem& _p;
  /// Mesh node of every node read, -1 if no element uses it; empty when every node is used
  /// (mesh numbering = reading numbering).
  std::vector<int32_t> _mesh_node;
  /// Per *CONTACT PAIR (deck order): its index in Problem::contacts and in Problem::ties (-1:
  /// none; a pair is one or the other, or both where *CHANGE SURFACE BEHAVIOR switches it).
  std::vector<int32_t> _contact_of_pair, _tie_of_pair;
  std::set<std::string> _restricted_surfaces; ///< node surfaces with a slave_nodes_NAME set
  DeckReferenceNodes _reference;
  /// Pretension sections' doubled nodes: old mesh node -> new (temperatures are copied).
  std::map<int32_t, int32_t> _partner_of;
};
} // namespace

Deck read_deck(const std::filesystem::path& path) { return read_deck(path, deck_outline(path)); }

Deck read_deck(const std::filesystem::path& path, const DeckOutline& outline)
{
  DeckData data = read_deck_data(path, outline);
  Deck deck;
  deck.info.path = path;
  deck.info.steps = data.steps;
  deck.problem.name = path.stem().string();
  ModelBuilder(data, deck).build();
  const auto& steps = deck.info.steps;
  if (steps.back().nlgeom && !steps.front().nlgeom)
    data.warn("NLGEOM is set from a later step on; feticon takes one kinematics for the run, large displacements");
  deck.info.warnings = std::move(data.warnings);
  deck.problem.validate();
  return deck;
}

namespace
{
/// The number of load steps of the first *STATIC's data line if it is DIRECT (1 if it has
/// none); unset for automatic increments.
std::optional<int> outline_increments(DeckTokenizer& tokens, const DeckKeyword& keyword)
{
  if (!keyword.has("DIRECT"))
    return std::nullopt;
  DeckDataLine line;
  if (!tokens.next_data(line) || line.fields.empty())
    return 1;
  // The reader checks these numbers; here a malformed one leaves the default.
  const double initial = std::strtod(std::string(line.fields[0]).c_str(), nullptr);
  const double total = line.fields.size() > 1 ? std::strtod(std::string(line.fields[1]).c_str(), nullptr) : 1.0;
  if (initial > 0 && total > 0 && total / initial <= 100000)
    return std::max(1, static_cast<int>(std::ceil(total / initial - 1e-9)));
  return 1;
}
} // namespace

DeckOutline deck_outline(const std::filesystem::path& path)
{
  DeckOutline out;
  DeckTokenizer tokens(path);
  DeckKeyword keyword;
  bool first_step = true;
  // The nodes and elements of each *PART, counted once for each of its *INSTANCEs.
  std::map<std::string, std::pair<int64_t, int64_t>> part_counts;
  std::string part;
  while (tokens.next_keyword(keyword))
  {
    if (keyword.name == "NODE" || keyword.name == "ELEMENT")
    {
      const bool nodes = keyword.name == "NODE";
      int64_t& count = part.empty() ? (nodes ? out.nodes : out.elements)
                                    : (nodes ? part_counts[part].first : part_counts[part].second);
      count += tokens.count_data_lines();
    }
    else if (keyword.name == "PART" || keyword.name == "END PART")
      part = keyword.name == "PART" && keyword.value("NAME") ? *keyword.value("NAME") : std::string();
    else if (const std::string* instance_of = keyword.value("PART"); keyword.name == "INSTANCE" && instance_of)
    {
      out.nodes += part_counts[*instance_of].first;
      out.elements += part_counts[*instance_of].second;
    }
    else if (keyword.name == "STEP")
    {
      const std::string* nlgeom = keyword.value("NLGEOM");
      out.nlgeom = out.nlgeom || (nlgeom && (nlgeom->empty() || *nlgeom == "YES"));
    }
    else if (keyword.name == "HYPERELASTIC")
      out.nlgeom = true; // CalculiX's rule: a hyperelastic material makes the model geometrically nonlinear
    else if (keyword.name == "STATIC" && first_step)
    {
      first_step = false;
      out.increments = outline_increments(tokens, keyword);
    }
  }
  return out;
}
} // namespace feticon::io
