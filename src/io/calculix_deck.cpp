#include "io/calculix_deck.hpp"

#include "common/error.hpp"
#include "fem/load_history.hpp"
#include "io/calculix_deck_writer.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace feticon::io
{
namespace deck_writer
{
/// A real number in CalculiX's free format: 13 significant digits fit its 20-character fields.
std::string number(double v)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12e", v);
  return buffer;
}

/// Deck names: CalculiX upper-cases names and allows 80 characters; feticon's set names are
/// identifiers already, so only a prefix keeps them apart from the deck's own.
std::string deck_name(const std::string& prefix, const std::string& name)
{
  std::string out = prefix + name;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      c = '_';
  FETICON_CHECK(out.size() <= 80, "calculix export: the name '" << name << "' is longer than CalculiX's 80 characters");
  return out;
}

/// Coulomb's mu of pair `pair` in step `step` (CalculixOptions::friction; 0 where not given).
double friction_of(const CalculixOptions& options, size_t step, size_t pair)
{
  return step < options.friction.size() && pair < options.friction[step].size() ? options.friction[step][pair] : 0.0;
}

double normal_slope(const fem::NormalLaw& law, const ContactPairFaces& pair)
{
  return law.kind == fem::NormalLawKind::linear ? law.slope : pair.stiffness;
}
int32_t tie_of_pair(const fem::Problem& problem, int32_t pair)
{
  const fem::ContactPairNames& names = problem.contacts[pair];
  for (int32_t t = 0; t < std::ssize(problem.ties); ++t)
    if (const fem::Tie& tie = problem.ties[t]; !tie.cyclic && tie.slave == names.slave && tie.master == names.master)
      return t;
  return -1;
}

bool is_pair_tie(const fem::Problem& problem, int32_t tie)
{
  for (int32_t p = 0; p < std::ssize(problem.contacts); ++p)
    if (tie_of_pair(problem, p) == tie)
      return true;
  return false;
}

bool tied_in_step(const fem::Problem& problem, int32_t pair, size_t step)
{
  const int32_t t = tie_of_pair(problem, pair);
  return t >= 0 && std::ranges::find(problem.steps[step].removed_ties, t) == problem.steps[step].removed_ties.end();
}

fem::NormalLaw law_in_step(const fem::Problem& problem, int32_t pair, size_t step)
{
  for (const auto& [changed, law] : problem.steps[step].changed_law)
    if (changed == pair)
      return law;
  return problem.contacts[pair].interaction.law;
}

void write_surface_behavior(std::ostream& out, const fem::NormalLaw& law, bool tied, const ContactPairFaces& pair,
                            bool node_to_segment)
{
  out << "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=";
  // A node-to-surface pair's LINEAR law has a tension sigma_inf, E / 70 000 where the line gives
  // none or one <= 0 (CalculiX's surfacebehaviors.f, and the deck reader): a deck's own law
  // keeps its value, hard contact written as a penalty gets that default.
  const double stiffness = normal_slope(law, pair);
  if (tied)
    out << "TIED\n";
  else if (law.kind == fem::NormalLawKind::exponential)
    out << "EXPONENTIAL\n" << number(law.c0) << ", " << number(law.p0) << '\n';
  else if (law.kind == fem::NormalLawKind::tabular)
  {
    out << "TABULAR\n";
    for (const auto& [overclosure, pressure] : law.table)
      out << number(pressure) << ", " << number(overclosure) << '\n';
  }
  else if (node_to_segment)
    out << "LINEAR\n"
        << number(stiffness) << ", " << number(law.kind == fem::NormalLawKind::linear ? law.sigma_inf : 0.0) << '\n';
  else
    out << "LINEAR\n" << number(stiffness) << '\n';
}
} // namespace deck_writer

