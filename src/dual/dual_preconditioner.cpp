#include "dual/dual_preconditioner.hpp"

#include "common/error.hpp"

namespace feticon::dual
{
DualPreconditionerOperator::DualPreconditionerOperator(const FetiOperators& feti, const CoarseProjector& projector,
                                                       const DualPenaltyOptions& options, double s, int64_t n_equality,
                                                       double rho, const std::vector<char>& held)
    : _feti(feti), _projector(projector), _options(options), _s(s), _rho(rho)
{
  if (options.constraint_scaling)
    _scaling.emplace(feti, n_equality, held);
  FETICON_CHECK(options.preconditioner != DualPreconditioner::dirichlet || options.schur,
                "the Dirichlet preconditioner needs the subdomain Schur complements");
}

void DualPreconditionerOperator::apply(const la::Vector& x, la::Vector& y) const
{
  const la::Vector q = _projector.apply_Q(x);
  const la::Vector p = scale(x - q);
  const la::Vector Xp = _options.preconditioner == DualPreconditioner::dirichlet
      ? _feti.apply_dirichlet(p, *_options.schur)
      : _feti.apply_lumped(p);
  y = _s * _projector.apply_P(scale(Xp));
  if (_rho > 0)
    y += q / _rho;
}
} // namespace feticon::dual
