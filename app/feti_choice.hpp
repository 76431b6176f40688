#pragma once
/// @file `subdomains = auto` and `qp.preconditioner = auto` (issue 40): the subdomain count
/// and the dual preconditioner chosen from the model's size and the memory the machine has,
/// with the reason written to summary.json; values the user gives win.
///
/// The rules are fitted to sweeps of both settings (bench/settings_sweep.sh, the table in
/// docs/benchmarks.md, "subdomains = auto"):
/// - plane strain: the Dirichlet preconditioner, whose boundary blocks are small there (the
///   explicit operators), took 1.3-4.6 times less dual-solve time than the lumped one at every
///   count; 3D: the Dirichlet one on a band of one cell layer (qp.dirichlet_layers = 1), whose
///   steps cost a little more than the lumped one's and are 25-38 % fewer, and whose shell
///   factors add about a tenth to the memory where the whole interior's would double the
///   factors (measured on hex8 meshes); the lumped one with quadratic cells, where a cell
///   layer is two node layers and the band cost more than it saved; the whole interior at
///   no 3D subdomain size measured (2 200-4 900 DOFs: 1.1-1.7 times the band's or the
///   lumped one's time; docs/benchmarks.md, "The whole interior in small 3D subdomains");
/// - the factors in single precision in 3D: the substitutions, most of a step, are bound by
///   reading them (hertz3d 924k: a step 0.49 -> 0.31 s, the peak 4.8 -> 3.2 GiB, the answer
///   the same to 1e-7; docs/benchmarks.md "Single-precision factors"); in plane strain they
///   are small and mostly simplicial, and a linear run would pay a refinement iteration; nor
///   with the whole interior's Dirichlet preconditioner, whose dual operators may be explicit;
/// - the steps grow with the subdomain count while a step's cost hardly falls (the dual grows
///   with the boundaries), so the count is the power of two nearest (geometrically) to the
///   count of subdomains of a target size, where the factorizations stop dominating; then it
///   is doubled until the memory guard's estimate of the run fits in half the budget.

#include "app/memory_guard.hpp"
#include "dual/dual_penalty_problem.hpp"
#include "fem/problem.hpp"
#include "io/settings.hpp"
#include "qp/mprgp.hpp"

#include <cstdint>
#include <string>

namespace feticon::app
{
/// What the choice looks at.
struct ModelSize
{
  int64_t nodes = 0; ///< as the memory guard counts them (guard_nodes)
  int64_t cells = 0; ///< 0: not known yet (before the mesh is made)
  int bodies = 1;    ///< a subdomain never spans two bodies
  bool plane_strain = false;
  double resident = 0;    ///< bytes a rank holds already (0: the guard's model of the process)
  bool quadratic = false; ///< some cells are quadratic (tet10, hex20)
  int64_t mesh_nodes = 0; ///< the mesh's own node count where it differs from `nodes` (hex20)
  /// 3D: the subdomains that cut every slender body (slender_subdomains) into pieces; 0: none.
  int64_t slender_pieces = 0;
  bool planar_cells = false; ///< 2D cells (plane or axisymmetric): 2 DOFs a node
};

/// A 3D body is slender when its bounding box is over `slender_aspect` times longer than thick
/// (a plate, a leaf, a beam). Its bending is then what the dual's coarse space must see: with
/// one subdomain per body the QP of eight stacked 0.5 x 0.04 x 0.008 m plates (44k DOFs) ran
/// out of 20 000 MPRGP steps; cut into pieces about slender_piece times as long as the body is
/// thick along its longest extent, each piece's rigid modes span the body's bending at that
/// length and the same QP took 1 904 steps (20.6 s; 7 630 steps and 66 s at a quarter of that
/// count, 1 625 steps but 30 s at twice: docs/contact.md, "Slender bodies").
constexpr double slender_aspect = 16;
constexpr double slender_piece = 4;
constexpr int64_t slender_piece_cells = 16; ///< and at least this many cells a subdomain
/// The pieces of the slender bodies of `mesh` (0 if none, or for a 2D or one-layer model); a
/// model with friction keeps the DOF rule (model_size, choose_feti).
int64_t slender_subdomains(const mesh::Mesh& mesh);

/// The subdomain count and the preconditioner of a run, each with why.
struct FetiChoice
{
  int subdomains = 8;
  std::string subdomains_reason; ///< "given" for a value of the settings
  /// MPRGP's expansion step (qp.expansion resolved) and why.
  qp::MprgpExpansion expansion = qp::MprgpExpansion::standard;
  std::string expansion_name = "std";
  std::string expansion_reason;
  dual::DualPreconditioner preconditioner = dual::DualPreconditioner::dirichlet;
  std::string preconditioner_name = "dirichlet";
  std::string preconditioner_reason;
  /// qp.dirichlet_layers resolved: the band of the Dirichlet preconditioner's S_s (0: all of
  /// the interior).
  int dirichlet_layers = 0;
  /// dual.factor_precision resolved, and why.
  bool single_precision_factors = false;
  std::string factor_precision_reason;
  /// The preconditioner keeps the K_ii factors (the implicit Dirichlet one): the memory
  /// guard counts them.
  bool dirichlet() const { return preconditioner == dual::DualPreconditioner::dirichlet; }
  /// The name, and the band if there is one ("dirichlet on a band of 1 cell layer").
  std::string preconditioner_label() const;
  InteriorFactors interior_factors() const
  {
    return !dirichlet() ? InteriorFactors::none : dirichlet_layers > 0 ? InteriorFactors::band : InteriorFactors::whole;
  }
};

/// The memory guard's description of the factors the choice keeps.
inline FactorStorage factor_storage(const FetiChoice& feti)
{
  return {feti.interior_factors(), feti.single_precision_factors};
}

/// The size of `problem`'s mesh as the choice sees it.
ModelSize model_size(const fem::Problem& problem);

/// DOFs per subdomain that `subdomains = auto` aims at (the plane-strain hex layer in units
/// of 3 a node, 2D cells, 3D).
constexpr double auto_subdomain_dofs_plane_strain = 3000;
constexpr double auto_subdomain_dofs_planar_cells = 4000;
constexpr double auto_subdomain_dofs_3d = 10000;
/// The smallest subdomains auto raises the count to for memory: below them a subdomain's
/// factor hardly shrinks (the fixed bytes per DOF dominate) while the steps keep growing.
constexpr double auto_min_subdomain_dofs = 1000;

/// The choice for a model of `size` on `ranks` ranks under `budget` (per rank), from the
/// settings `subdomains`, `subdomain_cells` and `qp.preconditioner`.
FetiChoice choose_feti(const io::Settings& settings, const ModelSize& size, const MemoryBudget& budget, int ranks);
} // namespace feticon::app