namespace
{
using namespace deck_writer;

/// Element and CalculiX face number (1..6) of every face of a set.
std::vector<std::pair<int32_t, int>> element_faces(const mesh::Mesh& mesh, const std::string& set,
                                                   const std::vector<std::vector<int32_t>>& cells_of_node)
{
  std::vector<std::pair<int32_t, int>> out;
  for (const mesh::Face& face : mesh.face_set(set))
  {
    const std::array<int32_t, 4> key = mesh::sorted_corners(face);
    std::pair<int32_t, int> found{-1, 0};
    for (int32_t c : cells_of_node[face[0]])
    {
      // cell_type's faces are CalculiX's S1, S2, ... in order.
      const int n_faces = static_cast<int>(mesh::cell_type(mesh.cells.kind(c)).faces.size());
      for (int f = 0; f < n_faces && found.first < 0; ++f)
        if (mesh::sorted_corners(mesh::cell_face(mesh.cells.kind(c), mesh.cells[c], f)) == key)
          found = {c, f + 1};
    }
    FETICON_CHECK(found.first >= 0,
                  "calculix export: a face of set '" << set << "' (corner nodes " << face[0] << ", " << face[1] << ", "
                                                     << face[2] << ", ...) is no face of a cell");
    out.push_back(found);
  }
  return out;
}

/// The bodies the cells of faces belong to.
std::set<int32_t> bodies_of(const mesh::Mesh& mesh, const std::vector<std::pair<int32_t, int>>& faces)
{
  std::set<int32_t> bodies;
  for (const auto& [cell, f] : faces)
    bodies.insert(mesh.cell_body[cell]);
  return bodies;
}

/// Area-weighted mean outward normal of a face set (unit), and its shortest face edge: the
/// contact element size where the mesh is finest (the thickness of a plane-strain layer is
/// no contact size, and it is the longer edge there).
std::pair<Eigen::Vector3d, double> mean_normal_and_size(const mesh::Mesh& mesh, const std::string& set)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double shortest = std::numeric_limits<double>::infinity();
  for (const mesh::Face& f : mesh.face_set(set))
  {
    if (mesh::is_line(f.kind)) // an edge of a 2D cell: its length, its normal (x1 - x0) x e_z
    {
      const Eigen::Vector3d edge = mesh.nodes.row(f[1]) - mesh.nodes.row(f[0]);
      sum += edge.cross(Eigen::Vector3d::UnitZ());
      shortest = std::min(shortest, edge.norm());
      continue;
    }
    const int n = f.n_corners();
    // Area vector of the corners' polygon: half the cross product of the diagonals of a quad,
    // of two edges of a triangle.
    const Eigen::Vector3d a = mesh.nodes.row(f[2]) - mesh.nodes.row(f[0]);
    const Eigen::Vector3d b = mesh.nodes.row(f[n - 1]) - mesh.nodes.row(f[1]);
    sum += 0.5 * a.cross(b);
    for (int k = 0; k < n; ++k)
      shortest = std::min(shortest, (mesh.nodes.row(f[(k + 1) % n]) - mesh.nodes.row(f[k])).norm());
  }
  FETICON_CHECK(sum.norm() > 0 && shortest > 0, "calculix export: face set '" << set << "' has no area");
  return {sum.normalized(), shortest};
}

/// True if no node of `body` has a prescribed displacement component along `normal` (a
/// component counts if the normal has a part along it of at least 1e-3).
bool floats_along(const fem::Problem& problem, int32_t body, const Eigen::Vector3d& normal)
{
  std::vector<char> in_body(problem.mesh.n_nodes(), 0);
  for (int32_t c = 0; c < problem.mesh.n_cells(); ++c)
    if (problem.mesh.cell_body[c] == body)
      for (int32_t n : problem.mesh.cells[c])
        in_body[n] = 1;
  for (const fem::DirichletCondition& d : problem.steps.front().dirichlet)
    for (int i = 0; i < 3; ++i)
      if (d.value[i] && std::abs(normal(i)) >= 1e-3)
        for (int32_t n : problem.mesh.node_set(d.set))
          if (in_body[n])
            return false;
  return true;
}

/// Node coordinates as the deck writes them (slave bodies shifted, see contact_pairs).
using Coordinates = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// The cells of every node (element_faces' lookup).
std::vector<std::vector<int32_t>> cells_of_nodes(const mesh::Mesh& mesh)
{
  std::vector<std::vector<int32_t>> out(mesh.n_nodes());
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (int32_t n : mesh.cells[c])
      out[n].push_back(c);
  return out;
}

