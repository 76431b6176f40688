#pragma once
/// @file Subdomain Schur complements on the boundary DOFs, for the FETI Dirichlet
/// preconditioner (Farhat, Mandel, Roux 1994):
///
///   F^{-1} ~ B S B',   S = diag(S_s),   S_s = K_bb - K_bi K_ii^{-1} K_ib,
///
/// b the subdomain's boundary DOFs, i the interior ones. F = B K+ B' acts like the inverse of
/// the Schur complements on the interface, so B S B' removes the H/h growth of its condition
/// number down to (1 + log(H/h))^2 for equality rows; on the graded Hertz mesh, whose contact
/// surface carries the smallest elements and is part of the interface, that is the growth
/// that costs MPRGP steps (docs/benchmarks.md).
///
/// S_s is applied implicitly: one sparse product with K_ib, one CHOLMOD solve with K_ii and
/// one product with K_bi, about the cost of one K_s+ application. The boundary is fixed for
/// the run (contact rows change every outer iteration, K_ii is factorized once per stiffness):
/// the DOFs of nodes shared with another subdomain and the DOFs flagged by the caller (the
/// supported components and the contact DOFs the rows may touch). Each boundary DOF no
/// row touches is held fixed in S_s instead of eliminated, which makes B S B' a different,
/// weaker SPD preconditioner and costs a larger S_s: a symmetry plane's node is on the
/// boundary with its one supported component only (docs/benchmarks.md, sphere on block).
///
/// With `interior_layers` = k > 0, i is only the interior within k cell layers of the
/// boundary, and the interior beyond is held fixed: S_s^(k) = K_bb - K_bi K_ii^{-1} K_ib on
/// that band, between S_s and K_bb (v'S v <= v'S^(k) v <= v'K_bb v: holding DOFs fixed only
/// stiffens the boundary), a weaker preconditioner whose K_ii is a shell and factorizes with
/// little fill. One layer: on hertz3d at 924k DOFs in 128 subdomains 150 MPRGP steps against
/// the lumped preconditioner's 233, for about an eighth more memory (docs/benchmarks.md).

#include "decomposition/subdomain_operators.hpp"
#include "la/cholmod.hpp"

#include <vector>

namespace feticon::decomposition
{
class SchurComplements
{
public:
  /// Finds the boundaries and, with `factorize_interior`, factorizes K_ii of the subdomains
  /// this rank owns. Without (the explicit dual operators form S_s densely themselves,
  /// explicit_boundary_operators.hpp) apply() must not be called.
  /// @param system        subdomain stiffnesses (kept by reference, must outlive this)
  /// @param boundary_dof one flag per mesh DOF (3 node + component): on the boundary
  ///        whatever subdomain has it
  /// @param interior_layers 0: the whole interior; k > 0: the band of k cell layers (above)
  SchurComplements(const SubdomainSystem& system, const std::vector<char>& boundary_dof, bool factorize_interior = true,
                   int interior_layers = 0);

  /// Factorizes K_ii of the owned subdomains (once; the boundaries stay as found), for apply().
  void factorize_interior();

  /// [0; S_s v_b] for a vector v over the active DOFs of owned subdomain s (its interior
  /// entries are ignored).
  la::Vector apply(int32_t s, const la::Vector& v) const;

  /// Boundary DOFs b_s (active DOFs of owned subdomain s, increasing).
  const std::vector<int32_t>& boundary(int32_t s) const { return local(s).boundary; }

private:
  struct Local
  {
    std::vector<int32_t> boundary, interior; ///< active DOFs, increasing (interior: the band's)
    la::SparseMatrix K_bb, K_ib;
    la::CholmodFactor K_ii;
  };
  const Local& local(int32_t s) const { return _local[s - _system.decomposition().first_owned()]; }

  const SubdomainSystem& _system;
  bool _factorized = false;
  std::vector<Local> _local; ///< per owned subdomain (index s - first owned)
};
} // namespace feticon::decomposition
