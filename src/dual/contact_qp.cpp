#include "dual/contact_qp.hpp"

#include "common/error.hpp"
#include "common/log.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace feticon::dual
{
namespace
{
/// Particular solution of G lambda = e (ALGORITHMS.md 1): variant B, lambda~ = [lambda~_E; 0]
/// from the equality rows alone, when they fix every rigid mode; then the contact bounds
/// are simply lambda_I >= 0 and mu = 0 is feasible. Otherwise (a body held only by
/// contact, like the Hertz cylinder) variant A, the minimal-norm G'(GG')^{-1} e.
/// @param load_scale  the largest nodal force (max |f|, on every rank)
la::Vector particular_solution(const FetiOperators& feti, const CoarseProjector& projector, const la::Vector& e,
                               const std::vector<RowKind>& kinds, double load_scale)
{
  // Either variant must satisfy G lambda~ = e. The pivot test of G_E G_E' can miss a
  // mode that only contact holds once that matrix is large (a 1 025-subdomain punch: the
  // round-off pivot passed, lambda~ missed the punch's load and SMALBE-M "converged" to a
  // zero contact force), so the equation itself decides. Relative to e, unless e is the
  // round-off of loads that balance on every subdomain (a pretension section's pairs of forces
  // within one subdomain: |e| = 1e-14 of the loads): then relative to the loads.
  const double tolerance = 1e-6 * std::max({e.norm(), 1e-8 * load_scale, 1e-300});
  const int64_t local_contact_rows =
      std::count_if(kinds.begin(), kinds.end(), [](RowKind k) { return k != RowKind::equality; });
  if (feti.comm().sum(local_contact_rows) > 0)
  {
    std::vector<char> equality_mask(kinds.size(), 0);
    for (size_t i = 0; i < kinds.size(); ++i)
      equality_mask[i] = kinds[i] == RowKind::equality;
    const CoarseProjector equality_projector(feti, std::nothrow, std::move(equality_mask));
    if (equality_projector.full_rank())
    {
      la::Vector lambda_tilde = equality_projector.particular_solution(e);
      if ((feti.apply_G(lambda_tilde) - e).norm() <= tolerance)
        return lambda_tilde;
    }
  }
  la::Vector lambda_tilde = projector.particular_solution(e);
  const double residual = (feti.apply_G(lambda_tilde) - e).norm();
  FETICON_CHECK(residual <= tolerance,
                "coarse problem: ||G lambda~ - e|| = " << residual << " exceeds " << tolerance
                                                       << " (G G' too ill-conditioned to balance the loads)");
  return lambda_tilde;
}

/// ||PFP||, the scale of the dual: the caller's last estimate, or power iterations.
qp::NormEstimate pfp_norm_estimate(const FetiOperators& feti, const CoarseProjector& projector,
                                   const DualPenaltyOptions& options, double known, const la::Vector* compliance)
{
  // ||PFP|| changes little when only the contact rows change (ALGORITHMS.md section 8): the
  // caller passes the last estimate while F is the same, and the power iterations (6-7
  // products per QP on Hertz) are skipped. It only scales F; a too small value makes an
  // expansion step too long, which MPRGP detects and halves.
  if (known > 0)
    return {known, 0};
  const FOperator F_raw(feti, 1.0, compliance);
  const ProjectedOperator PFP_raw(F_raw, projector, 0.0);
  qp::NormEstimate norm = qp::estimate_norm(PFP_raw, options.power_iterations, 1e-3, 1);
  if (norm.value == 0)
  {
    // P F P = 0: every row is in the range of G' (a body held by as many rows as it has rigid
    // modes, such as an axisymmetric one by one axial support), so lambda = lambda~ and the QP
    // is trivial. The scale of F keeps the penalty rho ||PFP|| of H positive.
    const qp::NormEstimate f_norm = qp::estimate_norm(F_raw, options.power_iterations, 1e-3, 1);
    norm = {f_norm.value, norm.applications + f_norm.applications};
  }
  FETICON_CHECK(norm.value > 0 && std::isfinite(norm.value), "||PFP|| estimate " << norm.value << " is not positive");
  return norm;
}

/// Omega of the homogenized unknown mu = lambda - lambda~: mu_i >= -lambda~_i on the normal
/// contact rows, free on the equality rows, |lambda~_i + mu_i| <= g_i on tangential rows of
/// plane strain, ||lambda~_d + mu_d|| <= g_d on the pairs of 3D. No upper bounds without
/// friction (MPRGP's lower-bound arithmetic, as before friction existed).
qp::SeparableConstraints constraint_set(const FetiOperators& feti, const std::vector<RowKind>& kinds,
                                        const la::Vector& lambda_tilde, int64_t n_equality,
                                        const FrictionRows* friction)
{
  constexpr double inf = std::numeric_limits<double>::infinity();
  qp::SeparableConstraints set;
  set.lower = la::Vector::Constant(lambda_tilde.size(), -inf);
  if (friction)
    set.upper = la::Vector::Constant(lambda_tilde.size(), inf);
  std::map<int64_t, la::Index> second_tangent; // id -> owned index, of the 3D pairs' second rows
  for (size_t i = 0; i < kinds.size(); ++i)
    if (kinds[i] == RowKind::normal)
      set.lower(i) = -lambda_tilde(i);
    else if (kinds[i] == RowKind::tangential)
    {
      const double g = friction->slip_bound(i);
      FETICON_CHECK(g >= 0, "friction: slip bound " << g << " of dual row " << i); // +infinity: sticks
      if (friction->n_tangents == 1)
      {
        set.lower(i) = -g - lambda_tilde(i);
        set.upper(i) = g - lambda_tilde(i);
      }
      else
        second_tangent[feti.row_id(i)] = static_cast<la::Index>(i);
    }
  // A held row's multiplier is 0; its partner alone takes friction, in the box |lambda| <= g.
  const auto fix_or_box = [&](la::Index i) {
    const double g = friction->is_held(i) ? 0.0 : friction->slip_bound(i);
    set.lower(i) = -g - lambda_tilde(i);
    set.upper(i) = g - lambda_tilde(i);
  };
  for (const auto& [id, i] : second_tangent)
  {
    if ((id - n_equality - friction->n_normal) % 2 != 0)
      continue; // a pair's second row
    const auto j = second_tangent.find(id + 1);
    FETICON_CHECK(j != second_tangent.end(),
                  "friction: the tangential rows " << id << " and " << id + 1 << " of one node are on different ranks");
    if (friction->is_held(i) || friction->is_held(j->second))
      fix_or_box(i), fix_or_box(j->second);
    else if (std::isfinite(friction->slip_bound(i))) // +infinity: the pair sticks, free components
      set.discs.push_back({i, j->second, friction->slip_bound(i), -lambda_tilde(i), -lambda_tilde(j->second)});
  }
  return set;
}
} // namespace

std::vector<RowKind> row_kinds(const FetiOperators& feti, int64_t n_equality, const FrictionRows* friction)
{
  std::vector<RowKind> kinds(feti.n_dual());
  for (la::Index i = 0; i < feti.n_dual(); ++i)
  {
    const int64_t id = feti.row_id(i);
    kinds[i] = id < n_equality                              ? RowKind::equality
        : !friction || id < n_equality + friction->n_normal ? RowKind::normal
                                                            : RowKind::tangential;
  }
  return kinds;
}

ContactQp::ContactQp(const FetiOperators& feti, const la::Vector& c, const la::Vector& f_stacked, int64_t n_equality,
                     const DualPenaltyOptions& options, double pfp_norm, const FrictionRows* friction,
                     const la::Vector* compliance)
    : _feti(feti), _c(c), _f_stacked(f_stacked), _friction(friction), _compliance(compliance),
      _kinds(row_kinds(feti, n_equality, friction)), _projector(feti), _e(feti.apply_Rt(f_stacked)),
      _lambda_tilde(
          particular_solution(feti, _projector, _e, _kinds, feti.comm().max(f_stacked.lpNorm<Eigen::Infinity>()))),
      _norm(pfp_norm_estimate(feti, _projector, options, pfp_norm, compliance)), _scale(1.0 / _norm.value),
      _F(feti, _scale, compliance),
      // The dual penalty's A holds rho Q; SMALBE-M adds rho Q = rho G~'G~ itself (for the rho
      // it has at the time).
      _A_untimed(_F, _projector, options.method == DualMethod::smalbe ? 0.0 : options.rho), _A(_A_untimed),
      _set(constraint_set(feti, _kinds, _lambda_tilde, n_equality, friction)), _C(_projector)
{
  FETICON_CHECK(c.size() == feti.n_dual() && n_equality <= feti.n_dual_global() &&
                    (!friction || friction->slip_bound.size() == feti.n_dual()) &&
                    (!compliance || compliance->size() == feti.n_dual()),
                "dual problem: sizes do not match");
  const la::Vector d = feti.apply_B(feti.apply_K_plus(f_stacked)) - c;
  la::Vector F_lambda_tilde;
  FOperator(feti, 1.0, compliance).apply(_lambda_tilde, F_lambda_tilde); // (F + C) lambda~
  _b = _projector.apply_P(_scale * (d - F_lambda_tilde));
  if (options.preconditioner != DualPreconditioner::none)
  {
    _preconditioner.emplace(feti, _projector, options, _norm.value, n_equality,
                            options.method == DualMethod::smalbe ? 0.0 : options.rho, held_rows());
    // Penalty rows among dependent ones: the preconditioner would leave their difference
    // unreduced (fricloop with its LINEAR law stalled at |g_P| 5e-5 for 20 000 steps); the QP
    // is then solved without it.
    if (compliance && !_preconditioner->scaled())
    {
      log::warning("penalty contact rows among linearly dependent constraint rows: the dual QP is solved without "
                   "preconditioner");
      _preconditioner.reset();
    }
    else
      _timed_preconditioner.emplace(*_preconditioner);
  }
}

la::Vector ContactQp::mu(const la::Vector& lambda) const
{
  // Projected onto Ker G: when K_M(u) or the contact rows change, G changes and
  // lambda_start - lambda~ is far from Ker G, which SMALBE-M would then repair slowly
  // through its multiplier (the inner stop ||g_P|| <= M ||G~ mu|| passes at once).
  if (lambda.size() != _feti.n_dual())
    return la::Vector::Zero(_feti.n_dual());
  return _projector.apply_P(lambda - _lambda_tilde);
}

std::optional<qp::QpState> ContactQp::inner_start(const qp::QpState& state) const
{
  // The multiplier of G~ mu = 0 in the scaled dual is 1/||PFP|| times the unscaled one.
  if (state.omega.size() != _feti.n_kernel())
    return std::nullopt;
  return qp::QpState{{}, _projector.tilde_multiplier(_scale * state.omega), state.M, state.rho, 0};
}

qp::QpState ContactQp::outer_state(const la::Vector& lambda, const qp::SmalbeReport& report) const
{
  return {lambda, _projector.coarse_multiplier(report.omega) / _scale, report.final_M, report.final_rho, _norm.value};
}

double ContactQp::feasibility_error(const la::Vector& lambda) const
{
  // Relative to the loads on the floating modes, or to the multipliers where those loads are
  // round-off (self-equilibrated: a press fit's ||e|| was 1e-13 N against 5e4 N of contact
  // force, and ||G lambda - e|| / ||e|| read 1e10 for an answer balanced to 4e-8 of its forces).
  const double e_norm = _e.norm();
  const double scale = e_norm > 1e-10 * lambda.norm() ? e_norm : lambda.norm();
  return (_feti.apply_G(lambda) - _e).norm() / (scale > 0 ? scale : 1.0);
}

PrimalSolution ContactQp::recover(const la::Vector& lambda, const std::vector<char>& active, const std::string& unheld,
                                  const SlidingRows& sliding) const
{
  if (!_compliance)
    return recover_primal(_feti, _f_stacked, _c, lambda, active, unheld, sliding);
  // A penalty row holds at the penetration its law gives the multiplier: B_i u = c_i + C_i lambda_i.
  return recover_primal(_feti, _f_stacked, _c + _compliance->cwiseProduct(lambda), lambda, active, unheld, sliding);
}
} // namespace feticon::dual
