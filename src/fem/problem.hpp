#pragma once
/// @file A contact problem as the solvers see it: mesh, materials, supports, loads, pairs.

#include "fem/dirichlet.hpp"
#include "fem/material.hpp"
#include "la/types.hpp"
#include "mesh/hex_mesh.hpp"

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

/// Slave and master face sets of one contact pair (node-to-segment: slave nodes against
/// master faces).
struct ContactPairNames
{
  std::string slave;
  std::string master;
};

struct Problem
{
  std::string name;
  mesh::HexMesh mesh;
  bool mesh_from_cache = false; ///< the mesh came from the mesh cache (mesh/mesh_cache.hpp)
  std::vector<Material> materials; ///< one per body
  std::vector<DirichletCondition> dirichlet;
  std::vector<FaceTraction> tractions;
  std::vector<ContactPairNames> contacts;
  /// Components fixed to zero on every node and eliminated (plane strain: {0,0,1}).
  std::array<bool, 3> eliminated{false, false, false};

  /// Consistent nodal forces of all tractions at load factor 1 (3 DOFs per node).
  la::Vector external_force() const;
  /// Dirichlet DOFs including the eliminated components (for undecomposed solves).
  ConstrainedDofs all_constrained_dofs() const;
  /// Checks materials, set names and sizes; throws feticon::Error naming what is wrong.
  void validate() const;
};
} // namespace feticon::fem
