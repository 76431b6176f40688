#pragma once
/// @file MPGP: modified proportioning with gradient projections, for separable convex sets.
///
/// Solves
///
///     min f(x) = 1/2 x'Ax - b'x   subject to   x in Omega,
///
/// Omega separable (qp/separable_constraints.hpp): bounds l_i <= x_i <= u_i per component and
/// discs ||(x_i, x_j)|| <= r_k over pairs, A symmetric positive definite. Tresca friction in 3D
/// gives this dual QP: normal multipliers x_i >= 0, the two tangential multipliers of a contact
/// node in the disc of its slip bound. The algorithm is MPRGP (qp/mprgp.hpp) with its gradients
/// generalized per set, as in Dostal & Kozubek (2012), "An optimal algorithm and superrelaxation
/// for minimization of a quadratic function subject to separable convex constraints with
/// applications", Math. Program. 135, and Dostal et al. (2016), Scalable Algorithms for Contact
/// Problems, the chapter on Tresca friction in 3D. At a feasible x with gradient g = Ax - b, the
/// face of x holds the components at a bound and the discs of radius 0 fixed and lets an active
/// disc (on its circle, outward normal n) move along the circle:
///   phi   free gradient:    g projected onto the face: g on free components and inactive
///                           discs, the tangential part g - (n'g) n on active discs;
///   beta  chopped gradient: MPRGP's on bounds; max(n'g, 0) n on an active disc (-beta points
///                           into the disc); 0 on fixed components and discs of radius 0;
///   g_P = phi + beta, zero exactly at the KKT point (on an active disc g = -nu n, nu >= 0);
///   phi~  reduced free gradient (x - P(x - alpha_bar phi)) / alpha_bar, P the projection onto
///         Omega (radial scaling on a disc).
/// x is proportional when ||beta||^2 <= gamma^2 phi~'phi. Then:
///   CG step        along the conjugate direction p in the face, with the curvature of f along
///                  a circle: q = (A + K) p, K = nu/r on the active discs (nu = -n'g, the
///                  Hessian of the Lagrangian); the step is taken if it stays in Omega (the
///                  largest feasible step is the ratio on bounds and the positive root of a
///                  quadratic on inactive discs; active discs follow their circle through the
///                  projection, after which g is recomputed and the step kept only if f did not
///                  increase, else replaced by the gradient projection step below);
///   expansion step otherwise: the feasible half step x_h = P(x - alpha_f p), then
///                  P(x_h - alpha_bar phi(x_h)); alpha_bar is halved when f increased.
/// Otherwise a proportioning step along beta with the line-search length g'beta / beta'A beta,
/// cut where it reaches a bound or crosses a disc (as MPRGP; -beta points into Omega).
/// The gradient projection step P(x - alpha_bar g) of Dostal & Kozubek's MPGP (monotone for
/// alpha_bar <= 2/||A||, halved otherwise) replaces a step along circles that increased f; it
/// counts as an expansion step and in QpReport::expansion_fallbacks. Freezing active discs in
/// the face instead (phi = 0 there, their angle found by proportioning steps only) measured
/// thousands of steps on the test QPs (docs/friction.md).
///
/// Without discs the iterates are those of Mprgp::solve(b, lower, upper, x) with
/// MprgpExpansion::standard, bitwise (same steps, same per-component arithmetic, same
/// reductions): tests/unit/qp/test_mpgp.cpp checks it. MPRGP's projected-CG expansion is not
/// offered here.
///
/// Preconditioner (optional): applied in the face as in MPRGP, z = D_F M D_F phi with D_F the
/// orthogonal projector onto the face (0/1 on bounds, the tangent on an active disc), so D_F M
/// D_F is symmetric positive semidefinite and definite on the face for M symmetric positive
/// definite: preconditioned CG on the face is sound. The proportional test, the expansion and
/// proportioning steps stay unpreconditioned.
///
/// Distributed vectors: every reduction goes through A.space() (la::VectorSpace); each rank
/// passes its local bounds and discs, a disc's two indices on one rank.
///
/// Operator products (QpReport::hessian_multiplications) are counted exactly, power iterations
/// and gradient refreshes included; without discs as MPRGP's
///   power iterations (first solve, alpha_bar = 0) + 1 + cg_steps + 2 expansion_steps
///   + proportioning_steps + floor(iterations / gradient_refresh),
/// with discs one more for each CG step along circles (the recomputed g), and a fallback
/// (counted as an expansion step) costs its CG or expansion step's products plus one.
///
/// Usage:
///   qp::SeparableConstraints set{lower, upper, discs};
///   qp::Mpgp mpgp(A, {.rtol = 1e-8});
///   la::Vector x = la::Vector::Zero(n);          // projected onto Omega by solve()
///   const qp::QpReport report = mpgp.solve(b, set, x);

