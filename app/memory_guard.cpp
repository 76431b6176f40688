#include "app/memory_guard.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"
#include "common/timer.hpp"
#include "par/communicator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace feticon::app
{
namespace
{
constexpr double MiB = 1024.0 * 1024.0, GiB = 1024.0 * MiB;

/// The process with MPI, Gmsh, CHOLMOD and BLAS loaded, before any mesh (measured: 55-65 MiB).
constexpr double process_bytes = 64 * MiB;

std::string gib(double bytes)
{
  char text[32];
  std::snprintf(text, sizeof text, bytes < GiB ? "%.0f MiB" : "%.1f GiB", bytes < GiB ? bytes / MiB : bytes / GiB);
  return text;
}
} // namespace

MemoryEstimate estimate_run_memory(int64_t nodes, bool plane_strain, int subdomains, int ranks,
                                   bool explicit_blocks, bool interior_factors)
{
  MemoryEstimate out;
  out.nodes = nodes;
  out.subdomains = std::max(1, subdomains);
  ranks = std::max(1, ranks);
  const double dofs = 3.0 * static_cast<double>(nodes);
  const double per_subdomain = dofs / out.subdomains;
  // Bytes per DOF fitted to the peaks of docs/benchmarks.md (without the explicit blocks);
  // the factor of a subdomain grows like n log n (2D) and n^(4/3) (3D). Plane strain 1.3-2.3 KB
  // at 1.5k-4k DOFs per subdomain; 3D with the K_ii factors 4.7 / 7.8 / 8.7 KB at 1.5k / 12k /
  // 14k, without them (lumped) 3.8 / 4.1 / 4.7 KB at 1.8k / 2.4k / 3.6k (hertz3d, 97k and 924k DOFs).
  // The 0.73 for the factor part without K_ii is that 3D fit; plane strain uses it unmeasured.
  const double factors = interior_factors ? 1.0 : 0.73;
  const double per_dof = plane_strain ? 1200 + 100 * std::log2(std::max(2.0, per_subdomain)) * factors
                                      : 1000 + 315 * std::cbrt(per_subdomain) * factors;
  double data = dofs * per_dof;
  if (explicit_blocks)
  {
    // One dense b x b array per subdomain (K+ and S in its two triangles), b its boundary
    // DOFs: fitted b = 6.5 sqrt(n) in plane strain, 5.8 n^(2/3) in 3D (Hertz, sphere, tensor deck).
    const double b = plane_strain ? 6.5 * std::sqrt(per_subdomain) : 5.8 * std::pow(per_subdomain, 2.0 / 3.0);
    const double block = 8.0 * std::min(b, per_subdomain) * std::min(b, per_subdomain);
    // Forming one holds about four more such arrays (la::schur_complement's result, the
    // matrix it inverts, the two blocks) on each thread forming them.
    data += (out.subdomains + 4.0 * std::min(threads(), out.subdomains)) * block;
  }
  out.bytes = ranks * process_bytes + data;
  out.per_rank = process_bytes + data / ranks;
  return out;
}

MemoryEstimate estimate_mesh_memory(int64_t nodes)
{
  MemoryEstimate out;
  out.nodes = nodes;
  out.subdomains = 1;
  // Coordinates, cells, sets and the deck's text: well under 1 KB per node.
  out.bytes = out.per_rank = process_bytes + 1000.0 * static_cast<double>(nodes);
  return out;
}

MemoryEstimate estimate_qp_memory(int64_t n, int64_t stored)
{
  MemoryEstimate out;
  out.subdomains = 1;
  // Triplets (16 B), the matrix and its transpose (12 B per entry each), column pointers,
  // and about twelve vectors of n doubles in MPRGP and the command.
  const double entries = static_cast<double>(stored), rows = static_cast<double>(n);
  out.bytes = out.per_rank = process_bytes + 40 * entries + 8 * rows + 12 * 8 * rows;
  return out;
}

MemoryBudget memory_budget(const io::Settings& settings) { return memory_budget(settings.number("memory_limit")); }

MemoryBudget memory_budget(double limit)
{
  const int ranks = par::Communicator::world().size();
  if (limit > 0)
    return {limit / ranks, "memory_limit"};
  return {static_cast<double>(available_memory_bytes()) / par::ranks_on_this_node(), "MemAvailable"};
}

void check_fits(const MemoryEstimate& estimate, const MemoryBudget& budget, const std::string& what)
{
  // MemAvailable unknown (0: no /proc/meminfo): nothing to check against.
  if (budget.per_rank <= 0 || estimate.per_rank <= budget.per_rank)
    return;
  const bool shared = budget.source == "MemAvailable" && par::ranks_on_this_node() > 1;
  const std::string size = estimate.nodes > 0 ? " (estimate for " + std::to_string(3 * estimate.nodes) + " DOFs in " +
                                                     std::to_string(estimate.subdomains) + " subdomains)"
                                               : std::string();
  FETICON_CHECK(false, what << " needs about " << gib(estimate.bytes) << size << ", more than the "
                            << gib(budget.per_rank * par::Communicator::world().size()) << " available ("
                            << budget.source << (shared ? " shared by the ranks of a node" : "")
                            << (estimate.nodes > 0 ? "); coarsen the mesh, or set memory_limit (bytes) if more is free"
                                                   : "); a smaller problem, or a machine with more memory"));
}

MemoryEstimate guard_memory(const io::Settings& settings, int64_t nodes, bool plane_strain, const std::string& what)
{
  const int ranks = par::Communicator::world().size();
  int subdomains = settings.integer("subdomains");
  const int cells_per_subdomain = settings.integer("subdomain_cells");
  if (cells_per_subdomain > 0) // about as many cells as nodes (half in a plane-strain layer)
    subdomains = static_cast<int>(std::max<int64_t>(1, (plane_strain ? nodes / 2 : nodes) / cells_per_subdomain));
  const bool explicit_blocks = settings.text("dual.operator") == "explicit";
  // auto decides after the mesh is built: counted with the K_ii factors, the larger case.
  const bool interior_factors = settings.text("qp.preconditioner") == "dirichlet" && !explicit_blocks;
  const MemoryEstimate estimate =
      estimate_run_memory(nodes, plane_strain, subdomains, ranks, explicit_blocks, interior_factors);
  check_fits(estimate, memory_budget(settings), what);
  return estimate;
}
} // namespace feticon::app
