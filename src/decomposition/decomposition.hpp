#pragma once
/// @file Decomposition: the mesh torn into subdomains, each with its own copy of its nodes.
///
/// Primal unknowns of all subdomains are stacked: subdomain s owns the index range
/// [offset(s), offset(s) + n_dofs(s)). Within a subdomain, DOFs are the active components
/// of its local nodes: every node has 3 components except those eliminated for the whole
/// problem (plane strain: u_z = 0 everywhere is eliminated, not enforced by multipliers,
/// which keeps the dual small and the kernel 3-dimensional; ALGORITHMS.md section 7).
///
/// Distributed over MPI ranks, every rank knows the layout of all subdomains (cells, node
/// copies: integers of the size of the mesh) but owns a contiguous range of them, balanced
/// by DOFs, and only those are assembled and factorized (SubdomainSystem). A rank's stacked
/// vector holds its owned subdomains only: it is a contiguous slice of the global stacked
/// vector, so gathering the slices in rank order gives the global one (gather_stacked).

#include "decomposition/partition.hpp"
#include "fem/assembler.hpp"
#include "la/types.hpp"
#include "par/communicator.hpp"

#include <array>
#include <utility>
#include <vector>

namespace feticon::decomposition
{
struct Subdomain
{
  int32_t id = 0;
  int32_t body = 0;
  fem::AssemblyDomain domain;          ///< cells and local node numbering
  std::vector<int32_t> active_of_full; ///< local full DOF 3n+i -> active DOF, -1 if eliminated
  std::vector<int32_t> full_of_active; ///< active DOF -> local full DOF 3n+i
  int32_t n_dofs() const { return static_cast<int32_t>(full_of_active.size()); }
};

/// A copy of a mesh node in one subdomain.
struct NodeCopy
{
  int32_t subdomain;
  int32_t local_node;
};

class Decomposition
{
public:
  /// @param eliminated components removed from every node (e.g. {false,false,true} for
  ///        plane strain u_z = 0), so they are neither unknowns nor multipliers.
  /// @param comm         ranks that share the subdomains (each owns a contiguous range)
  Decomposition(const mesh::Mesh& mesh, const Partition& partition,
                std::array<bool, 3> eliminated = {false, false, false},
                par::Communicator comm = par::Communicator::self());

  const mesh::Mesh& mesh() const { return _mesh; }
  int32_t n_subdomains() const { return static_cast<int32_t>(_subdomains.size()); }
  const Subdomain& subdomain(int32_t s) const { return _subdomains[s]; }
  const std::vector<Subdomain>& subdomains() const { return _subdomains; }
  const std::array<bool, 3>& eliminated() const { return _eliminated; }

  const par::Communicator& comm() const { return _comm; }
  /// Owned subdomains [first_owned, end_owned) and the rank that owns subdomain s.
  int32_t first_owned() const { return _rank_first[_comm.rank()]; }
  int32_t end_owned() const { return _rank_first[_comm.rank() + 1]; }
  bool owns(int32_t s) const { return s >= first_owned() && s < end_owned(); }
  int owner_rank(int32_t s) const;

  /// Stacked primal DOFs of the owned subdomains and the local start of owned subdomain s.
  int64_t n_primal() const { return _offsets[end_owned()] - _offsets[first_owned()]; }
  int64_t offset(int32_t s) const { return _offsets[s] - _offsets[first_owned()]; }
  /// Start of subdomain s in the global stacked vector.
  int64_t global_offset(int32_t s) const { return _offsets[s]; }
  /// Stacked primal DOFs of all subdomains.
  int64_t n_primal_global() const { return _offsets.back(); }
  /// The global stacked vector from every rank's owned slice, and this rank's slice of it.
  la::Vector gather_stacked(const la::Vector& stacked) const;
  la::Vector owned_slice(const la::Vector& global_stacked) const;
  /// Copies of mesh node `node` (one per subdomain that touches it).
  const std::vector<NodeCopy>& copies(int32_t node) const { return _copies[node]; }
  /// Subdomain id of every cell.
  const std::vector<int32_t>& cell_subdomain() const { return _partition.cell_subdomain; }

  /// Owned stacked vector holding the global (3 per mesh node) values at every copy.
  la::Vector scatter_copy(const la::Vector& global) const;
  /// Owned stacked vector with each global value split equally among the copies (forces).
  la::Vector scatter_split(const la::Vector& global) const;
  /// Global vector from a global stacked vector (gather_stacked): mean over copies
  /// (displacements); eliminated components are 0.
  la::Vector gather_mean(const la::Vector& global_stacked) const;
  /// Global vector from a global stacked vector: sum over copies (forces).
  la::Vector gather_sum(const la::Vector& global_stacked) const;
  /// Segment of an owned stacked vector for owned subdomain s.
  Eigen::VectorBlock<la::Vector> segment(la::Vector& stacked, int32_t s) const;
  Eigen::VectorBlock<const la::Vector> segment(const la::Vector& stacked, int32_t s) const;

private:
  const mesh::Mesh& _mesh;
  Partition _partition;
  std::array<bool, 3> _eliminated;
  std::vector<Subdomain> _subdomains;
  par::Communicator _comm;
  std::vector<int32_t> _rank_first; ///< rank r owns subdomains [_rank_first[r], _rank_first[r+1])
  std::vector<int64_t> _offsets;    ///< global stacked offsets of all subdomains
  std::vector<std::vector<NodeCopy>> _copies;
};
} // namespace feticon::decomposition
