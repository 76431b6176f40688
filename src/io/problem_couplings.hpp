#pragma once
/// @file A problem file's `couplings:` (fem/coupling.hpp) and the supports and loads of its
/// steps that name one (docs/usage.md, "Couplings in problem files"):
///
///   couplings:
///     - {name: tip, kind: kinematic, surface: tip_face, reference: [10, 0.5, 0.5]}
///     - {name: lug, kind: distributing, surface: lug_face, reference: [0, 0, 2], moments: [x, y, z]}
///   supports: [{coupling: tip, x: 0, rz: 0}]             # translations x y z, rotations rx ry rz
///   loads: [{coupling: tip, force: [0, 0, -1e3], moment: [0, 1e4, 0]}]
///
/// A kinematic coupling names a face set (`surface`) or a node set (`nodes`) and optionally the
/// `components` of its nodes that follow the rigid motion (default x, y, z); a distributing one
/// a face set, whose consistent nodal areas spread its loads, and the `moments` it spreads.
///
/// A pretension section (a bolt load; CalculiX's *PRE-TENSION SECTION) joins two bodies that meet
/// at the section with matching meshes (a bolt modelled as two parts):
///
///   couplings: [{name: preload, kind: pretension, surface: shank_top, partner: head_bottom}]
///   supports: [{coupling: preload, gap: 1e-4}]      # the two sides overlap by the gap (m), or
///   loads: [{coupling: preload, tension: 2e4}]      # the section carries the tension (N)
///
/// Each node of the `partner` face set is paired with the node of `surface` at its position; the
/// normal n (`normal:`, else the partner faces' mean outward normal) points away from the partner's
/// cells, as CalculiX's points away from the cells that took the doubled nodes.

#include "fem/problem.hpp"
#include "io/problem_reader.hpp"

#include <yaml-cpp/yaml.h>

#include <vector>

namespace feticon::io
{
/// @throws feticon::Error naming the file and key of what is wrong
/// A pretension section's node pairs become the node sets coupling_N_nodes and coupling_N_partners.
std::vector<fem::Coupling> read_couplings(const YAML::Node& list, mesh::Mesh& mesh, const ProblemReader& r);

/// The entries of a supports (loads) list that name a coupling, as reference values; the others
/// are left to the list's own reader; an entry's amplitude as io::amplitude_of reads it.
/// @throws feticon::Error naming the file and key of what is wrong
std::vector<fem::ReferenceValue> coupling_supports(const YAML::Node& list, const std::string& where,
                                                   const ProblemReader& r, fem::Problem& p);
std::vector<fem::ReferenceValue> coupling_loads(const YAML::Node& list, const std::string& where,
                                                const ProblemReader& r, fem::Problem& p);
} // namespace feticon::io
