#include "app/memory_guard.hpp"

#include "app/feti_choice.hpp"

#include "common/available_memory.hpp"
#include "common/error.hpp"
#include "common/parallel.hpp"
#include "nonlinear/feti_contact_solver.hpp"
#include "par/communicator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace feticon::app
{
namespace
{
constexpr double MiB = 1024.0 * 1024.0, GiB = 1024.0 * MiB;

/// The process with MPI, Gmsh, CHOLMOD and BLAS loaded, before any mesh (measured: 55-66 MiB;
/// 12-23 MiB without Gmsh, which only a mesh made or read by Gmsh loads). Once the mesh is
/// built, the guard uses what the process holds instead.
constexpr double process_bytes = 64 * MiB;

std::string gib(double bytes)
{
  char text[32];
  std::snprintf(text, sizeof text, bytes < GiB ? "%.0f MiB" : "%.1f GiB", bytes < GiB ? bytes / MiB : bytes / GiB);
  return text;
}

/// The factor part of bytes_per_dof kept in single precision, for `owned` subdomains on a
/// rank: the float entries, half the double ones less the upper triangles of the supernodes
/// the copy leaves out (18 % of CHOLMOD's entries on hertz3d), plus the double factor each
/// thread holds while it copies it (a share threads / owned of the whole: hertz3d 924k in 128
/// subdomains peaked at 3.03 GiB against 4.84 in double before the packing, 2.61 after;
/// 22k in 2 subdomains at 194 MiB against 170).
double single_factor_share(double owned) { return 0.5 * 0.82 + std::min(1.0, threads() / std::max(1.0, owned)); }

/// Bytes per DOF of the data without explicit blocks (see estimate_run_memory) for subdomains
/// of `per_subdomain` DOFs, `owned` of them on a rank.
double bytes_per_dof(double per_subdomain, double owned, bool plane_strain, FactorStorage storage)
{
  // Fitted to the peaks of docs/benchmarks.md ("The memory guard's estimate", issue 36) less
  // what the process held once its mesh was built; the factor of a subdomain grows like
  // n log n (2D) and n^(4/3) (3D). Measured: plane strain 1.1-1.6 KB at 1.5k-3.8k DOFs per
  // subdomain (the most with large displacements); 3D with the K_ii factors 6.8 / 7.1 / 8.3 KB
  // at 4.2k / 4.9k / 12k. The 0.73 for the factor part without K_ii was fitted on hertz3d with
  // the lumped preconditioner (97k and 924k DOFs, issue 21); the 0.83 with a one-layer band's
  // factors on hertz3d (121k and 924k DOFs: peaks 9 % and 12 % above the lumped runs').
  const double precision = storage.single_precision ? single_factor_share(owned) : 1.0;
  const double factors = precision *
      (storage.interior == InteriorFactors::whole      ? 1.0
           : storage.interior == InteriorFactors::band ? 0.83
                                                       : 0.73);
  return plane_strain ? 850 + 70 * std::log2(std::max(2.0, per_subdomain)) * factors
                      : 1100 + 315 * std::cbrt(per_subdomain) * factors;
}
} // namespace

MemoryEstimate estimate_run_memory(int64_t nodes, bool plane_strain, int subdomains, int ranks, bool explicit_blocks,
                                   FactorStorage factors, double process)
{
  if (process <= 0)
    process = process_bytes;
  MemoryEstimate out;
  out.nodes = nodes;
  out.subdomains = std::max(1, subdomains);
  ranks = std::max(1, ranks);
  const double dofs = 3.0 * static_cast<double>(nodes);
  const double per_subdomain = dofs / out.subdomains;
  const double owned_subdomains = std::ceil(static_cast<double>(out.subdomains) / ranks);
  double data = dofs * bytes_per_dof(per_subdomain, owned_subdomains, plane_strain, factors);
  double rank_data = data / ranks;
  if (explicit_blocks)
  {
    // One dense b x b array per subdomain (K+ and S in its two triangles), b its boundary
    // DOFs: b = 5.2 sqrt(n) in plane strain (Hertz: 4.6-5.3; flat punch 6.5), 6.0 n^(2/3) in
    // 3D (hertz3d 6.3, sphere on block 3.9); the busiest rank holds ceil(subdomains / ranks)
    // of them, and forms them on its threads.
    const double b = std::min(per_subdomain,
                              plane_strain ? 5.2 * std::sqrt(per_subdomain) : 6.0 * std::pow(per_subdomain, 2.0 / 3.0));
    const int owned = (out.subdomains + ranks - 1) / ranks;
    const double block = 8.0 * b * b;
    data += out.subdomains * block;
    rank_data += owned * block + nonlinear::explicit_forming_bytes(std::vector<double>(owned, b), threads());
  }
  out.bytes = ranks * process + data;
  out.per_rank = process + rank_data;
  return out;
}

MemoryEstimate estimate_primal_penalty_memory(int64_t nodes, bool plane_strain, double process)
{
  // The undecomposed matrix in one factor: the model of one subdomain, counted with the
  // factor part of the K_ii factors' runs (the penalized and the reduced matrix beside K and
  // the factor; measured 2.6 KB per DOF on Hertz at 19k DOFs, 11.4 KB on hertz3d at 39k).
  return estimate_run_memory(nodes, plane_strain, 1, 1, false, {InteriorFactors::whole, false}, process);
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
  const AvailableMemory available = available_memory();
  if (available.bytes < 0)
    return {-1, available.source};
  return {static_cast<double>(available.bytes) / par::ranks_on_this_node(), available.source};
}

void check_fits(const MemoryEstimate& estimate, const MemoryBudget& budget, const std::string& what)
{
  // Available memory unknown (no /proc/meminfo, no cgroup limit): nothing to check against.
  if (budget.per_rank < 0 || estimate.per_rank <= budget.per_rank)
    return;
  const bool shared = budget.source != "memory_limit" && par::ranks_on_this_node() > 1;
  const bool cgroup = budget.source.rfind("the cgroup", 0) == 0;
  const std::string size = estimate.nodes > 0 ? " (estimate for " + std::to_string(3 * estimate.nodes) + " DOFs in " +
          std::to_string(estimate.subdomains) + " subdomains)"
                                              : std::string();
  const std::string fix = estimate.nodes == 0 ? "a smaller problem, or a machine with more memory"
      : cgroup                                ? "coarsen the mesh, or raise the cgroup's memory limit"
                                              : "coarsen the mesh, or set memory_limit (bytes) if more is free";
  FETICON_CHECK(false,
                what << " needs about " << gib(estimate.per_rank * par::Communicator::world().size()) << size
                     << ", more than the " << gib(budget.per_rank * par::Communicator::world().size()) << " available ("
                     << budget.source << (cgroup ? " less its usage" : "")
                     << (shared ? ", shared by the ranks of a node" : "") << "); " << fix);
}

int64_t guard_nodes(const mesh::Mesh& mesh)
{
  if (mesh.cells.empty())
    return mesh.n_nodes();
  double weight = 0;
  for (size_t c = 0; c < mesh.cells.size(); ++c)
    weight += mesh.cells.kind(c) == mesh::CellKind::hex20 ? 1.25 : 1.0;
  return static_cast<int64_t>(std::llround(mesh.n_nodes() * weight / static_cast<double>(mesh.cells.size())));
}

MemoryEstimate guard_memory(const io::Settings& settings, const FetiChoice& feti, int64_t nodes, bool plane_strain,
                            const std::string& what, double resident)
{
  const MemoryBudget budget = memory_budget(settings);
  if (settings.text("method") == "primal_penalty")
  {
    const MemoryEstimate estimate = estimate_primal_penalty_memory(nodes, plane_strain, resident);
    check_fits(estimate, budget, what);
    return estimate;
  }
  const int ranks = par::Communicator::world().size();
  const int subdomains = feti.subdomains;
  const std::string& mode = settings.text("dual.operator");
  const bool dirichlet = feti.dirichlet();
  const bool explicit_blocks = mode == "explicit";
  // auto is checked as implicit, with the K_ii factors: the run it can always fall back to.
  MemoryEstimate estimate = estimate_run_memory(
      nodes, plane_strain, subdomains, ranks, explicit_blocks,
      {explicit_blocks ? InteriorFactors::none : feti.interior_factors(), feti.single_precision_factors}, resident);
  check_fits(estimate, budget, what);
  if (mode == "auto" && dirichlet)
  {
    estimate.per_rank_explicit = estimate_run_memory(nodes, plane_strain, subdomains, ranks, true,
                                                     {InteriorFactors::none, feti.single_precision_factors}, resident)
                                     .per_rank;
    // The blocks get what the budget leaves beside an explicit run without them.
    const MemoryEstimate rest = estimate_run_memory(nodes, plane_strain, subdomains, ranks, false,
                                                    {InteriorFactors::none, feti.single_precision_factors}, resident);
    if (budget.per_rank >= 0)
      estimate.explicit_block_budget = std::max(0.0, budget.per_rank - rest.per_rank);
  }
  return estimate;
}
} // namespace feticon::app
