#pragma once
/// @file Coarse space projectors Q = G'(GG')^{-1}G and P = I - Q (ALGORITHMS.md section 1).
///
/// GG' (sparse: subdomains couple only with neighbours) is factorized once by a sparse
/// Cholesky with fill-reducing ordering, P_o GG' P_o' = L L'; the orthonormalized
/// G~ = L^{-1} P_o G is applied implicitly (G~ G~' = I), so Q = G~' G~ = G'(GG')^{-1}G.
/// Distributed, GG' and its factor are replicated on every rank (they are small: 6 per
/// subdomain); G and G' are FetiOperators products, dual vectors stay distributed.
/// With a mask (one flag per owned dual row), G is replaced by G_A, its masked columns.

#include "dual/feti_operators.hpp"
#include "la/operator.hpp"

#include <Eigen/SparseCholesky>
#include <new>

namespace feticon::dual
{
class CoarseProjector
{
public:
  /// Factorizes G G'. Throws feticon::Error if G has dependent rows, i.e. some rigid
  /// motion is not suppressed by any constraint (a body that can fly away).
  explicit CoarseProjector(const FetiOperators& feti, std::vector<char> mask = {});
  /// Factorizes G G' without throwing; full_rank() tells whether it succeeded, and only then
  /// may the other members be used.
  CoarseProjector(const FetiOperators& feti, std::nothrow_t, std::vector<char> mask = {});
  /// True if G has full row rank (G G' factorized with no vanishing pivot).
  bool full_rank() const { return _pivot_ratio > 1e-7; }
  /// Smallest over largest pivot of the Cholesky factor of G G' (0 where it failed): its square
  /// is about the ratio of G G''s extreme eigenvalues.
  double pivot_ratio() const { return _pivot_ratio; }

  la::Vector apply_Q(const la::Vector& lambda) const;
  la::Vector apply_P(const la::Vector& lambda) const { return lambda - apply_Q(lambda); }
  /// G~ lambda = L^{-1} G lambda and G~' omega.
  la::Vector apply_G_tilde(const la::Vector& lambda) const;
  la::Vector apply_G_tilde_t(const la::Vector& omega) const;
  /// beta with G' beta = G~' omega (beta = P_o' L^{-T} omega: indexed by rigid modes, so it
  /// carries over to a projector of changed G), and omega = L' P_o beta back.
  la::Vector coarse_multiplier(const la::Vector& omega) const;
  la::Vector tilde_multiplier(const la::Vector& beta) const;
  /// G lambda from G~ lambda: P_o' L (G~ lambda), e.g. ||G mu|| in force units from SMALBE-M's
  /// ||C x|| without applying G again.
  la::Vector from_tilde(const la::Vector& g_tilde_lambda) const;
  /// (G G')^{-1} y.
  la::Vector coarse_solve(const la::Vector& y) const;
  /// Minimal-norm solution of G lambda = e: G'(GG')^{-1} e.
  la::Vector particular_solution(const la::Vector& e) const;

private:
  la::Vector apply_G(const la::Vector& lambda) const;
  la::Vector apply_Gt(const la::Vector& alpha) const;

  const FetiOperators& _feti;
  std::vector<char> _mask; ///< empty: all rows
  Eigen::SimplicialLLT<la::SparseMatrix> _llt;
  double _pivot_ratio = 0;
};

/// P as a LinearOperator.
class ProjectorP : public la::LinearOperator
{
public:
  explicit ProjectorP(const CoarseProjector& projector, la::Index n) : _projector(projector), _n(n) {}
  la::Index size() const override { return _n; }
  void apply(const la::Vector& x, la::Vector& y) const override { y = _projector.apply_P(x); }

private:
  const CoarseProjector& _projector;
  la::Index _n;
};

/// P A P + rho Q for a symmetric operator A (rho = 0 gives P A P).
class ProjectedOperator : public la::LinearOperator
{
public:
  ProjectedOperator(const la::LinearOperator& A, const CoarseProjector& projector, double rho)
      : _A(A), _projector(projector), _rho(rho)
  {
  }
  la::Index size() const override { return _A.size(); }
  const la::VectorSpace* space() const override { return _A.space(); }
  void apply(const la::Vector& x, la::Vector& y) const override;

private:
  const la::LinearOperator& _A;
  const CoarseProjector& _projector;
  double _rho;
};
} // namespace feticon::dual
