#pragma once
/// @file The preconditioner of the dual QP: M = s P Y X Y P [+ Q / rho], X = B K B' (lumped)
/// or B S B' (Dirichlet), Y = (B B')^{-1} (constraint_scaling.hpp): the FETI preconditioner on
/// Im P (scaled like F^ = F / s) and, with rho > 0, the exact inverse of H = ... + rho Q on
/// Im Q (SMALBE-M adds that term itself, for its current rho, and is given rho = 0).

#include "dual/constraint_scaling.hpp"
#include "dual/dual_penalty_problem.hpp"
#include "dual/projector.hpp"

#include <optional>

namespace feticon::dual
{
class DualPreconditionerOperator : public la::LinearOperator
{
public:
  /// @param s the scale of F^ = F / s (||PFP||)
  /// @param held friction rows that supports hold (ConstraintScaling)
  DualPreconditionerOperator(const FetiOperators& feti, const CoarseProjector& projector,
                             const DualPenaltyOptions& options, double s, int64_t n_equality, double rho,
                             const std::vector<char>& held = {});
  la::Index size() const override { return _feti.n_dual(); }
  const la::VectorSpace* space() const override { return &_feti.space(); }
  void apply(const la::Vector& x, la::Vector& y) const override;
  /// Whether Y = (B B')^{-1} is applied (not where the rows are (nearly) dependent): without
  /// it X is singular on the combinations of dependent rows, which F^ + C is not where those
  /// rows have a compliance C (contact_qp.hpp), and a CG step could not reduce their gradient.
  bool scaled() const { return _scaling && _scaling->factorized(); }

private:
  la::Vector scale(const la::Vector& x) const { return _scaling ? _scaling->apply(x) : x; }

  const FetiOperators& _feti;
  const CoarseProjector& _projector;
  const DualPenaltyOptions& _options;
  double _s, _rho;
  std::optional<ConstraintScaling> _scaling;
};
} // namespace feticon::dual