/// Element faces and stiffness of every contact pair; a slave body that floats along the
/// master normal is shifted into its master in `x` (the overclosure recorded in `summary`).
std::vector<ContactPairFaces> contact_pairs(const fem::Problem& problem, const CalculixOptions& options, Coordinates& x,
                                            CalculixDeckSummary& summary)
{
  const mesh::Mesh& mesh = problem.mesh;
  const std::vector<std::vector<int32_t>> cells_of_node = cells_of_nodes(mesh);
  std::vector<ContactPairFaces> pairs;
  std::vector<char> shifted_body(mesh.n_bodies(), 0);
  for (const fem::ContactPairNames& names : problem.contacts)
  {
    ContactPairFaces pair;
    pair.slave = element_faces(mesh, names.slave, cells_of_node);
    pair.master = element_faces(mesh, names.master, cells_of_node);
    // A surface may span bodies (a deck's plate of two sections; a node surface's faces around
    // a node of it that is a corner of none of its own).
    const std::set<int32_t> slave_bodies = bodies_of(mesh, pair.slave), master_bodies = bodies_of(mesh, pair.master);
    FETICON_CHECK(slave_bodies.size() != 1 || slave_bodies != master_bodies,
                  "calculix export: contact pair " << names.slave << " / " << names.master << " lies on one body");
    const double slave_size = mean_normal_and_size(mesh, names.slave).second;
    const Eigen::Vector3d master_normal = mean_normal_and_size(mesh, names.master).first;
    double young = 0;
    for (const std::set<int32_t>* bodies : {&slave_bodies, &master_bodies})
      for (const int32_t b : *bodies)
        young = std::max(young, problem.materials[b].young);
    pair.stiffness = options.contact_stiffness_factor * young / slave_size;
    const int32_t slave_body = slave_bodies.size() == 1 ? *slave_bodies.begin() : -1;
    if (slave_body >= 0 && floats_along(problem, slave_body, master_normal) && !shifted_body[slave_body])
    {
      const double shift = options.overclosure >= 0 ? options.overclosure : 0.02 * slave_size;
      for (int32_t c = 0; c < mesh.n_cells(); ++c)
        if (mesh.cell_body[c] == slave_body)
          for (int32_t n : mesh.cells[c])
            x.row(n) = mesh.nodes.row(n) - shift * master_normal.transpose();
      shifted_body[slave_body] = 1;
      summary.overclosure = shift;
    }
    summary.n_slave_faces += static_cast<int64_t>(pair.slave.size());
    summary.n_master_faces += static_cast<int64_t>(pair.master.size());
    pairs.push_back(std::move(pair));
  }
  summary.n_contact_pairs = static_cast<int64_t>(pairs.size());
  if (!pairs.empty())
    summary.contact_stiffness = pairs.front().stiffness;
  if (!pairs.empty() && friction_of(options, 0, 0) > 0)
  {
    summary.friction_coefficient = friction_of(options, 0, 0);
    summary.stick_slope = pairs.front().stiffness / options.stick_slope_ratio;
  }
  return pairs;
}

/// CalculiX's element type of a cell: C3D8 ..., C3D20R; a 2D cell's by its formulation (CPE4,
/// CPS8R, CAX6, ...).
std::string calculix_element_name(mesh::CellKind kind, bool reduced, mesh::PlanarKind planar)
{
  const std::string_view solid = mesh::cell_type(kind).calculix_names.front(); // C3D8, CPE4, ...
  if (!mesh::is_planar(kind))
    return reduced ? "C3D20R" : std::string(solid);
  const char* prefix = planar == mesh::PlanarKind::plane_stress ? "CPS"
      : planar == mesh::PlanarKind::axisymmetric                ? "CAX"
                                                                : "CPE";
  return prefix + std::string(solid.substr(3)) + (reduced ? "R" : "");
}

/// The deck's heading, *NODE (coordinates x) and one *ELEMENT block per body.
void write_mesh(std::ostream& out, const fem::Problem& problem, const Coordinates& x,
                const CalculixDeckSummary& summary, const DeckNodes& nodes)
{
  const mesh::Mesh& mesh = problem.mesh;
  out << "** CalculiX deck of the feticon problem '" << problem.name << "' (feticon export --format calculix)\n"
      << "** SI units: m, N, Pa. " << mesh.n_nodes() << " nodes, " << mesh.n_cells() << " elements.\n";
  if (summary.overclosure > 0)
    out << "** Slave bodies held only by contact are shifted by " << number(summary.overclosure)
        << " m into their master (see src/io/calculix_deck.hpp).\n";
  out << "*HEADING\nfeticon " << problem.name << "\n*NODE, NSET=NALL\n";
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
    if (!nodes.doubled(n))
      out << n + 1 << ", " << number(x(n, 0)) << ", " << number(x(n, 1)) << ", " << number(x(n, 2)) << '\n';
  for (int32_t b = 0; b < mesh.n_bodies(); ++b)
  {
    // One *ELEMENT block per cell type of the body, and integration (C3D20 and C3D20R).
    for (const mesh::CellKind kind : mesh::all_cell_kinds)
      for (const bool reduced : {false, true})
      {
        if (reduced && mesh.reduced_integration.empty())
          continue;
        bool any = false;
        for (int32_t c = 0; c < mesh.n_cells(); ++c)
          if (mesh.cell_body[c] == b && mesh.cells.kind(c) == kind && mesh.reduced(c) == reduced)
          {
            if (!any)
              out << "*ELEMENT, TYPE=" << calculix_element_name(kind, reduced, mesh.planar_of_body(b).kind)
                  << ", ELSET=" << deck_name("B_", mesh.body_names[b]) << '\n';
            any = true;
            out << c + 1;
            // CalculiX reads at most 16 entries a line: the label and 15 nodes, then the rest.
            const std::span<const int32_t> cell = mesh.cells[c];
            for (size_t k = 0; k < cell.size(); ++k)
              out << (k == 15 ? ",\n" : ", ") << nodes.cell_label(cell[k]);
            out << '\n';
          }
      }
  }
}

