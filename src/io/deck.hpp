#pragma once
/// @file A CalculiX / Abaqus input deck (`.inp`) as feticon's model: the problem, the step's
/// settings, the output requests and the deck's own numbering, for `feticon run model.inp`.
///
/// The keyword format is the one of the CalculiX CrunchiX user's manual, chapter "Input deck
/// format" (shared with Abaqus). deck_tokenizer.hpp splits the text into keyword and data
/// lines with their positions, deck_keywords.cpp handles each keyword, deck_model.cpp turns
/// what they collected into a fem::Problem. What feticon does not implement is a one-line
/// error naming the keyword, file and line; what it reads but does not honour is a line of
/// `warnings`.

#include "fem/problem.hpp"
#include "io/result_labels.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace feticon::io
{
/// One output request of a step (*NODE PRINT, *EL PRINT, *CONTACT PRINT, *NODE FILE,
/// *EL FILE, *CONTACT FILE): what CalculiX would write to the .dat or .frd file.
struct DeckOutputRequest
{
  enum class Kind
  {
    node_print,
    el_print,
    contact_print,
    node_file,
    el_file,
    contact_file
  };
  enum class Totals
  {
    no,
    yes,
    only
  };
  Kind kind = Kind::node_print;
  std::string set;                    ///< NSET= or ELSET= as in the deck (upper case); empty: all
  std::vector<std::string> variables; ///< upper case: U, RF, S, E, CSTR, CDIS, ...
  Totals totals = Totals::no;
  std::string where; ///< "file:line" of the keyword, for messages
  /// GLOBAL=: vectors of nodes with a *TRANSFORM in global (true) or local components; unset:
  /// CalculiX's default, local in *NODE PRINT, global in *NODE FILE.
  std::optional<bool> global = {};
};

/// A *STEP of the deck: its kinematics, increments and output requests.
struct DeckStep
{
  bool nlgeom = false;
  /// *STATIC, DIRECT: load steps of the step, total time / initial increment (rounded up).
  std::optional<int> increments = {};
  /// *STATIC without DIRECT: automatic increments (fem::LoadHistory).
  std::optional<fem::IncrementControl> automatic = {};
  double time = 1.0; ///< the step's time (*STATIC), for CalculiX's total time in the outputs
  bool ramp = true;  ///< *STEP, AMPLITUDE=RAMP (the default) or STEP
  std::vector<DeckOutputRequest> outputs;
  std::string where;
};

/// What a deck holds beside the problem: its steps, numbering, element sets and warnings.
struct DeckInfo
{
  std::vector<DeckStep> steps;
  Labels node_labels;    ///< deck number of every mesh node
  Labels element_labels; ///< deck number of every mesh cell
  /// Element sets by deck name (mesh cell indices, sorted).
  std::map<std::string, std::vector<int32_t>> element_sets;
  /// What the deck says that feticon reads but does not honour exactly, one line each.
  std::vector<std::string> warnings;
  std::filesystem::path path;
  /// Reference nodes of couplings that no element uses (fem/coupling.hpp): printed by *NODE
  /// PRINT as CalculiX prints them, U and RF of reference DOFs first_dof .. first_dof + 2 (a
  /// *RIGID BODY's ROT NODE: the rotations and moments).
  struct ReferenceNode
  {
    int64_t label;
    int32_t coupling;
    int first_dof; ///< 0 or 3
  };
  std::vector<ReferenceNode> reference_nodes;
  /// Node sets by deck name -> the reference nodes (indices into reference_nodes) they hold.
  std::map<std::string, std::vector<int32_t>> reference_node_sets;
};

struct Deck
{
  fem::Problem problem; ///< nodes and cells renumbered 0.., sets under their deck names (upper case)
  DeckInfo info;
};

/// Reads the deck `path` (and its *INCLUDEs).
/// @throws feticon::Error with one line "FILE:LINE: what is wrong" for anything malformed or
///   not implemented.
Deck read_deck(const std::filesystem::path& path);

/// What a scan of the keyword lines tells before the deck is read (memory guard, settings):
/// data lines under *NODE and *ELEMENT are counted, not parsed.
struct DeckOutline
{
  int64_t nodes = 0;
  int64_t elements = 0;
  bool nlgeom = false; ///< some *STEP has NLGEOM, or a material is hyperelastic (CalculiX turns it on)
  /// Load steps of the first *STATIC if it is DIRECT (feticon's load_steps); unset: automatic.
  std::optional<int> increments = {};
};
DeckOutline deck_outline(const std::filesystem::path& path);

/// read_deck with the outline already scanned (the problem file keeps it: one scan a run).
Deck read_deck(const std::filesystem::path& path, const DeckOutline& outline);
} // namespace feticon::io
