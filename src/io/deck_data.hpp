#pragma once
/// @file What the keyword handlers of an input deck collect (deck_keywords.cpp), in the
/// deck's terms, before deck_model.cpp makes a fem::Problem of it. Nodes and elements are
/// stored once, as mesh arrays indexed in reading order, with their deck labels beside.

#include "fem/amplitude.hpp"
#include "fem/material.hpp"
#include "fem/step.hpp"
#include "io/deck.hpp"
#include "io/deck_tokenizer.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <deque>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace feticon::io
{
/// Deck label -> index in reading order. No table at all while every label is its index + 1
/// (the numbering of most decks); then a dense table while the labels are compact, and a hash
/// map for labels far beyond the count.
class LabelIndex
{
public:
  /// Registers `label` as index `index`; false if the label is known already.
  bool insert(int64_t label, int32_t index);
  /// Makes room for `labels` labels numbered from 1 (the outline's count).
  void reserve(int64_t labels);
  /// The index of `label`, or -1.
  int32_t find(int64_t label) const;

private:
  /// Labels 1.._identity are indices 0.._identity-1 (no table), until the first label that
  /// breaks the rule; -1 after that.
  int64_t _identity = 0;
  int64_t _reserve = 0;        ///< the outline's count, for the dense table once it is needed
  std::vector<int32_t> _dense; ///< index + 1 by label, 0 if absent
  int64_t _count = 0;
  std::unordered_map<int64_t, int32_t> _sparse;
};

/// A node or element set while reading: runs of consecutive indices in the order given. The
/// sets *NODE, NSET= and *ELEMENT, ELSET= and GENERATE build are a single run however large,
/// so the reader holds them in a few bytes, not 4 bytes a member.
class IndexRuns
{
public:
  void push_back(int32_t index)
  {
    if (!_runs.empty() && _runs.back().last + 1 == index)
      ++_runs.back().last;
    else
      _runs.push_back({index, index});
    ++_size;
  }
  void append(const std::vector<int32_t>& indices)
  {
    for (const int32_t i : indices)
      push_back(i);
  }
  int64_t size() const { return _size; }
  template <class F>
  void for_each(F&& f) const
  {
    for (const Run& run : _runs)
      for (int32_t i = run.first;; ++i)
      {
        f(i);
        if (i == run.last)
          break;
      }
  }
  std::vector<int32_t> expand() const
  {
    std::vector<int32_t> out;
    out.reserve(static_cast<size_t>(_size));
    for_each([&](int32_t i) { out.push_back(i); });
    return out;
  }
  /// Sorts and drops repeats once the set holds more than twice the entities there are: a set
  /// that names itself ("*NSET, NSET=A" / "A, A") doubles with each line, and a few lines
  /// would take all memory. The model sorts and unifies every set anyway.
  void compact(size_t n_entities)
  {
    if (static_cast<size_t>(_size) <= 2 * n_entities + 1024)
      return;
    std::vector<int32_t> members = expand();
    std::sort(members.begin(), members.end());
    members.erase(std::unique(members.begin(), members.end()), members.end());
    *this = {};
    append(members);
  }

private:
  struct Run
  {
    int32_t first, last;
  };
  std::vector<Run> _runs;
  int64_t _size = 0;
};

/// A face of an element surface: cell index and CalculiX face number 1..6.
struct DeckFace
{
  int32_t cell;
  int face;
};

/// The key of the node surface NAME where an element surface has that name too (CalculiX keeps
/// the two kinds apart: "*SURFACE, TYPE=NODE" and "TYPE=ELEMENT" may share a name).
inline std::string node_surface_key(const std::string& name) { return name + " (NODE)"; }

struct DeckSurface
{
  bool node_based = false;
  std::vector<DeckFace> faces; ///< TYPE=ELEMENT
  std::vector<int32_t> nodes;  ///< TYPE=NODE
  DeckPosition where;
};

/// *TRANSFORM (model data): a rectangular system (TYPE=R, the default) or a cylindrical one
/// (TYPE=C) from points a and b, as CalculiX defines them (fem/node_frames.hpp).
struct DeckTransform
{
  bool cylindrical = false;
  Eigen::Vector3d a, b;
  DeckPosition where;
};

struct DeckSection
{
  std::string elset, material;
  DeckPosition where;
  double thickness = 0; ///< the data line's first field (2D cells), 0 if not given
};

/// *FRICTION under a *SURFACE INTERACTION (CalculiX's data line: mu, stick slope).
struct DeckFriction
{
  double coefficient = 0; ///< Coulomb's mu, >= 0 (0: frictionless)
  double stick_slope = 0; ///< CalculiX's penalty slope of the stick range (Pa/m); 0 if not given
  DeckPosition where;
};

struct DeckContactPair
{
  std::string interaction, slave, master;
  bool node_to_surface = true; ///< CalculiX's default TYPE
  double adjust = 0;           ///< ADJUST=distance (m); 0: none
  std::string adjust_set;      ///< ADJUST=node set
  DeckPosition where;
};

/// *TIE (CalculiX: model data; one line "slave surface, master surface").
struct DeckTie
{
  std::string name, slave, master;
  double position_tolerance = 0; ///< POSITION TOLERANCE= (m); 0: the default rule (fem::Tie)
  bool adjust = true;            ///< ADJUST=NO turns it off
  bool cyclic = false;           ///< CYCLIC SYMMETRY: its *CYCLIC SYMMETRY MODEL gives `symmetry`
  std::optional<fem::Tie::CyclicSymmetry> symmetry = {};
  DeckPosition where;
};

/// *RIGID BODY, *COUPLING with *KINEMATIC or *DISTRIBUTING, *DISTRIBUTING COUPLING, *PRE-TENSION
/// SECTION (fem/coupling.hpp), as the deck gives them; the model builder resolves the names.
struct DeckCoupling
{
  fem::CouplingKind kind = fem::CouplingKind::kinematic;
  std::string name;      ///< for messages: "*RIGID BODY (line 31)", "*COUPLING C1 (line 40)"
  int32_t ref_node = -1; ///< node in reading order; -1: the origin (*RIGID BODY without REF NODE)
  int32_t rot_node = -1; ///< *RIGID BODY's ROT NODE, whose DOFs 1-3 are the rotations; -1: none
  /// What it couples: a node set or an element set (*RIGID BODY), a surface (*COUPLING)
  std::string node_set, element_set, surface;
  std::array<bool, 3> components{true, true, true}; ///< *KINEMATIC's DOFs
  std::array<bool, 3> moments{false, false, false}; ///< *DISTRIBUTING's DOFs 4-6
  /// *DISTRIBUTING COUPLING's lines: a node label or a node set name, and its weight
  struct Weighted
  {
    std::string nodes;
    double weight;
    DeckPosition where;
  };
  std::vector<Weighted> weighted = {};
  /// *PRE-TENSION SECTION's normal (its data line); zero: the surface's mean outward normal
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  DeckPosition where;
};

/// A load or prescribed value with the amplitude its keyword names (AMPLITUDE=; empty: the
/// step's ramp).
struct DeckValue
{
  double value = 0;
  std::string amplitude;
  bool operator==(const DeckValue&) const = default;
  auto operator<=>(const DeckValue&) const = default;
};

/// *DLOAD GRAV (g x, y, z) or CENTRIF (omega^2, the axis's point and direction) on a cell.
struct DeckBodyLoad
{
  std::array<double, 7> values{};
  std::string where; ///< the deck line that gave it
  std::string amplitude;
};

/// The loads and supports in force at the end of a step (CalculiX's OP=MOD and OP=NEW
/// applied): DOF 3*node+component -> value, (cell, face 1..6) -> pressure.
struct DeckLoadState
{
  std::map<int64_t, DeckValue> boundary;
  std::map<int64_t, DeckValue> cload;
  /// DOFs 4 to 6 (3 node + dof - 4): reference nodes' rotations and moments (fem/coupling.hpp)
  std::map<int64_t, DeckValue> boundary_rotation;
  std::map<int64_t, DeckValue> cload_moment;
  std::map<std::pair<int32_t, int>, DeckValue> dload;
  /// (cell, 0 GRAV / 1 CENTRIF) -> the load.
  std::map<std::pair<int32_t, int>, DeckBodyLoad> body;
  std::map<int32_t, DeckValue> temperature; ///< node -> *TEMPERATURE
  /// (slave, master) of the pairs *MODEL CHANGE, REMOVE took out -> the line that did
  std::map<std::pair<std::string, std::string>, std::string> removed_pairs;
  /// Interaction -> the friction a *CHANGE FRICTION gave it (this step and the next ones).
  std::map<std::string, DeckFriction> frictions;
  /// Interaction -> whether the law a *CHANGE SURFACE BEHAVIOR gave it is TIED (this step and
  /// the next ones; else the model's: DeckData::tied_interactions).
  std::map<std::string, bool> tied;
  /// Interaction -> the contact law a *CHANGE SURFACE BEHAVIOR gave it (not TIED; this step and
  /// the next ones).
  std::map<std::string, fem::NormalLaw> laws;
};

struct DeckData
{
  Labels node_labels;
  /// Rows 0 .. node_labels.size() hold x, y, z per node; sized from the outline's count, so
  /// that it becomes the mesh's node array without a copy when every node is used.
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> coordinates;
  LabelIndex node_index;
  Labels element_labels;
  mesh::CellList cells;                  ///< node indices, CalculiX's order (mesh/cell_type.hpp)
  std::vector<char> reduced_integration; ///< per cell: C3D20R (mesh::Mesh::reduced_integration)
  LabelIndex element_index;

  std::map<std::string, IndexRuns> node_sets;    ///< node indices, may repeat
  std::map<std::string, IndexRuns> element_sets; ///< cell indices, may repeat
  /// By name; a node surface whose name an element surface has too under node_surface_key.
  std::map<std::string, DeckSurface> surfaces;
  std::map<std::string, fem::Material> materials;
  std::string first_material; ///< the name of the deck's first *MATERIAL (CalculiX's default K)
  std::vector<DeckSection> sections;
  /// The formulation of the 2D cells (CPE*: plane strain, CPS*: plane stress, CAX*:
  /// axisymmetric) of the first cell block; none if the cells are 3D.
  mesh::PlanarKind planar = mesh::PlanarKind::none;
  DeckPosition first_cells;
  /// Per cell, its element type's formulation (2D decks may mix them as CalculiX allows).
  std::vector<mesh::PlanarKind> cell_planar;
  std::set<std::string> interactions;
  std::map<std::string, DeckFriction> frictions; ///< by interaction name
  std::vector<DeckContactPair> pairs;
  std::vector<DeckTie> ties;
  std::vector<DeckCoupling> couplings;
  /// The node label of each DCOUP3D element set (*ELEMENT, TYPE=DCOUP3D): a reference node
  std::map<std::string, int64_t> coupling_elements;
  /// Interactions whose *SURFACE BEHAVIOR is PRESSURE-OVERCLOSURE=TIED: their pairs are ties.
  std::set<std::string> tied_interactions;
  /// Interactions' contact laws (*SURFACE BEHAVIOR other than TIED; none given: hard). A linear
  /// slope of 0 stands for CalculiX's default, 50 times the first material's E.
  std::map<std::string, fem::NormalLaw> laws;
  std::vector<fem::LinearEquation> equations;
  std::vector<DeckTransform> transforms;
  /// Node -> its transform (index into `transforms`; the last one given wins, as in CalculiX).
  std::map<int32_t, int32_t> node_transform;

  std::map<int32_t, double> initial_temperatures; ///< node -> *INITIAL CONDITIONS, TYPE=TEMPERATURE
  /// Supports given before the first *STEP (model data): in force in every step.
  std::map<int64_t, DeckValue> model_boundary;
  std::map<int64_t, DeckValue> model_boundary_rotation; ///< DOFs 4-6, as DeckLoadState's
  std::map<std::string, fem::Amplitude> amplitudes;     ///< *AMPLITUDE by name
  std::map<std::string, std::string> amplitude_uses;    ///< AMPLITUDE= name -> where first named
  DeckLoadState state;                                  ///< the current step's
  std::vector<DeckStep> steps;
  std::vector<DeckLoadState> step_states; ///< at the end of every step

  std::vector<std::string> warnings;
  std::set<std::string> warned;       ///< each warning once
  std::deque<std::string> file_names; ///< what the positions above point to

  void warn(const std::string& line)
  {
    if (warned.insert(line).second)
      warnings.push_back(line);
  }
};

/// The largest friction coefficient a deck may give: the range of contact.friction.coefficient.
constexpr double largest_friction_coefficient = 100;

/// A real number of a deck's data field (a leading '+' and Fortran's exponent 1.5D3 allowed),
/// or nothing if the field is not one finite number.
std::optional<double> parse_deck_real(std::string_view field);

/// Runs the keyword handlers over the whole deck; `outline` sizes the node and cell arrays.
DeckData read_deck_data(const std::filesystem::path& path, const DeckOutline& outline);
} // namespace feticon::io
