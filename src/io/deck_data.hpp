#pragma once
/// @file What the keyword handlers of an input deck collect (deck_keywords.cpp), in the
/// deck's terms, before deck_model.cpp makes a fem::Problem of it. Nodes and elements are
/// stored once, as mesh arrays indexed in reading order, with their deck labels beside.

#include "fem/material.hpp"
#include "io/deck.hpp"
#include "io/deck_tokenizer.hpp"
#include "mesh/hex_mesh.hpp"

#include <deque>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace feticon::io
{
/// Deck label -> index in reading order: a dense table while the labels are compact (the
/// usual 1..n), a hash map otherwise.
class LabelIndex
{
public:
  /// Registers `label` as index `index`; false if the label is known already.
  bool insert(int64_t label, int32_t index);
  /// The index of `label`, or -1.
  int32_t find(int64_t label) const;

private:
  std::vector<int32_t> _dense; ///< index + 1 by label, 0 if absent
  int64_t _count = 0;
  std::unordered_map<int64_t, int32_t> _sparse;
};

/// A face of an element surface: cell index and CalculiX face number 1..6.
struct DeckFace
{
  int32_t cell;
  int face;
};

struct DeckSurface
{
  bool node_based = false;
  std::vector<DeckFace> faces;  ///< TYPE=ELEMENT
  std::vector<int32_t> nodes;   ///< TYPE=NODE
  DeckPosition where;
};

struct DeckSection
{
  std::string elset, material;
  DeckPosition where;
};

struct DeckContactPair
{
  std::string interaction, slave, master;
  bool node_to_surface = true; ///< CalculiX's default TYPE
  DeckPosition where;
};

/// The loads and supports in force at the end of a step (CalculiX's OP=MOD and OP=NEW
/// applied): DOF 3*node+component -> value, (cell, face 1..6) -> pressure.
struct DeckLoadState
{
  std::map<int64_t, double> boundary;
  std::map<int64_t, double> cload;
  std::map<std::pair<int32_t, int>, double> dload;
};

struct DeckData
{
  std::vector<int64_t> node_labels;
  /// Rows 0 .. node_labels.size() hold x, y, z per node; sized from the outline's count, so
  /// that it becomes the mesh's node array without a copy when every node is used.
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> coordinates;
  LabelIndex node_index;
  std::vector<int64_t> element_labels;
  std::vector<mesh::Cell> cells; ///< node indices, VTK hex order (= CalculiX C3D8 order)
  LabelIndex element_index;

  std::map<std::string, std::vector<int32_t>> node_sets;    ///< node indices, may repeat
  std::map<std::string, std::vector<int32_t>> element_sets; ///< cell indices, may repeat
  std::map<std::string, DeckSurface> surfaces;
  std::map<std::string, fem::Material> materials;
  std::vector<DeckSection> sections;
  std::set<std::string> interactions;
  std::vector<DeckContactPair> pairs;
  std::vector<fem::LinearEquation> equations;

  /// Supports given before the first *STEP (model data): in force in every step.
  std::map<int64_t, double> model_boundary;
  DeckLoadState state; ///< the current step's
  std::vector<DeckStep> steps;
  std::vector<DeckLoadState> step_states; ///< at the end of every step

  std::vector<std::string> warnings;
  std::set<std::string> warned; ///< each warning once
  std::deque<std::string> file_names; ///< what the positions above point to

  void warn(const std::string& line)
  {
    if (warned.insert(line).second)
      warnings.push_back(line);
  }
};

/// Runs the keyword handlers over the whole deck; `outline` sizes the node and cell arrays.
DeckData read_deck_data(const std::filesystem::path& path, const DeckOutline& outline);
} // namespace feticon::io
