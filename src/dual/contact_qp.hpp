#pragma once
/// @file The contact dual as a QP object (PERMON's QP with its transforms): the FETI dual
/// of Vondrák et al. (DD XVI, 2007), problem (9), homogenized and scaled, with its
/// constraints by row kind and the maps back to lambda and u (ALGORITHMS.md section 1).
///
///   lambda = lambda~ + mu,  G lambda~ = e (particular_solution in contact_qp.cpp),
///   min 1/2 mu' A mu - mu' b   s.t.  mu in Omega,  G~ mu = 0 (SMALBE-M; the dual penalty
///   adds rho Q to A instead),
///   A = P F^ P,  b = P (d^ - F^ lambda~),  F^ = F / ||PFP||,  d^ = d / ||PFP||,
///   Omega: mu_i free on equality rows, mu_i >= -lambda~_i on normal contact rows,
///          -g_i - lambda~_i <= mu_i <= g_i - lambda~_i on tangential rows (Tresca's box, 2D),
///          ||mu_d + lambda~_d|| <= g_d on the pair d of a node's tangential rows (disc, 3D).
/// Scaling by ||PFP|| (power iterations) leaves the minimizer unchanged and makes rho and the
/// tolerances dimensionless.
/// Penalty contact laws (fem::NormalLaw linear: p = K max(d, 0)) enter as a compliance: F is
/// F + C with C = diag(C_i), C_i = 1 / (K A_i |b_i|^2) on the normal rows of such a pair (A_i
/// the slave node's area, |b_i| the row's norm, contact_constraints.hpp) and 0 elsewhere, so
/// that at the minimizer B_i u - c_i = C_i lambda_i where lambda_i > 0 (the penetration the law
/// allows) and B_i u <= c_i where lambda_i = 0: the KKT conditions of the law, with no new
/// kind of constraint; primal recovery takes c_i + C_i lambda_i on the active rows. Coordinates of SMALBE-M's multiplier omega of G~ mu = 0: inside
/// the QP it is scaled and in G~'s rows; outside (qp::QpState of a dual solve) it is the
/// coarse vector beta by rigid modes, unscaled, which carries over to the next outer
/// iteration's G (CoarseProjector::coarse_multiplier).

