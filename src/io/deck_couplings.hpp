#pragma once
/// @file The deck's reference nodes and couplings (*RIGID BODY, *COUPLING with *KINEMATIC or
/// *DISTRIBUTING, *DISTRIBUTING COUPLING) as fem::Coupling (fem/coupling.hpp), and the supports
/// and loads on reference nodes as a step's reference values.
///
/// CalculiX's reference nodes: a *RIGID BODY's REF NODE carries the translations (DOFs 1-3) and
/// its ROT NODE's DOFs 1-3 are the rotations; a *COUPLING's REF NODE has all six (4-6 the
/// rotations); a *DISTRIBUTING COUPLING's DCOUP3D node has the translations. A reference node
/// that an element uses (CalculiX lets a rigid body's REF NODE belong to it) is a mesh node:
/// its DOFs 1-3 stay the mesh node's.

#include "fem/coupling.hpp"
#include "fem/step.hpp"
#include "io/deck_data.hpp"

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace feticon::io
{
/// What the couplings need of the nodes before they are renumbered (nodes in reading order).
struct DeckReferenceNodes
{
  /// Reference node -> (coupling, the reference DOF its DOFs 1-3 are: 0, or 3 for a ROT NODE)
  std::map<int32_t, std::pair<int32_t, int>> of_node;
  std::vector<Eigen::Vector3d> positions;                        ///< per coupling
  std::vector<std::vector<std::pair<int32_t, double>>> weighted; ///< per mean coupling: node, weight
};

/// @throws feticon::Error naming the keyword for a node that is the reference node of two
///         couplings, or a *DISTRIBUTING COUPLING line naming an unknown node or set
DeckReferenceNodes deck_reference_nodes(const DeckData& data, const std::function<int64_t(int32_t)>& label_of);

/// The couplings, their coupled node sets added to `mesh` as coupling_N_nodes.
/// @param mesh_of        mesh node of a node in reading order, -1 if no element uses it
/// @param element_sets   the deck's element sets as cells
/// @throws feticon::Error naming the keyword for an unknown set or surface, a ROT NODE that an
///         element uses, or a *DISTRIBUTING COUPLING node that no element uses
std::vector<fem::Coupling> deck_couplings(const DeckData& data, const DeckReferenceNodes& reference, mesh::Mesh& mesh,
                                          const std::map<std::string, std::vector<int32_t>>& element_sets,
                                          const std::function<int32_t(int32_t)>& mesh_of,
                                          const std::function<int64_t(int32_t)>& label_of);

/// The values of `translations` and `rotations` (3 node + DOF - 1, DOF - 4 for rotations) on
/// reference nodes. A rotation on a node that is none: a support warns that solid nodes have no
/// rotations (`data.warn`), a moment is refused.
/// @throws feticon::Error for a moment on a node that is no reference node
std::vector<fem::ReferenceValue> reference_values(DeckData& data, const DeckReferenceNodes& reference,
                                                  const std::map<int64_t, DeckValue>& translations,
                                                  const std::map<int64_t, DeckValue>& rotations, bool supports,
                                                  const std::function<int32_t(int32_t)>& mesh_of,
                                                  const std::function<int64_t(int32_t)>& label_of);
} // namespace feticon::io
