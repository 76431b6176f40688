#pragma once
/// @file The memory guard (issue 21): a run's peak memory estimated from its size before
/// anything large is allocated, and a one-line refusal when it does not fit the budget.
///
/// The estimate is a model fitted to measured peaks (docs/benchmarks.md): the process with its
/// libraries, plus bytes per degree of freedom that grow with the subdomain size as the
/// Cholesky factors do (nested dissection: nnz(L) ~ n log n in the one-layer plane-strain
/// meshes, ~ n^(4/3) in 3D), plus the dense boundary blocks of dual.operator=explicit with
/// the arrays of forming them. The budget is a rank's share of what its node has available
/// (the smaller of MemAvailable and the cgroup's room: common/available_memory.hpp), or of
/// `memory_limit`. dual.operator = auto is checked as implicit, the run it can always fall
/// back to; the blocks get what the budget leaves (MemoryEstimate::explicit_block_budget),
/// and auto forms them only if they fit it.

#include "io/problem_file.hpp"
#include "mesh/mesh.hpp"

#include <cstdint>
#include <string>

namespace feticon::app
{
/// What the estimate is made of.
struct MemoryEstimate
{
  double bytes = 0;    ///< peak of the whole run, all ranks together
  double per_rank = 0; ///< peak of the busiest rank
  int64_t nodes = 0;   ///< the size it was made for (0 for a QP)
  int subdomains = 0;
  /// dual.operator = auto: the peak of a rank if auto forms the explicit blocks (0: not auto).
  double per_rank_explicit = 0;
  /// dual.operator = auto: bytes per rank left to the blocks and their forming by the budget
  /// (nonlinear::SolverSettings::explicit_block_budget); negative: no budget known.
  double explicit_block_budget = -1;

  /// per_rank, or per_rank_explicit for an auto run whose blocks were formed (`dual_operator`
  /// as the solver reports it: "explicit" or "implicit").
  double per_rank_for(const std::string& dual_operator) const
  {
    return dual_operator == "explicit" && per_rank_explicit > 0 ? per_rank_explicit : per_rank;
  }
};

/// The budget a rank may use and where it comes from.
struct MemoryBudget
{
  double per_rank = -1; ///< negative: unknown (nothing to check against)
  std::string source;   ///< "memory_limit", "MemAvailable" or "the cgroup limit <file>"
};

/// The K_ii factors of the implicit Dirichlet preconditioner (SchurComplements): none, those
/// of a band of the interior (qp.dirichlet_layers > 0) or of the whole interior.
enum class InteriorFactors
{
  none,
  band,
  whole
};

/// What the subdomain factors of a run are: those of K+ always, the K_ii factors of the
/// implicit Dirichlet preconditioner as `interior`, in single or double precision.
struct FactorStorage
{
  InteriorFactors interior = InteriorFactors::none;
  bool single_precision = false;
};

/// Peak memory of a solve of a mesh with `nodes` nodes (plane strain: one cell layer) in
/// `subdomains` subdomains on `ranks` ranks; `explicit_blocks` adds the dense boundary blocks,
/// `factors` the K_ii factors of the implicit Dirichlet preconditioner and the precision.
/// `process`: bytes a rank holds before the solve (0: the model's figure for a process that
/// has loaded Gmsh, before any mesh).
MemoryEstimate estimate_run_memory(int64_t nodes, bool plane_strain, int subdomains, int ranks, bool explicit_blocks,
                                   FactorStorage factors, double process = 0);

/// Peak memory of method = primal_penalty on one rank: the whole stiffness matrix, penalized,
/// in one factorization; `process` as for estimate_run_memory.
MemoryEstimate estimate_primal_penalty_memory(int64_t nodes, bool plane_strain, double process = 0);

/// Peak memory of building a mesh of `nodes` nodes and writing it (feticon export).
MemoryEstimate estimate_mesh_memory(int64_t nodes);

/// Peak memory of `feticon qp` on an n x n matrix with `stored` entries (both triangles):
/// the triplets read, the matrix, its transpose for the symmetry check, MPRGP's vectors.
MemoryEstimate estimate_qp_memory(int64_t n, int64_t stored);

/// `limit` bytes if > 0 (for the whole run, split evenly over the ranks), else the available
/// memory (common/available_memory.hpp) shared by the ranks on this node.
MemoryBudget memory_budget(double limit);

/// memory_budget of the `memory_limit` setting.
MemoryBudget memory_budget(const io::Settings& settings);

/// Throws feticon::Error (one line: the estimate, the budget and what to change) when
/// `estimate` exceeds `budget`; `what` names the run ("hertz.refinement = 64", ...).
void check_fits(const MemoryEstimate& estimate, const MemoryBudget& budget, const std::string& what);

/// Nodes weighted for the guard's bytes per DOF, which were fitted on hex8 meshes. hex20 cells
/// count 1.25 times (the estimate grows faster than the nodes, through the subdomain size):
/// on hertz3d's hex20 meshes the estimates were 0.71 / 0.75 / 0.71 of the peaks at 23k / 59k /
/// 151k DOFs unweighted, 0.91 / 0.98 weighted (23k, 59k measured). tet10's were 0.95-1.05 at
/// 35k-112k DOFs unweighted, and the linear types couple fewer nodes than hex8: they count once.
/// A mixed mesh takes the cell-weighted mean (docs/elements.md).
int64_t guard_nodes(const mesh::Mesh& mesh);

struct FetiChoice; // app/feti_choice.hpp

/// The memory guard of a run before anything large is allocated: the estimate for `nodes`
/// (plane strain or 3D) with the settings' method, dual.operator, the ranks and `feti`'s
/// subdomain count and preconditioner,
/// checked against the budget; `what` names the model in the message. `resident`: the bytes
/// the rank holds already, measured once the mesh is built (the libraries, Gmsh among them if
/// it made or read the mesh, and the mesh; common/available_memory.hpp); 0 before the mesh.
/// Returns the estimate (with auto's block budget).
MemoryEstimate guard_memory(const io::Settings& settings, const FetiChoice& feti, int64_t nodes, bool plane_strain,
                            const std::string& what, double resident = 0);
} // namespace feticon::app