/// One *NSET per node set that a support names, 16 nodes a line.
void write_node_sets(std::ostream& out, const mesh::Mesh& mesh, const std::set<std::string>& node_sets,
                     const DeckNodes& nodes)
{
  for (const std::string& name : node_sets)
  {
    out << "*NSET, NSET=" << deck_name("N_", name) << '\n';
    int k = 0;
    for (int32_t n : mesh.node_set(name))
      out << nodes.label(n, "node set " + name) << (++k % 16 == 0 ? ",\n" : ", ");
    out << '\n';
  }
}

/// *MATERIAL with *ELASTIC or *HYPERELASTIC (*EXPANSION, *PLASTIC) and its *SOLID SECTION, per body.
void write_materials(std::ostream& out, const fem::Problem& problem)
{
  const mesh::Mesh& mesh = problem.mesh;
  for (int32_t b = 0; b < mesh.n_bodies(); ++b)
  {
    const fem::Material& m = problem.materials[b];
    out << "*MATERIAL, NAME=" << deck_name("M_", mesh.body_names[b]) << '\n';
    const fem::Hyperelastic& h = m.hyperelastic;
    if (!m.is_hyperelastic())
      out << "*ELASTIC\n" << number(m.young) << ", " << number(m.poisson) << '\n';
    else if (h.c01 == 0)
      out << "*HYPERELASTIC, NEO HOOKE\n" << number(h.c10) << ", " << number(h.d1) << '\n';
    else
      out << "*HYPERELASTIC, MOONEY-RIVLIN\n" << number(h.c10) << ", " << number(h.c01) << ", " << number(h.d1) << '\n';
    if (m.expansion != 0)
      out << "*EXPANSION\n" << number(m.expansion) << '\n';
    if (m.is_plastic())
    {
      out << (m.plastic.kinematic ? "*PLASTIC, HARDENING=KINEMATIC\n" : "*PLASTIC\n");
      for (size_t k = 0; k < m.plastic.stress.size(); ++k)
        out << number(m.plastic.stress[k]) << ", " << number(m.plastic.plastic_strain[k]) << '\n';
    }
    out << "*SOLID SECTION, ELSET=" << deck_name("B_", mesh.body_names[b])
        << ", MATERIAL=" << deck_name("M_", mesh.body_names[b]) << '\n';
    if (const mesh::Planar& planar = mesh.planar_of_body(b);
        planar.kind == mesh::PlanarKind::plane_strain || planar.kind == mesh::PlanarKind::plane_stress)
      out << number(planar.thickness) << '\n';
  }
}

/// Every *AMPLITUDE (tabular, its TIME=, SHIFTX and SHIFTY), four (time, value) pairs a line.
void write_amplitudes(std::ostream& out, const fem::Problem& problem)
{
  for (const auto& [name, a] : problem.amplitudes)
  {
    out << "*AMPLITUDE, NAME=" << deck_name("A_", name) << (a.total_time ? ", TIME=TOTAL TIME" : "");
    if (a.shift_x != 0)
      out << ", SHIFTX=" << number(a.shift_x);
    if (a.shift_y != 0)
      out << ", SHIFTY=" << number(a.shift_y);
    out << '\n';
    for (size_t k = 0; k < a.points.size(); ++k)
      out << number(a.points[k].first) << ", " << number(a.points[k].second)
          << (k % 4 == 3 || k + 1 == a.points.size() ? "\n" : ", ");
  }
}

