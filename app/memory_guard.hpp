#pragma once
/// @file The memory guard (issue 21): a run's peak memory estimated from its size before
/// anything large is allocated, and a one-line refusal when it does not fit the budget.
///
/// The estimate is a model fitted to measured peaks (docs/benchmarks.md): the process with its
/// libraries, plus bytes per degree of freedom that grow with the subdomain size as the
/// Cholesky factors do (nested dissection: nnz(L) ~ n log n in the one-layer plane-strain
/// meshes, ~ n^(4/3) in 3D), plus the dense boundary blocks of dual.operator=explicit.

#include "io/problem_file.hpp"

#include <cstdint>
#include <string>

namespace feticon::app
{
/// What the estimate is made of.
struct MemoryEstimate
{
  double bytes = 0;        ///< peak of the whole run, all ranks together
  double per_rank = 0;     ///< peak of one rank
  int64_t nodes = 0;       ///< the size it was made for (0 for a QP)
  int subdomains = 0;
};

/// The budget a rank may use and where it comes from.
struct MemoryBudget
{
  double per_rank = 0;
  std::string source; ///< "memory_limit" or "MemAvailable"
};

/// Peak memory of a solve of a mesh with `nodes` nodes (plane strain: one cell layer) in
/// `subdomains` subdomains on `ranks` ranks; `explicit_blocks` adds the dense boundary blocks,
/// `interior_factors` the K_ii factors of the implicit Dirichlet preconditioner.
MemoryEstimate estimate_run_memory(int64_t nodes, bool plane_strain, int subdomains, int ranks,
                                   bool explicit_blocks, bool interior_factors);

/// Peak memory of building a mesh of `nodes` nodes and writing it (feticon export).
MemoryEstimate estimate_mesh_memory(int64_t nodes);

/// Peak memory of `feticon qp` on an n x n matrix with `stored` entries (both triangles):
/// the triplets read, the matrix, its transpose for the symmetry check, MPRGP's vectors.
MemoryEstimate estimate_qp_memory(int64_t n, int64_t stored);

/// `limit` bytes if > 0, else MemAvailable of /proc/meminfo shared by the ranks on this node.
MemoryBudget memory_budget(double limit);

/// The `memory_limit` setting if > 0 (bytes for the whole run, split evenly over the ranks),
/// else MemAvailable of /proc/meminfo shared by the ranks on this node.
MemoryBudget memory_budget(const io::Settings& settings);

/// Throws feticon::Error (one line: the estimate, the budget and what to change) when
/// `estimate` exceeds `budget`; `what` names the run ("hertz.refinement = 64", ...).
void check_fits(const MemoryEstimate& estimate, const MemoryBudget& budget, const std::string& what);

/// The memory guard of a run before anything large is allocated: the estimate for `nodes`
/// (plane strain or 3D) with the settings' subdomains, ranks and dual.operator, checked
/// against the budget; `what` names the model in the message. Returns the estimate.
MemoryEstimate guard_memory(const io::Settings& settings, int64_t nodes, bool plane_strain,
                            const std::string& what);
} // namespace feticon::app
