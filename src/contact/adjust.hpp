#pragma once
/// @file ADJUST of a contact pair (CalculiX's and Abaqus's *CONTACT PAIR, ADJUST=): before the
/// first increment, slave nodes are moved onto the master surface, so that a mesh whose
/// surfaces were meant to touch starts touching (no gap to close, no overlap to push out).
///
/// For each pair with fem::ContactPairNames::adjust > 0 (a distance) or adjust_nodes (a node
/// set): the node-to-segment closest point of every slave node (contact_constraints.hpp, in
/// the reference configuration) gives its gap g along the master's outward normal n; a node
/// with g <= adjust (CalculiX: "clearance smaller than or equal", penetrating nodes included),
/// or in the node set, moves by -g n onto the master face (or its edge, for a node in the blind
/// spot of a convex master edge). A node without a closest point within one master element (or
/// the distance, if larger) stays.
///
/// Usage (app/problem_setup.cpp, before the solver sees the problem):
///   fem::Problem problem = io::read_deck(path).problem;
///   const int64_t moved = contact::adjust_slave_nodes(problem);

#include "fem/problem.hpp"

#include <cstdint>

namespace feticon::contact
{
/// Moves the slave nodes of every pair with an ADJUST (see file comment) in problem.mesh;
/// returns how many nodes moved.
int64_t adjust_slave_nodes(fem::Problem& problem);
} // namespace feticon::contact