#include "dual/dual_penalty_problem.hpp"
#include "dual/dual_preconditioner.hpp"
#include "dual/primal_recovery.hpp"
#include "dual/projector.hpp"
#include "qp/norm_estimate.hpp"
#include "qp/qp_state.hpp"
#include "qp/separable_constraints.hpp"
#include "qp/smalbe.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace feticon::dual
{
/// What a dual row constrains.
enum class RowKind : uint8_t
{
  equality,  ///< gluing, supports, linear equations: B_E u = c_E, multiplier free
  normal,    ///< contact: B_I u <= c_I, multiplier >= 0
  tangential ///< friction: |multiplier| <= g (Tresca's slip bound, or mu times the normal force)
};

/// The tangential rows of a problem with friction and their slip bounds.
struct FrictionRows
{
  int64_t n_normal = 0;  ///< the normal rows are ids [n_equality, n_equality + n_normal), the
                         ///< tangential ones follow
  la::Vector slip_bound; ///< g_i >= 0 of each owned row (row-normalized force; others ignored)
  /// Tangential rows per normal row: 1 (plane strain: the box |lambda_i| <= g_i), or 2 (3D:
  /// the rows n_equality + n_normal + 2j and + 2j + 1 of node j, on one rank, in the disc
  /// ||(lambda_i, lambda_i+1)|| <= g_i).
  int n_tangents = 1;
  /// Per owned row: a tangential row whose tangent supports hold (contact::TangentialRows::
  /// held): its multiplier is fixed at 0 and the other row of its node has the box
  /// |lambda_i| <= g_i. Empty: none.
  std::vector<char> held;
  bool is_held(la::Index i) const { return !held.empty() && held[static_cast<size_t>(i)]; }
};

/// The kinds of `feti`'s owned rows: ids below n_equality are equalities; without friction the
/// rest are normal contact rows, with it the next friction->n_normal, then tangential ones.
std::vector<RowKind> row_kinds(const FetiOperators& feti, int64_t n_equality, const FrictionRows* friction = nullptr);

class ContactQp
{
public:
  /// @param c         right-hand sides of the owned rows (B u = c_E, B u <= c_I)
  /// @param f_stacked stacked load
  /// @param n_equality global number of equality rows (ids below it; the rest are contact
  ///                  rows, row_kinds)
  /// @param options   rho (dual penalty: in A), preconditioner, power iterations (referenced)
  /// @param pfp_norm  ||PFP|| of a solve with the same F, or 0 to estimate it here
  /// @param friction  the tangential rows and their slip bounds, or null without friction
  /// @param compliance C_i per owned row (see the file comment), or null for hard contact
  /// Vectors are this rank's parts (FetiOperators); feti, c, f_stacked and compliance are referenced.
  ContactQp(const FetiOperators& feti, const la::Vector& c, const la::Vector& f_stacked, int64_t n_equality,
            const DualPenaltyOptions& options, double pfp_norm, const FrictionRows* friction = nullptr,
            const la::Vector* compliance = nullptr);

  /// A = P F^ P, + rho Q for the dual penalty; timed.
  const la::TimedOperator& hessian() const { return _A; }
  const la::Vector& rhs() const { return _b; }
  const qp::SeparableConstraints& constraints() const { return _set; }
  /// G~, orthonormal rows.
  const qp::EqualityOperator& equality() const { return _C; }
  /// The preconditioner of A (none: null); timed.
  const la::TimedOperator* preconditioner() const { return _timed_preconditioner ? &*_timed_preconditioner : nullptr; }
  const CoarseProjector& projector() const { return _projector; }
  /// The scaled F^.
  const FOperator& scaled_F() const { return _F; }
  double pfp_norm() const { return _norm.value; }
  /// Products with PFP spent on the norm estimate (0 when it was given).
  int norm_applications() const { return _norm.applications; }
  const std::vector<RowKind>& kinds() const { return _kinds; }
  /// g_i of owned tangential row i (0 without friction).
  double slip_bound(la::Index i) const { return _friction ? _friction->slip_bound(i) : 0.0; }
  /// Whether owned row i is a tangential row that supports hold (FrictionRows::held).
  bool held(la::Index i) const { return _friction && _friction->is_held(i); }
  /// Per owned row, FrictionRows::held (empty: none).
  const std::vector<char>& held_rows() const
  {
    static const std::vector<char> none;
    return _friction ? _friction->held : none;
  }

  /// mu of lambda, projected onto Ker G (a warm start of a changed G); 0 if lambda is empty.
  la::Vector mu(const la::Vector& lambda) const;
  la::Vector lambda(const la::Vector& mu) const { return _lambda_tilde + mu; }
  /// SMALBE-M's start from a dual solve's state (omega as a coarse vector), or none when the
  /// state has no multiplier for this coarse space.
  std::optional<qp::QpState> inner_start(const qp::QpState& state) const;
  /// The dual solve's state of SMALBE-M's result (omega back to a coarse vector).
  qp::QpState outer_state(const la::Vector& lambda, const qp::SmalbeReport& report) const;
  /// ||G lambda - e|| / ||e||, or / ||lambda|| where ||e|| <= 1e-10 ||lambda|| (self-equilibrated loads).
  double feasibility_error(const la::Vector& lambda) const;
  /// ||e||, the net load on the subdomains' rigid modes.
  double load_norm() const { return _e.norm(); }
  /// u from lambda and its active rows (primal_recovery.hpp); `unheld` explains a body the
  /// active rows leave free.
  PrimalSolution recover(const la::Vector& lambda, const std::vector<char>& active, const std::string& unheld,
                         const SlidingRows& sliding = {}) const;

private:
  const FetiOperators& _feti;
  const la::Vector& _c;
  const la::Vector& _f_stacked;
  const FrictionRows* _friction;
  const la::Vector* _compliance;
  std::vector<RowKind> _kinds;
  CoarseProjector _projector;
  la::Vector _e;
  la::Vector _lambda_tilde;
  qp::NormEstimate _norm;
  double _scale; ///< 1 / ||PFP||
  FOperator _F;
  ProjectedOperator _A_untimed;
  la::TimedOperator _A;
  la::Vector _b;
  qp::SeparableConstraints _set;
  /// G~ as SMALBE-M's equality operator.
  class GTildeOperator : public qp::EqualityOperator
  {
  public:
    explicit GTildeOperator(const CoarseProjector& projector) : _projector(projector) {}
    la::Vector apply(const la::Vector& x) const override { return _projector.apply_G_tilde(x); }
    la::Vector apply_transpose(const la::Vector& y) const override { return _projector.apply_G_tilde_t(y); }

  private:
    const CoarseProjector& _projector;
  } _C;
  std::optional<DualPreconditionerOperator> _preconditioner;
  std::optional<la::TimedOperator> _timed_preconditioner;
};
} // namespace feticon::dual