/// *INITIAL CONDITIONS, TYPE=TEMPERATURE: every node where the model has temperatures, and the
/// nodes whose T_0 is not 0.
void write_initial_temperatures(std::ostream& out, const fem::Problem& problem, const DeckNodes& nodes)
{
  // CalculiX refuses a *TEMPERATURE without thermal *INITIAL CONDITIONS (temperatures.f): a
  // model with temperatures gets them for every node, 0 (feticon's default T_0) first.
  if (problem.has_temperatures())
    out << "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.0\n";
  bool header = problem.has_temperatures();
  const std::vector<double>& t0 = problem.initial_temperatures;
  for (int32_t n = 0; n < std::ssize(t0); ++n)
    // A doubled node takes its original's T_0 when CalculiX doubles it again.
    if (t0[n] != 0 && !(nodes.doubled(n) && t0[n] == t0[nodes.original(n)]))
    {
      if (!header)
        out << "*INITIAL CONDITIONS, TYPE=TEMPERATURE\n";
      header = true;
      out << nodes.label(n, "an initial temperature") << ", " << number(t0[n]) << '\n';
    }
}

/// Per contact pair: its two *SURFACEs, a linear pressure-overclosure interaction (with
/// *FRICTION for Coulomb friction) and the *CONTACT PAIR (node to surface for node-to-segment
/// rows, else surface to surface).
void write_contact(std::ostream& out, const fem::Problem& problem, const CalculixOptions& options,
                   const std::vector<ContactPairFaces>& pairs, const DeckNodes& nodes)
{
  for (size_t p = 0; p < pairs.size(); ++p)
  {
    const fem::ContactPairNames& names = problem.contacts[p];
    for (const auto& [set, faces] :
         {std::pair{names.slave, &pairs[p].slave}, std::pair{names.master, &pairs[p].master}})
    {
      // A deck's node surface stays one (its nodes, or those of its faces): CalculiX's law acts
      // on the master face's area at a node that is a corner of none of its faces
      // (fem::NormalLaw::on_master_face), and the nodes may be fewer than its faces'.
      if (set == names.slave && (!names.slave_nodes.empty() || names.interaction.law.on_master_face))
      {
        out << "*SURFACE, NAME=" << deck_name("S_", set) << ", TYPE=NODE\n";
        for (const int32_t n :
             names.slave_nodes.empty() ? problem.mesh.face_set_nodes(set) : problem.mesh.node_set(names.slave_nodes))
          out << nodes.label(n, "contact surface " + set) << '\n';
        continue;
      }
      out << "*SURFACE, NAME=" << deck_name("S_", set) << ", TYPE=ELEMENT\n";
      for (const auto& [cell, f] : *faces)
        out << cell + 1 << ", S" << f << '\n';
    }
    const std::string interaction = "SI_" + std::to_string(p + 1);
    const bool node_to_segment = p < options.node_to_segment.size() && options.node_to_segment[p];
    const double stiffness = normal_slope(names.interaction.law, pairs[p]);
    // The pair's law in the first step (TIED where *CHANGE SURFACE BEHAVIOR makes it contact
    // later: write_model_changes writes the changes).
    out << "*SURFACE INTERACTION, NAME=" << interaction << '\n';
    const auto pair = static_cast<int32_t>(p);
    write_surface_behavior(out, law_in_step(problem, pair, 0), tied_in_step(problem, pair, 0), pairs[p],
                           node_to_segment);
    // Friction in some step: *FRICTION from the first (CalculiX asks mu > 0 there), changed
    // by the steps (write_model_changes).
    bool friction = false;
    for (size_t k = 0; k < problem.steps.size(); ++k)
      friction = friction || friction_of(options, k, p) > 0;
    FETICON_CHECK(!friction || friction_of(options, 0, p) > 0,
                  "calculix export: contact pair " << names.slave << " / " << names.master
                                                   << " has friction in a later step but none in the first, which "
                                                      "CalculiX cannot say (its *FRICTION asks mu > 0)");
    if (friction)
      out << "** Coulomb friction; the stick slope is the normal slope / " << options.stick_slope_ratio
          << " (src/io/calculix_deck.hpp)\n*FRICTION\n"
          << number(friction_of(options, 0, p)) << ", " << number(stiffness / options.stick_slope_ratio) << '\n';
    out << "*CONTACT PAIR, INTERACTION=" << interaction;
    // ADJUST by a distance or a node set (write_node_sets writes it): the slave nodes moved onto
    // the master before the first increment, in both codes.
    if (!names.adjust_nodes.empty())
      out << ", ADJUST=" << deck_name("N_", names.adjust_nodes);
    else if (names.adjust > 0)
      out << ", ADJUST=" << number(names.adjust);
    out << (node_to_segment ? ", TYPE=NODE TO SURFACE\n" : ", TYPE=SURFACE TO SURFACE\n")
        << deck_name("S_", names.slave) << ", " << deck_name("S_", names.master) << '\n';
  }
}

