#pragma once
/// @file A contact problem as the solvers see it: mesh, materials, supports, loads, pairs.

#include "fem/body_loads.hpp"
#include "fem/contact_interaction.hpp"
#include "fem/dirichlet.hpp"
#include "fem/material.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <string>
#include <vector>

namespace feticon::fem
{
/// Uniform dead traction (Pa, force per reference area) on a named face set.
struct FaceTraction
{
  std::string set;
  Eigen::Vector3d traction;
};

/// Uniform dead pressure (Pa, positive pushes into the body, on the reference normals) on a
/// named face set (deck *DLOAD Pn).
struct FacePressure
{
  std::string set;
  double pressure;
};

/// A concentrated dead force (N) on one component of one node (deck *CLOAD).
struct NodalForce
{
  int32_t node;
  int component; ///< 0, 1, 2
  double value;
};

/// Linear multi-point constraint sum_k a_k u(node_k, component_k) = 0 (deck *EQUATION):
/// FETI takes it as an equality row beside the gluing rows.
struct LinearEquation
{
  struct Term
  {
    int32_t node;
    int component; ///< 0, 1, 2
    double coefficient;
  };
  std::vector<Term> terms;
};

/// Slave and master face sets of one contact pair (node-to-segment: slave nodes against
/// master faces) and the interaction between them. A body may be slave in one pair and
/// master in another; the solver builds every pair's rows and keys them by (pair, slave node).
struct ContactPairNames
{
  std::string slave;
  std::string master;
  /// If not empty, a node set: only these nodes of the slave faces carry contact rows (a
  /// deck's node-based slave surface, whose faces give the nodes' tributary areas).
  /// Node-to-segment only: mortar integrates whole slave faces.
  std::string slave_nodes = {};
  ContactInteraction interaction = {};
  /// ADJUST (CalculiX, Abaqus): before the first increment the slave nodes whose gap is at most
  /// this (m; penetrating ones included) are moved onto the master surface
  /// (contact::adjust_slave_nodes). 0: the mesh as it is.
  double adjust = 0;
  /// ADJUST by node set: these slave nodes are moved onto the master surface. Empty: none.
  std::string adjust_nodes = {};
};

/// The loads and prescribed displacements one later stage of the load history reaches at its
/// end (a deck's second and later *STEPs): the history runs linearly from the end of one stage
/// to the end of the next in `increments` load steps. The prescribed components are those of
/// the first stage (Problem::dirichlet); a stage changes their values only.
struct LoadStage
{
  std::vector<FaceTraction> tractions;
  std::vector<FacePressure> pressures;
  std::vector<NodalForce> nodal_forces;
  std::vector<DirichletCondition> dirichlet;
  int increments = 1;
  std::vector<BodyLoad> body_loads = {};
};

struct Problem
{
  std::string name;
  mesh::Mesh mesh;
  bool mesh_from_cache = false;    ///< the mesh came from the mesh cache (mesh/mesh_cache.hpp)
  std::vector<Material> materials; ///< one per body
  std::vector<DirichletCondition> dirichlet;
  std::vector<FaceTraction> tractions;
  std::vector<FacePressure> pressures;
  std::vector<NodalForce> nodal_forces;
  std::vector<BodyLoad> body_loads; ///< gravity and centrifugal loads (fem/body_loads.hpp)
  std::vector<LinearEquation> equations;
  /// Stages after the first (Problem's own loads and supports, reached at load factor 1):
  /// stage k ends at load factor 1 + k. Empty for every problem but multi-step decks.
  std::vector<LoadStage> later_stages;
  /// Any number of pairs, none included (a model held by supports, glued or tied only).
  std::vector<ContactPairNames> contacts;
  /// Components fixed to zero on every node and eliminated (plane strain: {0,0,1}).
  std::array<bool, 3> eliminated{false, false, false};

  /// Consistent nodal forces of all tractions, pressures and nodal forces at load factor 1 (3 DOFs per node).
  la::Vector external_force() const;
  /// Dirichlet DOFs including the eliminated components (for undecomposed solves).
  ConstrainedDofs all_constrained_dofs() const;
  /// Checks materials, set names and sizes; throws feticon::Error naming what is wrong.
  void validate() const;
};
} // namespace feticon::fem
