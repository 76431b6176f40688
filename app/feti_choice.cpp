#include "app/feti_choice.hpp"

#include "common/error.hpp"
#include "mesh/cell_type.hpp"
#include "nonlinear/solver_settings.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <cstdio>

namespace feticon::app
{
namespace
{
std::string format(const char* pattern, double a, double b = 0, double c = 0)
{
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

/// The run's peak on the busiest rank with `subdomains`, as the memory guard will check it.
double estimated_peak(const ModelSize& size, int subdomains, int ranks, FactorStorage factors)
{
  return estimate_run_memory(size.nodes, size.plane_strain, subdomains, ranks, false, factors, size.resident).per_rank;
}

/// dual.factor_precision; before the count, whose memory check counts the factors.
void choose_factor_precision(const io::Settings& settings, const ModelSize& size, FetiChoice& out)
{
  const std::string& name = settings.text("dual.factor_precision");
  if (name != "auto")
  {
    out.single_precision_factors = name == "single";
    out.factor_precision_reason = "given";
  }
  else if (size.plane_strain)
    out.factor_precision_reason = "plane strain: small factors, most of them simplicial; the round-off a linear "
                                  "run would correct costs more than the traffic saved";
  else
  {
    out.single_precision_factors = true;
    out.factor_precision_reason = "3D: the substitutions with the factors, most of a step, are bound by reading them; "
                                  "single precision halves that and the factors' memory (applied in double "
                                  "arithmetic; the primal recovery refines against K in double)";
  }
}

/// qp.dirichlet_layers as given; auto: 0 (the whole interior).
int given_layers(const io::Settings& settings)
{
  return settings.is_auto("qp.dirichlet_layers") ? 0 : settings.integer("qp.dirichlet_layers");
}

void set_preconditioner(FetiChoice& out, const std::string& name, const std::string& reason, int layers = 0)
{
  out.dirichlet_layers = name == "dirichlet" ? layers : 0;
  out.preconditioner_name = name;
  out.preconditioner_reason = reason;
  out.preconditioner = name == "lumped" ? dual::DualPreconditioner::lumped
      : name == "none"                  ? dual::DualPreconditioner::none
                                        : dual::DualPreconditioner::dirichlet;
}

/// The preconditioner before the count is known (the count's memory check counts its factors).
void choose_preconditioner(const io::Settings& settings, const ModelSize& size, FetiChoice& out)
{
  const std::string& name = settings.text("qp.preconditioner");
  const int layers = given_layers(settings);
  if (name != "auto")
    set_preconditioner(out, name, "given", layers);
  else if (size.plane_strain)
    set_preconditioner(out, "dirichlet",
                       "a plane model (2D cells, or the plane-strain layer): its small boundary blocks make its "
                       "steps cheap, and it needs the fewest of them",
                       layers);
  else if (settings.text("dual.operator") == "explicit") // whose blocks hold the whole S_s
    set_preconditioner(out, "dirichlet", "dual.operator = explicit forms it", layers);
  else if (size.quadratic)
    set_preconditioner(out, "lumped",
                       "3D with quadratic cells: a band of one cell layer is two layers of nodes, and its factors "
                       "cost more than its fewer steps save (hertz3d's Gmsh tet10 mesh at 38k DOFs: 1.11 times the "
                       "lumped run's time); no second set of subdomain factors");
  else
    set_preconditioner(out, "dirichlet",
                       "3D: on a band of one cell layer, 25-38 % fewer steps than the lumped preconditioner's at a "
                       "little more cost each, and shell factors where the whole interior's would double the memory",
                       settings.is_auto("qp.dirichlet_layers") ? 1 : layers);
}

/// MPRGP's expansion step: projcg where slender bodies make most steps expansions.
void choose_expansion(const io::Settings& settings, const ModelSize& size, FetiChoice& out)
{
  if (!settings.is_auto("qp.expansion"))
  {
    out.expansion_name = settings.text("qp.expansion");
    out.expansion_reason = "given";
  }
  else if (size.slender_pieces > 0)
  {
    out.expansion_name = "projcg";
    out.expansion_reason = "slender bodies: their contact opens and closes over their length and most MPRGP steps are "
                           "expansions, which the projected CG step takes together (eight stacked leaves at 44k DOFs: "
                           "581 steps and 8.2 s against 1 904 and 20.6 s)";
  }
  else
  {
    out.expansion_name = "std";
    out.expansion_reason = "expansions are a tenth of the steps on compact bodies, where projcg saves nothing "
                           "(docs/contact.md, \"MPRGP expansion steps\")";
  }
  out.expansion = qp::expansion_from_name(out.expansion_name);
}

/// auto's single precision needs implicit dual operators to pay: with the whole interior's
/// Dirichlet preconditioner dual.operator = auto may form explicit blocks, whose steps do not
/// read the factors, and a linear run would pay a refinement iteration for nothing (the hex8
/// sphere on a block, explicit: 0.91 s against 0.85 s, medians of 3).
void revise_factor_precision(const io::Settings& settings, FetiChoice& out)
{
  if (settings.text("dual.factor_precision") == "auto" && out.interior_factors() == InteriorFactors::whole &&
      settings.text("dual.operator") != "implicit")
  {
    out.single_precision_factors = false;
    out.factor_precision_reason = "the whole interior's Dirichlet preconditioner: the dual operators may be explicit, "
                                  "whose steps do not read the factors";
  }
}

void choose_count(const io::Settings& settings, const ModelSize& size, const MemoryBudget& budget, int ranks,
                  FetiChoice& out)
{
  const int per_subdomain_cells = settings.integer("subdomain_cells");
  if (per_subdomain_cells > 0)
  {
    // About as many cells as nodes before the mesh is made (half in a plane-strain layer).
    const int64_t cells = size.cells > 0 ? size.cells : (size.plane_strain ? size.nodes / 2 : size.nodes);
    out.subdomains =
        static_cast<int>(std::max<int64_t>(size.bodies, (cells + per_subdomain_cells - 1) / per_subdomain_cells));
    out.subdomains_reason = "subdomain_cells = " + std::to_string(per_subdomain_cells);
    return;
  }
  if (!settings.is_auto("subdomains"))
  {
    out.subdomains = settings.integer("subdomains");
    out.subdomains_reason = "given";
    return;
  }
  // 2D cells' factors fill less than the hex layer's at the same node count: their own target,
  // measured on the 2D Hertz (docs/benchmarks.md: 2 subdomains fastest at 6 306 and 10 080 DOFs,
  // 4 to 8 at 16 392, 4 to 16 within 2.5 % at 27 592).
  const double dofs = (size.planar_cells ? 2.0 : 3.0) * static_cast<double>(size.nodes);
  const double target = size.planar_cells ? auto_subdomain_dofs_planar_cells
      : size.plane_strain                 ? auto_subdomain_dofs_plane_strain
                                          : auto_subdomain_dofs_3d;
  const int64_t cap = size.cells > 0 ? size.cells : std::max<int64_t>(1, size.nodes);
  auto clamp = [&](double n) {
    return static_cast<int>(std::min<double>(static_cast<double>(cap), std::max({n, 1.0 * size.bodies, 1.0 * ranks})));
  };
  // A power of two: METIS's k-way partitions of other counts cost steps (Hertz at 18.8k DOFs:
  // 188 MPRGP steps in 5 subdomains, 142 in 4, 168 in 8; hertz3d at 121k: 181 in 13, 147 in
  // 8, 153 in 16).
  int n = clamp(std::exp2(std::round(std::log2(std::max(1.0, dofs / target)))));
  out.subdomains_reason = size.mesh_nodes > 0
      ? format("%.0f DOFs, counted as %.0f for hex20's denser factors, at about %.0f DOFs a subdomain",
               3.0 * static_cast<double>(size.mesh_nodes), dofs, target)
      : size.planar_cells ? format("%.0f DOFs of 2D cells at about %.0f DOFs a subdomain", dofs, target)
      : size.plane_strain
      ? format("%.0f nodes, %.0f units at 3 a node (the rule's unit, measured on the plane-strain layer), at "
               "about %.0f a subdomain",
               static_cast<double>(size.nodes), dofs, target)
      : format("%.0f DOFs at about %.0f DOFs a subdomain", dofs, target);
  if (n == cap && n < dofs / target)
    out.subdomains_reason += ": one subdomain per cell";
  // A piece needs cells enough to have an interior (eight stacked plates of 1 120 cells: 3 775
  // MPRGP steps in 128 subdomains, 1 903 in 64, 1 351 in 32).
  const int64_t pieces = std::min(size.slender_pieces, size.cells / slender_piece_cells);
  if (pieces > n)
  {
    n = clamp(std::exp2(std::round(std::log2(static_cast<double>(pieces)))));
    out.subdomains_reason +=
        format("; raised to %.0f to cut the slender bodies into pieces about %.0f times as long as "
               "they are thick (%.0f pieces)",
               static_cast<double>(n), slender_piece, static_cast<double>(pieces));
  }
  // Half the budget: the estimate is within about 10 % of the measured peaks, and the machine
  // is rarely the run's alone.
  const double room = 0.5 * budget.per_rank;
  const int first = n;
  const int smallest = clamp(std::floor(dofs / auto_min_subdomain_dofs));
  while (budget.per_rank >= 0 && n < smallest && estimated_peak(size, n, ranks, factor_storage(out)) > room)
    n = std::min(smallest, clamp(2.0 * n));
  const double peak = estimated_peak(size, n, ranks, factor_storage(out));
  if (n != first && peak <= room)
    out.subdomains_reason += format("; raised from %.0f so that the estimated peak, %.0f MiB a rank, fits in half "
                                    "the %.0f MiB available",
                                    first, peak / 1048576.0, budget.per_rank / 1048576.0);
  else if (n != first) // the guard decides whether the whole budget holds it
    out.subdomains_reason += format("; raised from %.0f to subdomains of about %.0f DOFs, the smallest auto takes; "
                                    "the estimated peak, %.0f MiB a rank, is over half the budget",
                                    first, auto_min_subdomain_dofs, peak / 1048576.0);
  out.subdomains = n;
}
} // namespace

std::string FetiChoice::preconditioner_label() const
{
  if (dirichlet_layers == 0)
    return preconditioner_name;
  return preconditioner_name + " on a band of " + std::to_string(dirichlet_layers) +
      (dirichlet_layers == 1 ? " cell layer" : " cell layers");
}

int64_t slender_subdomains(const mesh::Mesh& mesh)
{
  if (mesh.planar.kind != mesh::PlanarKind::none || mesh.n_cells() == 0)
    return 0;
  std::vector<Eigen::Vector3d> lo(mesh.n_bodies(), Eigen::Vector3d::Constant(1e300)), hi(lo.size(), -lo[0]);
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (const int32_t node : mesh.cells[static_cast<size_t>(c)])
    {
      const int32_t b = mesh.cell_body[c];
      lo[b] = lo[b].cwiseMin(mesh.nodes.row(node).transpose());
      hi[b] = hi[b].cwiseMax(mesh.nodes.row(node).transpose());
    }
  int64_t pieces = 0;
  for (size_t b = 0; b < lo.size(); ++b)
  {
    std::array<double, 3> extent{hi[b](0) - lo[b](0), hi[b](1) - lo[b](1), hi[b](2) - lo[b](2)};
    std::ranges::sort(extent, std::greater<>());
    pieces += extent[0] > slender_aspect * extent[2] && extent[2] > 0
        ? static_cast<int64_t>(std::ceil(extent[0] / (slender_piece * extent[2])))
        : 1;
  }
  return pieces > static_cast<int64_t>(lo.size()) ? pieces : 0;
}

ModelSize model_size(const fem::Problem& problem)
{
  bool quadratic = false;
  for (size_t c = 0; c < problem.mesh.cells.size() && !quadratic; ++c)
    quadratic = mesh::cell_type(problem.mesh.cells.kind(c)).order > 1;
  const int64_t counted = guard_nodes(problem.mesh);
  return {counted,
          problem.mesh.n_cells(),
          problem.mesh.n_bodies(),
          problem.eliminated[2],
          0,
          quadratic,
          counted != problem.mesh.n_nodes() ? problem.mesh.n_nodes() : 0,
          problem.eliminated[2] || nonlinear::SolverSettings().has_friction(problem) ? 0
                                                                                     : slender_subdomains(problem.mesh),
          problem.mesh.dofs_per_node() == 2};
}

FetiChoice choose_feti(const io::Settings& settings, const ModelSize& size, const MemoryBudget& budget, int ranks)
{
  FETICON_CHECK(given_layers(settings) == 0 || settings.text("dual.operator") != "explicit",
                "qp.dirichlet_layers = " << given_layers(settings)
                                         << " bands the implicit Schur complements; dual.operator = explicit forms the "
                                            "whole ones: set one of them to auto");
  FetiChoice out;
  // The slender rule is measured on frictionless contact only: with Coulomb friction metalforming's
  // J2 sheet (6 096 DOFs) ended at "every tangential row slides" in 16 and 32 subdomains and ran
  // in 2 to 8.
  ModelSize sized = size;
  if (settings.given("contact.friction.model") && settings.text("contact.friction.model") != "none")
    sized.slender_pieces = 0;
  choose_factor_precision(settings, sized, out);
  choose_preconditioner(settings, sized, out);
  choose_expansion(settings, sized, out);
  choose_count(settings, sized, budget, std::max(1, ranks), out);
  revise_factor_precision(settings, out);
  return out;
}
} // namespace feticon::app