#include "la/operator.hpp"
#include "qp/mprgp.hpp"
#include "qp/qp_report.hpp"
#include "qp/separable_constraints.hpp"

#include <functional>
#include <optional>
#include <string>

namespace feticon::qp
{
/// Parameters of Mpgp: MprgpOptions, whose `expansion` it ignores (MPGP has the standard
/// expansion step only).
using MpgpOptions = MprgpOptions;

/// QP solver over a separable convex set; see the file comment. Keeps alpha_bar between
/// solves, as Mprgp does.
class Mpgp : public QpSolver
{
public:
  /// @param[in] A        symmetric operator, positive definite on the iterates' span;
  ///                     referenced, must outlive the object.
  /// @param[in] options  parameters; checked here (FETICON_CHECK).
  Mpgp(const la::LinearOperator& A, MpgpOptions options);

  /// @brief Minimizes 1/2 x'Ax - b'x subject to x in Omega.
  /// @param[in]     b    right-hand side, finite, size A.size().
  /// @param[in]     set  Omega (this rank's components); checked by
  ///                     check_separable_constraints.
  /// @param[in,out] x    initial guess (finite), projected onto Omega; on output the last
  ///                     iterate, feasible (is_feasible).
  /// @return counters and state; converged = false with a reason on max_iterations, a
  ///         non-finite gradient norm or a non-positive curvature p'Ap.
  /// Throws feticon::Error for invalid input, one line naming the component or disc.
  /// `gradient` as in QpSolver::solve.
  QpReport solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x, la::Vector* gradient) override;
  using QpSolver::solve;

  /// The current expansion step length (0 before the first solve when it is estimated).
  double alpha_bar() const override { return _alpha_bar; }

private:
  /// x, g = Ax - b, the direction p and the work vectors of one solve (mpgp.cpp).
  struct SolveState;

  /// g = Ax - b recomputed (start, and every gradient_refresh steps).
  void refresh_gradient(SolveState& s) const;
  /// The CG and restart direction: phi, preconditioned in the face when a preconditioner is set.
  void direction(SolveState& s, la::Vector& out) const;
  /// At a proportional x: the CG step, or the expansion step where it would leave Omega.
  std::optional<std::string> cg_or_expansion_step(SolveState& s, double cost);
  /// x and g moved by alpha_cg along p, and the next conjugate p; `on_circles`: p moves an
  /// active disc (g recomputed, the step replaced by a gradient projection step if f grew).
  void cg_step(SolveState& s, double alpha_cg, double pq, bool on_circles, double cost);
  /// Feasible half step of length alpha_f, then P(x_h - alpha_bar phi(x_h)); p restarted.
  void expansion_step(SolveState& s, double alpha_f, la::Index blocking, bool on_circles, double cost);
  /// At a non-proportional x: the step along beta, cut where it reaches a bound or a circle.
  std::optional<std::string> proportioning_step(SolveState& s);
  /// x <- P(x - alpha_bar g) with g updated (alpha_bar halved if f increased), counted as an
  /// expansion step and an expansion fallback; p restarted.
  void gradient_projection_step(SolveState& s, double cost);

  const la::LinearOperator& _A;
  MpgpOptions _options;
  double _alpha_bar;
};
} // namespace feticon::qp
