#pragma once
/// @file The FETI dual operators, applied without forming F (ALGORITHMS.md section 1).
///
///   F = B K+ B',  G = R' B',  e = R' f,  d = B K+ f - c,
/// with B = [B_E; B_I] given as constraint rows, K+ = diag(K_s+), R = diag(R_s).
/// B is held per subdomain: the rows that touch subdomain s and a sparse block B_s, so
/// F lambda = sum_s B_s K_s+ B_s' lambda_s needs no global matrix.

#include "decomposition/constraint_rows.hpp"
#include "decomposition/subdomain_operators.hpp"
#include "la/operator.hpp"

namespace feticon::dual
{
class FetiOperators
{
public:
  /// @param system subdomain K, R, K+ (kept by reference; must outlive this object)
  /// @param rows   all constraint rows, equality rows first
  FetiOperators(const decomposition::SubdomainSystem& system,
                const decomposition::ConstraintRows& rows);

  int64_t n_dual() const { return _n_dual; }
  int64_t n_primal() const { return _system.decomposition().n_primal(); }
  int64_t n_kernel() const { return _system.n_kernel(); }

  la::Vector apply_B(const la::Vector& u_stacked) const;
  la::Vector apply_Bt(const la::Vector& lambda) const;
  la::Vector apply_K_plus(const la::Vector& f_stacked) const;
  la::Vector apply_R(const la::Vector& alpha) const;
  la::Vector apply_Rt(const la::Vector& u_stacked) const;
  /// F lambda = B K+ B' lambda.
  la::Vector apply_F(const la::Vector& lambda) const;
  /// Lumped preconditioner B K B' lambda (Farhat, Mandel, Roux 1994): cheap, one sparse
  /// product per subdomain.
  la::Vector apply_lumped(const la::Vector& lambda) const;
  /// G lambda = R' B' lambda and G' alpha = B R alpha.
  la::Vector apply_G(const la::Vector& lambda) const { return _G * lambda; }
  la::Vector apply_Gt(const la::Vector& alpha) const { return _G.transpose() * alpha; }
  /// G as a sparse matrix (n_kernel x n_dual).
  const la::SparseMatrix& G() const { return _G; }
  /// G restricted to the columns in `keep` (others zeroed), for primal recovery.
  la::SparseMatrix G_columns(const std::vector<char>& keep) const;

  const decomposition::SubdomainSystem& system() const { return _system; }

private:
  /// sum_s B_s local_op(s, B_s' lambda_s): the pattern of F and of the lumped preconditioner.
  template <class LocalOperator>
  la::Vector sum_over_subdomains(const la::Vector& lambda, LocalOperator&& local_op) const;

  const decomposition::SubdomainSystem& _system;
  int64_t _n_dual = 0;
  std::vector<std::vector<int64_t>> _rows;  ///< per subdomain: global row ids of B_s
  std::vector<la::SparseMatrix> _B;         ///< per subdomain: |rows_s| x n_s
  la::SparseMatrix _G;
};

/// The lumped preconditioner B K B' as a LinearOperator.
class LumpedPreconditioner : public la::LinearOperator
{
public:
  explicit LumpedPreconditioner(const FetiOperators& feti) : _feti(feti) {}
  la::Index size() const override { return _feti.n_dual(); }
  void apply(const la::Vector& x, la::Vector& y) const override { y = _feti.apply_lumped(x); }

private:
  const FetiOperators& _feti;
};

/// F as a LinearOperator, optionally scaled by `scale` (F / ||PFP|| in the dual penalty).
class FOperator : public la::LinearOperator
{
public:
  explicit FOperator(const FetiOperators& feti, double scale = 1.0) : _feti(feti), _scale(scale) {}
  la::Index size() const override { return _feti.n_dual(); }
  void apply(const la::Vector& x, la::Vector& y) const override { y = _scale * _feti.apply_F(x); }

private:
  const FetiOperators& _feti;
  double _scale;
};
} // namespace feticon::dual
