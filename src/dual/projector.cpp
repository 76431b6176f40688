#include "dual/projector.hpp"

#include "common/error.hpp"

namespace feticon::dual
{
namespace
{
/// Factorizes G G' into `llt`; returns the pivot ratio (CoarseProjector::pivot_ratio), 1 for an
/// empty coarse space, 0 where the factorization failed: dependent rows of G show up as a
/// (nearly) zero pivot.
double factorize(const la::SparseMatrix& GGt, Eigen::SimplicialLLT<la::SparseMatrix>& llt)
{
  llt.compute(GGt);
  if (llt.info() != Eigen::Success)
    return 0;
  if (GGt.rows() == 0)
    return 1;
  const la::Vector d = llt.matrixL().nestedExpression().diagonal().cwiseAbs();
  return d.minCoeff() / d.maxCoeff();
}
} // namespace

CoarseProjector::CoarseProjector(const FetiOperators& feti, std::nothrow_t, std::vector<char> mask)
    : _feti(feti), _mask(std::move(mask))
{
  FETICON_ASSERT(_mask.empty() || static_cast<int64_t>(_mask.size()) == feti.n_dual(), "mask size");
  _pivot_ratio = factorize(feti.coarse_matrix(_mask.empty() ? nullptr : &_mask), _llt);
}

CoarseProjector::CoarseProjector(const FetiOperators& feti, std::vector<char> mask)
    : CoarseProjector(feti, std::nothrow, std::move(mask))
{
  FETICON_CHECK(full_rank(),
                "the constraints do not suppress every rigid-body motion (G G' is "
                "singular): a body is free to move; add supports or symmetry conditions");
}

la::Vector CoarseProjector::apply_G(const la::Vector& lambda) const
{
  return _feti.apply_G(lambda, _mask.empty() ? nullptr : &_mask);
}

la::Vector CoarseProjector::apply_Gt(const la::Vector& alpha) const
{
  return _feti.apply_Gt(alpha, _mask.empty() ? nullptr : &_mask);
}

la::Vector CoarseProjector::coarse_solve(const la::Vector& y) const { return _llt.solve(y); }

la::Vector CoarseProjector::apply_Q(const la::Vector& lambda) const { return apply_Gt(coarse_solve(apply_G(lambda))); }

la::Vector CoarseProjector::apply_G_tilde(const la::Vector& lambda) const
{
  return _llt.matrixL().solve(_llt.permutationP() * apply_G(lambda));
}

la::Vector CoarseProjector::apply_G_tilde_t(const la::Vector& omega) const
{
  return apply_Gt(coarse_multiplier(omega));
}

la::Vector CoarseProjector::from_tilde(const la::Vector& g_tilde_lambda) const
{
  return _llt.permutationPinv() * la::Vector(_llt.matrixL() * g_tilde_lambda);
}

la::Vector CoarseProjector::coarse_multiplier(const la::Vector& omega) const
{
  return _llt.permutationPinv() * la::Vector(_llt.matrixU().solve(omega));
}

la::Vector CoarseProjector::tilde_multiplier(const la::Vector& beta) const
{
  return _llt.matrixU() * la::Vector(_llt.permutationP() * beta);
}

la::Vector CoarseProjector::particular_solution(const la::Vector& e) const { return apply_Gt(coarse_solve(e)); }

void ProjectedOperator::apply(const la::Vector& x, la::Vector& y) const
{
  const la::Vector q = _projector.apply_Q(x);
  la::Vector Apx;
  _A.apply(x - q, Apx);
  y = _projector.apply_P(Apx);
  if (_rho != 0.0)
    y += _rho * q;
}
} // namespace feticon::dual