/// Per tie: its two *SURFACEs (named T_ apart from the contact pairs' S_) and the *TIE; a cyclic
/// symmetry tie with its *CYCLIC SYMMETRY MODEL. The formulation is the slave surface's kind, as
/// the deck reader takes it: node to segment is a node surface (the tie's slave nodes, or its
/// faces' nodes), mortar element faces.
void write_ties(std::ostream& out, const fem::Problem& problem, const DeckNodes& nodes)
{
  if (problem.ties.empty())
    return;
  const mesh::Mesh& mesh = problem.mesh;
  const std::vector<std::vector<int32_t>> cells_of_node = cells_of_nodes(mesh);
  for (int32_t t = 0; t < std::ssize(problem.ties); ++t)
  {
    const fem::Tie& tie = problem.ties[t];
    // A contact pair's tied steps are its own (write_contact, write_model_changes).
    if (is_pair_tie(problem, t))
      continue;
    for (const std::string& set : {tie.slave, tie.master})
    {
      if (set == tie.slave && tie.formulation == fem::ContactFormulation::node_to_segment)
      {
        out << "*SURFACE, NAME=" << deck_name("T_", set) << ", TYPE=NODE\n";
        for (const int32_t n : tie.slave_nodes.empty() ? mesh.face_set_nodes(set) : mesh.node_set(tie.slave_nodes))
          out << nodes.label(n, "tie surface " + set) << '\n';
        continue;
      }
      out << "*SURFACE, NAME=" << deck_name("T_", set) << ", TYPE=ELEMENT\n";
      for (const auto& [cell, f] : element_faces(mesh, set, cells_of_node))
        out << cell + 1 << ", S" << f << '\n';
    }
    const std::string name = deck_name("TIE_", tie.name);
    out << "*TIE, NAME=" << name << (tie.cyclic ? ", CYCLIC SYMMETRY" : "");
    if (tie.position_tolerance > 0)
      out << ", POSITION TOLERANCE=" << number(tie.position_tolerance);
    out << (tie.adjust || tie.cyclic ? "" : ", ADJUST=NO") << '\n'
        << deck_name("T_", tie.slave) << ", " << deck_name("T_", tie.master) << '\n';
    if (!tie.cyclic)
      continue;
    const fem::Tie::CyclicSymmetry& c = *tie.cyclic;
    // N= as an integer where it is one (CalculiX reads the sectors that way).
    const std::string sectors = c.sectors == std::round(c.sectors) && std::abs(c.sectors) < 1e9
        ? std::to_string(static_cast<int64_t>(c.sectors))
        : number(c.sectors);
    out << "*CYCLIC SYMMETRY MODEL, N=" << sectors << ", TIE=" << name << '\n';
    for (int k = 0; k < 6; ++k)
      out << number(k < 3 ? c.axis_a(k) : c.axis_b(k - 3)) << (k < 5 ? ", " : "\n");
  }
}

/// The deck's *EQUATIONs (Problem::equations) as they were read: the number of terms, then
/// four (node, DOF, coefficient) triples a line.
void write_equations(std::ostream& out, const fem::Problem& problem, const DeckNodes& nodes)
{
  for (const fem::LinearEquation& eq : problem.equations)
  {
    FETICON_CHECK(eq.rhs == 0,
                  "calculix export: an equation with a right-hand side (" << eq.rhs << ") has no *EQUATION");
    out << "*EQUATION\n" << eq.terms.size() << '\n';
    for (size_t k = 0; k < eq.terms.size(); ++k)
      out << nodes.label(eq.terms[k].node, "an *EQUATION") << ", " << eq.terms[k].component + 1 << ", "
          << number(eq.terms[k].coefficient) << (k % 4 == 3 || k + 1 == eq.terms.size() ? "\n" : ", ");
  }
}

