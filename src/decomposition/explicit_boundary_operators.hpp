#pragma once
/// @file The subdomain operators of the FETI dual formed explicitly on the boundary DOFs b_s
/// (Říha, Brzobohatý, Meca et al., explicit FETI operators in ESPRESO):
///
///   (K_s+)_bb = E_b' K_s+ E_b   and   S_s = K_bb - K_bi K_ii^-1 K_ib,
///
/// b_s the boundary of the Dirichlet preconditioner (schur_complements.hpp): the DOFs of
/// nodes shared with another subdomain, of supported nodes and of both contact surfaces, so
/// every gluing, Dirichlet and contact row, whatever the contact search finds, touches only
/// b_s. Then B_s K_s+ B_s' = B_b (K_s+)_bb B_b' and B_s S_s B_s' = B_b S_s B_b' exactly, and an
/// MPRGP step costs dense products of size |b_s| instead of forward and backward
/// substitutions with the factors of K_s and K_ii. Both blocks depend only on the
/// factorization: with the initial stiffness kept (modified Newton), they are formed once per
/// run, while B_b changes with the contact rows of every outer iteration.
///
/// Formed from one partial factorization per subdomain (la/schur_complement.hpp): with b' =
/// b_s and the fixing DOFs f of K_s+ (generalized_inverse.hpp), S' = the Schur complement of
/// K_s on b' (the trailing block of a CHOLMOD factor with b' ordered last), and then
///   fixing DOFs:     (K_s+)_bb = [S'_rr^-1 0; 0 0], r = b' minus f  (K_rr's own Schur complement),
///   regularization:  (K_s+)_bb = (S' + rho C C')^-1 restricted to b,
///   Dirichlet:       S_s = S'_bb - S'_bg S'_gg^-1 S'_gb, g = f outside b (usually none),
/// the same operators as the substitutions apply, in about |b'|^3 flops of dense LAPACK
/// instead of |b_s| substitutions with each of two factors.
/// Both blocks are symmetric and share one square array: (K_s+)_bb in the lower triangle and the
/// diagonal, S_s in the strict upper triangle (its diagonal aside), applied by BLAS dsymv
/// (la/symmetric_product.hpp), which reads one triangle: half the memory, and the products,
/// bound by memory traffic, read half as much. The array holds sigma (K_s+)_bb and S_s / sigma,
/// sigma^2 = mean diag(S_s) / mean diag((K_s+)_bb): K+ scales like 1 / E and S like E, and
/// unscaled, a modulus far from 1 made the shared diagonal K+'s alone, so that S's diagonal,
/// restored by adding diag(S) - diag(K+), was lost to cancellation (E = 1e-30 Pa: the
/// Dirichlet preconditioner was noise and MPRGP stalled; issue 36).

#include "decomposition/schur_complements.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace feticon::decomposition
{
class ExplicitBoundaryOperators
{
public:
  /// @param system subdomain K+ (kept by reference; must outlive this object)
  /// @param schur  the boundaries b_s (used during construction only; its K_ii factors are not needed)
  /// @param reuse  optional operators of the same K: the blocks of every subdomain whose
  ///               boundary is unchanged are moved from it instead of formed again
  ExplicitBoundaryOperators(const SubdomainSystem& system, const SchurComplements& schur,
                            ExplicitBoundaryOperators* reuse = nullptr);

  /// Boundary DOFs of owned subdomain s (active DOFs, increasing).
  const std::vector<int32_t>& boundary(int32_t s) const { return local(s).boundary; }
  /// (K_s+)_bb v and S_s v for v on the boundary of owned subdomain s.
  la::Vector apply_K_plus(int32_t s, const la::Vector& v) const;
  la::Vector apply_schur(int32_t s, const la::Vector& v) const;
  /// Bytes of the dense blocks of this rank.
  int64_t bytes() const;
  /// Owned subdomains whose blocks the constructor formed (the others were reused).
  int32_t formed() const { return _formed; }

private:
  struct Local
  {
    std::vector<int32_t> boundary;
    la::Matrix blocks;             ///< sigma (K_s+)_bb in the lower triangle, S_s / sigma in the upper
    la::Vector schur_minus_K_plus; ///< diag(S_s) / sigma - sigma diag((K_s+)_bb)
    double sigma = 1;
  };
  const Local& local(int32_t s) const { return _local[s - _first]; }

  int32_t _first = 0;
  int32_t _formed = 0;
  std::vector<Local> _local; ///< per owned subdomain (index s - first owned)
};

/// S_s from S' = [S'_bb S'_bg; S'_gb S'_gg], the Schur complement of K_s on its boundary b (the
/// first nb rows) followed by the fixing DOFs g outside b: S'_bb - S'_bg S'_gg^-1 S'_gb.
/// Throws a one-line error naming `what` (the subdomain) if S'_gg is not positive definite.
la::Matrix eliminate_fixing_dofs(const la::Matrix& S_ext, la::Index nb, const std::string& what);

/// Bytes the dense blocks of the owned subdomains would take: |b_s|^2 doubles each.
int64_t explicit_operator_bytes(const SubdomainSystem& system, const SchurComplements& schur);
} // namespace feticon::decomposition
