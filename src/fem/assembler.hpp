#pragma once
/// @file Sparse assembly of stiffness and internal force over a set of cells.
///
/// The same assembler serves the undecomposed mesh (direct reference solves, primal
/// penalty) and each FETI subdomain (its cells with local node numbering). The node
/// adjacency is built once; each assembly writes K's pattern from it and adds the element
/// matrices in place, so no triplet list of 576 entries per cell is ever held in memory.
/// hex8 cells of elastic bodies go through hex8_element (fixed-size, the fast path), every
/// other cell through cell_element.
///
/// The cells of plastic bodies keep a J2 state per quadrature point: the state committed at
/// the end of the last converged increment. f_int(u) and K(u) return from it (so a cut-back
/// increment rolls back by not committing), and commit_plastic_state(u) makes the states at u
/// the committed ones.

#include "fem/hex8_element.hpp"
#include "fem/j2_plasticity.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <vector>

namespace feticon::fem
{
/// A set of cells and the local numbering of the nodes they touch.
struct AssemblyDomain
{
  std::vector<int32_t> cells;           ///< cell ids of the mesh
  std::vector<int32_t> local_to_global; ///< local node -> mesh node, increasing
  /// Local node ids of each cell, in the order of `cells`. Kept instead of a mesh-sized
  /// global-to-local map, which cost every subdomain O(mesh) memory and setup time
  /// (docs/measurements.md).
  mesh::CellList cell_nodes;

  int32_t n_nodes() const { return static_cast<int32_t>(local_to_global.size()); }
  int64_t n_dofs() const { return 3 * static_cast<int64_t>(local_to_global.size()); }
};

/// Domain of the given cells, local nodes in increasing mesh id order.
AssemblyDomain make_domain(const mesh::Mesh& mesh, std::vector<int32_t> cells);
/// Domain of every cell; local numbering equals mesh numbering.
AssemblyDomain whole_mesh_domain(const mesh::Mesh& mesh);

/// Which nodes share a cell, compressed: the neighbours of node n (itself included) are
/// neighbours[offsets[n], offsets[n + 1]), increasing.
struct NodeAdjacency
{
  std::vector<int64_t> offsets;
  std::vector<int32_t> neighbours;
};

/// Assembles K and f_int of one domain. DOF 3*n + i is component i of local node n.
class Assembler
{
public:
  /// @param body_materials one material per body of the mesh (indexed by cell_body)
  Assembler(const mesh::Mesh& mesh, AssemblyDomain domain, std::vector<Material> body_materials, Kinematics kinematics);
  /// The mesh the cells are of.
  const mesh::Mesh& mesh() const { return _mesh; }

  const AssemblyDomain& domain() const { return _domain; }
  Kinematics kinematics() const { return _kinematics; }

  /// Stiffness at displacement `u` (local DOFs). Linear kinematics ignore `u` for K.
  la::SparseMatrix stiffness(const la::Vector& u, StiffnessKind kind) const;
  /// Internal force at displacement `u`.
  la::Vector internal_force(const la::Vector& u) const;
  /// Both in one pass over the cells (either output may be null).
  void assemble(const la::Vector& u, StiffnessKind kind, la::SparseMatrix* K, la::Vector* f_int) const;

  /// @brief The temperature change T - T_0 (K) of each local node for the assemblies that follow
  /// (thermal strain, fem/hex8_element.hpp); empty: none. The load history sets it at every
  /// load step (fem/temperature_history.hpp).
  void set_temperature_change(la::Vector temperature_change);

  /// True if some cell of the domain belongs to a plastic body.
  bool has_plastic_cells() const { return !_plastic_committed.empty(); }
  /// True if some cell of the domain belongs to a hyperelastic body.
  bool has_hyperelastic_cells() const;
  /// Makes the J2 states at displacement `u` the committed ones (the end of a converged increment).
  void commit_plastic_state(const la::Vector& u);
  /// The committed states of the quadrature points of the domain's k-th cell (empty: elastic).
  std::span<const PlasticPointState> plastic_state(size_t k) const;
  /// Replaces every committed state (a restart), in the order of plastic_state(0), (1), ...
  void set_plastic_state(std::vector<PlasticPointState> states);

  /// Reference coordinates of the domain's nodes, one row per local node.
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> local_coordinates() const;

private:
  const mesh::Mesh& _mesh;
  AssemblyDomain _domain;
  std::vector<Material> _materials;
  Kinematics _kinematics;
  la::Vector _temperature_change; ///< per local node; empty: none
  /// The committed J2 states: those of domain cell k are [_plastic_offset[k], _plastic_offset[k + 1]).
  std::vector<int64_t> _plastic_offset;
  std::vector<PlasticPointState> _plastic_committed;
  /// assemble() with, where `updated` is not null, the states at u written into it.
  void assemble_cells(const la::Vector& u, StiffnessKind kind, la::SparseMatrix* K, la::Vector* f_int,
                      std::vector<PlasticPointState>* updated) const;
  /// The sparsity pattern of K, kept per node (a ninth of K's indices, none of its values):
  /// a zero-valued copy of K held as much memory as K for the whole run.
  NodeAdjacency _adjacency;
};
} // namespace feticon::fem