/// Per coupling (fem/coupling.hpp): its reference node, labelled after the mesh nodes (its DOFs
/// 1-3 the translations, 4-6 the rotations, as CalculiX's *COUPLING REF NODE), the surface it
/// drives (its faces, or its node set as a node surface) and the *COUPLING with *KINEMATIC (the
/// components that follow the rigid motion) or *DISTRIBUTING (forces, and the moments it spreads);
/// a mean coupling as its DCOUP3D element and *DISTRIBUTING COUPLING with the nodes' weights; a
/// pretension section as its faces and *PRE-TENSION SECTION.
void write_couplings(std::ostream& out, const fem::Problem& problem, const DeckNodes& nodes)
{
  if (problem.couplings.empty())
    return;
  const mesh::Mesh& mesh = problem.mesh;
  out << "*NODE, NSET=REFERENCE_NODES\n";
  for (size_t k = 0; k < problem.couplings.size(); ++k)
  {
    const Eigen::Vector3d& x = problem.couplings[k].reference;
    out << mesh.n_nodes() + k + 1 << ", " << number(x(0)) << ", " << number(x(1)) << ", " << number(x(2)) << '\n';
  }
  const std::vector<std::vector<int32_t>> cells_of_node = cells_of_nodes(mesh);
  for (size_t k = 0; k < problem.couplings.size(); ++k)
  {
    const fem::Coupling& c = problem.couplings[k];
    if (c.kind == fem::CouplingKind::pretension)
    {
      // The section's faces, of the cells that took the doubled nodes (DeckNodes): CalculiX
      // doubles the nodes again when it reads them (pretensionsections.f, as the deck reader).
      const std::string surface = "PRETENSION_" + std::to_string(k + 1);
      out << "*SURFACE, NAME=" << surface << ", TYPE=ELEMENT\n";
      for (const auto& [cell, f] : element_faces(mesh, c.faces, cells_of_node))
        out << cell + 1 << ", S" << f << '\n';
      out << "*PRE-TENSION SECTION, SURFACE=" << surface << ", NODE=" << mesh.n_nodes() + k + 1 << '\n';
      if (c.normal.norm() > 0)
        out << number(c.normal(0)) << ", " << number(c.normal(1)) << ", " << number(c.normal(2)) << '\n';
      continue;
    }
    if (c.kind == fem::CouplingKind::mean)
    {
      // CalculiX's *DISTRIBUTING COUPLING takes its reference node from a DCOUP3D element
      // (labelled after the cells), whose *SOLID SECTION CalculiX asks for (any material).
      const std::string elset = "MEAN_" + std::to_string(k + 1);
      out << "*ELEMENT, TYPE=DCOUP3D, ELSET=" << elset << '\n'
          << mesh.n_cells() + k + 1 << ", " << mesh.n_nodes() + k + 1 << "\n*SOLID SECTION, ELSET=" << elset
          << ", MATERIAL=" << deck_name("M_", mesh.body_names.front()) << "\n*DISTRIBUTING COUPLING, ELSET=" << elset
          << '\n';
      const std::vector<int32_t>& coupled = mesh.node_set(c.nodes);
      for (size_t i = 0; i < coupled.size(); ++i)
        out << nodes.label(coupled[i], c.name) << ", " << number(c.weights[i]) << '\n';
      continue;
    }
    const std::string surface = "COUPLING_" + std::to_string(k + 1);
    if (!c.faces.empty())
    {
      out << "*SURFACE, NAME=" << surface << ", TYPE=ELEMENT\n";
      for (const auto& [cell, f] : element_faces(mesh, c.faces, cells_of_node))
        out << cell + 1 << ", S" << f << '\n';
    }
    else
    {
      out << "*SURFACE, NAME=" << surface << ", TYPE=NODE\n";
      for (const int32_t n : mesh.node_set(c.nodes))
        out << nodes.label(n, c.name) << '\n';
    }
    out << "*COUPLING, REF NODE=" << mesh.n_nodes() + k + 1 << ", SURFACE=" << surface
        << ", CONSTRAINT NAME=" << deck_name("C_", c.name) << '\n';
    if (c.kind == fem::CouplingKind::kinematic)
    {
      out << "*KINEMATIC\n";
      for (int i = 0; i < 3; ++i)
        if (c.components[i])
          out << i + 1 << ", " << i + 1 << '\n';
      continue;
    }
    out << "*DISTRIBUTING\n1, 3\n";
    for (int i = 0; i < 3; ++i)
      if (c.moments[i])
        out << i + 4 << ", " << i + 4 << '\n';
  }
}

/// A *TRANSFORM per node with a frame: TYPE=R with a on the local x axis and b on the local y
/// axis is the frame exactly.
void write_frames(std::ostream& out, const fem::Problem& problem)
{
  FETICON_CHECK(problem.frames.empty() || problem.mesh.planar.kind != mesh::PlanarKind::none ||
                    !problem.eliminated[2] ||
                    std::ranges::all_of(problem.frames.axes,
                                        [](const Eigen::Matrix3d& e) { return std::abs(e(2, 2) - 1) < 1e-14; }),
                "calculix export: a local system turns the z axis of a plane strain hex layer, whose u_z = 0 the deck "
                "states as a support");
  for (size_t k = 0; k < problem.frames.nodes.size(); ++k)
  {
    const Eigen::Matrix3d& e = problem.frames.axes[k];
    out << "*NSET, NSET=FRAME_" << k + 1 << '\n'
        << problem.frames.nodes[k] + 1 << "\n*TRANSFORM, NSET=FRAME_" << k + 1 << ", TYPE=R\n";
    for (int i = 0; i < 6; ++i)
      out << number(e(i / 3, i % 3)) << (i < 5 ? ", " : "\n");
  }
}

} // namespace

