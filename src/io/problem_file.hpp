#pragma once
/// @file Problem files: YAML describing the mesh, bodies, supports, loads, contact pairs and
/// the solver settings of a run, with command-line overrides applied to the YAML tree.
///
/// Top level (every key optional; see examples/ and `feticon run --help`):
///   problem: custom, or a built-in problem (problems/built_in_problem.hpp)
///   mesh:                          (custom)
///     file: punch.msh              Gmsh file, physical groups name bodies and sets, or
///     boxes:                       built-in boxes, each a body named <name>, its sets
///       - {name: base, origin: [0,0,0], lengths: [1,1,0.5], cells: [8,8,4]}  <name>_xmin, ...
///   bodies: {base: {young: 2e11, poisson: 0.3}, ...}   (custom: one entry per body)
///   plane_strain: false            u_z = 0 everywhere, eliminated
///   supports: [{set: base_zmin, x: 0, y: 0, z: 0}, ...]   prescribed displacement (m)
///   loads: [{set: punch_zmax, traction: [0, 0, -1e8]}, ...]  dead traction (Pa)
///   contact: [{slave: punch_zmin, master: base_zmax}]
///   method, rho, qp: {rtol: ...}, ...  the solver keys of io::Settings
/// Overrides KEY=VALUE address any node by its dotted path (list items by index:
/// loads.0.traction=[0,0,-2e8]); VALUE is parsed as YAML.

#include "fem/problem.hpp"
#include "io/deck.hpp"
#include "io/settings.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

namespace feticon::io
{
struct ProblemFile
{
  YAML::Node root;              ///< the tree after overrides (written to the results)
  Settings settings;            ///< solver, output and built-in problem keys
  std::string source;           ///< file name for messages ("defaults" without a file)
  std::filesystem::path folder; ///< folder of the file: relative mesh paths start here
  /// The input deck that gives the model (`feticon run model.inp`, or mesh.file: model.inp),
  /// empty if none.
  std::filesystem::path deck;
  DeckOutline deck_outline; ///< of `deck`, scanned once when the file is loaded
};

/// True for the file names of input decks: `.inp` in any case.
bool is_deck_file(const std::filesystem::path& path);

/// Reads `path` (empty: defaults only), applies `overrides`, validates every key. An input
/// deck (is_deck_file) is a custom problem whose model is the deck, with the settings it
/// implies (displacements from NLGEOM, load_steps from *STATIC, contact.formulation from the
/// pairs' TYPE) below the overrides. `declared`: the keys of the layers above io (the built-in
/// problems' problems::setting_specs), see io::Settings.
ProblemFile load_problem_file(const std::filesystem::path& path, const std::vector<std::string>& overrides,
                              const std::vector<SettingSpec>& declared);

/// As load_problem_file for a problem given as YAML text (JSON is YAML too), not a file:
/// `source` names it in messages, relative paths in it start at `folder`.
ProblemFile load_problem_text(const std::string& text, const std::string& source, const std::filesystem::path& folder,
                              const std::vector<std::string>& overrides, const std::vector<SettingSpec>& declared);

/// The size of a `problem: custom` file's mesh before it is built or read: nodes of the
/// boxes, or as declared in the Gmsh file's header (memory guard).
struct CustomMeshSize
{
  int64_t nodes = 0;
  bool plane_strain = false;
};
CustomMeshSize custom_mesh_size(const ProblemFile& file);

/// The problem of a `problem: custom` file: mesh, bodies, supports, loads, contact.
/// A deck's model is read by io::read_deck instead (the caller keeps its DeckInfo).
fem::Problem build_custom_problem(const ProblemFile& file);

/// The structured sections (not in the Settings registry).
bool is_structured_key(const std::string& top_level_key);
} // namespace feticon::io