CalculixDeckSummary write_calculix_deck(const fem::Problem& problem, const CalculixOptions& options, std::ostream& out)
{
  FETICON_CHECK(options.increments >= 1, "calculix export: increments = " << options.increments << " must be >= 1");
  FETICON_CHECK(std::isfinite(options.contact_stiffness_factor) && options.contact_stiffness_factor > 0,
                "calculix export: contact stiffness factor " << options.contact_stiffness_factor
                                                             << " must be positive");
  for (const std::vector<double>& step : options.friction)
    for (const double mu : step)
      FETICON_CHECK(std::isfinite(mu) && mu >= 0, "calculix export: friction coefficient " << mu << " must be >= 0");
  FETICON_CHECK(std::isfinite(options.stick_slope_ratio) && options.stick_slope_ratio > 0,
                "calculix export: stick slope ratio " << options.stick_slope_ratio << " must be positive");
  const mesh::Mesh& mesh = problem.mesh;
  CalculixDeckSummary summary;
  summary.n_nodes = mesh.n_nodes();
  summary.n_elements = mesh.n_cells();

  // Contact pairs first: the shift of floating slave bodies changes the node coordinates.
  Coordinates x = mesh.nodes;
  const std::vector<ContactPairFaces> pairs = contact_pairs(problem, options, x, summary);

  const DeckNodes nodes(problem);
  write_mesh(out, problem, x, summary, nodes);
  // A tie out of force in a step is a contact pair's tied state (*CHANGE SURFACE BEHAVIOR).
  for (const fem::Step& step : problem.steps)
    for (const int32_t t : step.removed_ties)
      FETICON_CHECK(is_pair_tie(problem, t),
                    "calculix export: tie " << problem.ties[t].name
                                            << " is taken out of force in a step, which a deck's *TIE cannot say (a "
                                               "tied contact pair's *CHANGE SURFACE BEHAVIOR can)");
  std::set<std::string> node_sets;
  for (const fem::Step& step : problem.steps)
    for (const fem::DirichletCondition& d : step.dirichlet)
      node_sets.insert(d.set);
  std::set<std::string> written_sets = node_sets; // the supports' (printed below) and ADJUST's
  for (const fem::ContactPairNames& pair : problem.contacts)
    if (!pair.adjust_nodes.empty())
      written_sets.insert(pair.adjust_nodes);
  write_node_sets(out, mesh, written_sets, nodes);
  write_frames(out, problem);
  write_materials(out, problem);
  write_contact(out, problem, options, pairs, nodes);
  write_ties(out, problem, nodes);
  write_equations(out, problem, nodes);
  write_couplings(out, problem, nodes);
  const auto output_requests = [&] {
    out << "*NODE FILE\nU, RF\n";
    if (!problem.couplings.empty())
      out << "*NODE PRINT, NSET=REFERENCE_NODES\nU, RF\n";
    if (!pairs.empty())
      out << "*CONTACT FILE\nCSTR\n";
    for (const std::string& name : node_sets)
      out << "*NODE PRINT, NSET=" << deck_name("N_", name) << ", TOTALS=ONLY\nRF\n";
    if (problem.has_plastic_body())
    {
      out << "*EL FILE\nS, PE\n";
      for (int32_t b = 0; b < mesh.n_bodies(); ++b)
        if (problem.materials[b].is_plastic())
          out << "*EL PRINT, ELSET=" << deck_name("B_", mesh.body_names[b]) << "\nPEEQ\n";
    }
    out << "*END STEP\n";
  };
  write_initial_temperatures(out, problem, nodes);
  write_amplitudes(out, problem);
  write_step(out, problem, options, pairs, nodes, summary);
  write_temperatures(out, problem, problem.steps.front(), nodes);
  output_requests();
  if (problem.steps.size() > 1)
  {
    const fem::LoadHistory history(problem, {.default_steps = options.increments});
    for (int stage = 2; stage <= history.n_stages(); ++stage)
    {
      write_later_step(out, problem, history, stage, options, pairs, nodes, summary);
      write_temperatures(out, problem, problem.steps[stage - 1], nodes);
      output_requests();
    }
  }
  FETICON_CHECK(out.good(), "calculix export: writing the deck failed");
  return summary;
}
} // namespace feticon::io
