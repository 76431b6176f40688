#pragma once
/// @file MPRGP: modified proportioning with reduced gradient projections.
///
/// Solves the box-constrained quadratic program
///
///     min f(x) = 1/2 x'Ax - b'x   subject to   l <= x <= u,
///
/// with A symmetric positive definite (on the iterates' span), l_i possibly -infinity and
/// u_i possibly +infinity, by the algorithm of Dostal & Schoberl (2005), "Minimizing
/// quadratic functions subject to bound constraints with the rate of convergence and finite
/// termination", Comput. Optim. Appl. 30, as written in ALGORITHMS.md section 5 for x >= l,
/// with both bounds as in Dostal (2009), Optimal Quadratic Programming Algorithms, ch. 8.
/// At a feasible x with gradient g = Ax - b, free set F = {i : l_i < x_i < u_i} and active
/// set the rest:
///   phi   free gradient,        phi_i = g_i on F, 0 elsewhere;
///   beta  chopped gradient,     beta_i = min(g_i, 0) where x_i = l_i < u_i,
///                               beta_i = max(g_i, 0) where x_i = u_i > l_i, 0 elsewhere
///                               (a component with l_i = u_i is fixed);
///   g_P   projected gradient,   g_P = phi + beta;
///   phi~  reduced free gradient, phi~_i = min((x_i - l_i)/alpha_bar, max((x_i - u_i)/alpha_bar, phi_i))
///                               on F, so that x - alpha_bar phi~ = P(x - alpha_bar phi).
/// x is proportional when ||beta||^2 <= gamma^2 phi~'phi; then MPRGP takes a CG step, or, if
/// that leaves the feasible set, an expansion step (feasible half step + projected gradient
/// step of length alpha_bar); otherwise a proportioning step along beta, cut at the first
/// bound it reaches (only an upper bound of a component leaving its lower one, or the
/// reverse, can stop it; without upper bounds it is never cut).
///
/// Without upper bounds (the solve overload without `upper`) the arithmetic is that of the
/// lower-bound algorithm; with u = +infinity everywhere the iterates are the same bitwise.
///
/// Operator products (QpReport::hessian_multiplications) are counted exactly:
///
///     power iterations (first solve only, when alpha_bar is estimated)
///   + 1                                   initial gradient g = Ax - b
///   + cg_steps + 2 expansion_steps + expansion_fallbacks + proportioning_steps
///   + floor(iterations / gradient_refresh) gradient refreshes g = Ax - b
///
/// Usage:
///   qp::Mprgp mprgp(A, {.rtol = 1e-6});
///   la::Vector x = la::Vector::Zero(n);          // projected onto the box by solve()
///   const qp::QpReport report = mprgp.solve(b, lower, x);          // x >= l
///   const qp::QpReport box = mprgp.solve(b, lower, upper, y);      // l <= y <= u
///   if (!report.converged) log::warning(report.reason);

#include "la/operator.hpp"
#include "la/vector_space.hpp"
#include "qp/qp_report.hpp"
#include "qp/qp_solver.hpp"

#include <functional>
#include <optional>
#include <string>

namespace feticon::qp
{
/// What produced an MPRGP iterate.
enum class MprgpStep
{
  start,        ///< the projected initial guess
  cg,           ///< conjugate gradient step inside the current face
  expansion,    ///< feasible half step + gradient projection with alpha_bar
  proportioning ///< step along the chopped gradient, releasing active components
};

/// Lower-case name of a step kind, for logs and monitors.
const char* to_string(MprgpStep step);

/// The state handed to MprgpOptions::monitor after every step (and for the start point).
struct MprgpIterate
{
  /// Steps taken so far (0 for the start point).
  int iteration = 0;
  /// The step that produced this iterate.
  MprgpStep step = MprgpStep::start;
  /// ||g_P||.
  double projected_gradient_norm = 0.0;
  /// ||phi||.
  double free_gradient_norm = 0.0;
  /// ||beta||.
  double chopped_gradient_norm = 0.0;
  /// f(x) = 1/2 x'Ax - b'x, evaluated as 1/2 x'(g - b) from the recursive gradient.
  double cost = 0.0;
};

/// How an expansion step (a CG step that would leave the feasible set) expands the active set
/// (Kruzik, Horak, Cermak, Pospisil, Pecha 2020, "Active set expansion strategies in MPRGP
/// algorithm"; PERMON's -qps_mpgp_expansion_type).
enum class MprgpExpansion
{
  /// Feasible half step to the first blocking bound, then the projected gradient step
  /// P(x - alpha_bar phi): ALGORITHMS.md section 5, the step of the rate-of-convergence theory.
  standard,
  /// The whole CG step projected, P(x - alpha_cg p): adds every bound the CG step crosses at
  /// once. Not monotone in general, so a step that increases f is replaced by the standard
  /// one from the same point (PERMON's fallback), which keeps f monotone.
  projected_cg
};

/// "std" or "projcg" (PERMON's names) to MprgpExpansion; throws feticon::Error for others.
MprgpExpansion expansion_from_name(const std::string& name);

/// Parameters of Mprgp, with the defaults of ALGORITHMS.md section 5.
struct MprgpOptions
{
  /// Default stopping test ||g_P|| <= rtol ||b||; absolute ||g_P|| <= rtol when b = 0.
  double rtol = 1e-5;
  /// Proportioning parameter Gamma > 0 of the test ||beta||^2 <= Gamma^2 phi~'phi.
  double gamma = 1.0;
  /// Steps allowed before the solve stops unconverged.
  int max_iterations = 10000;
  MprgpExpansion expansion = MprgpExpansion::standard;
  /// Expansion step length in (0, 2/||A||]; 0 means 1.8/nu with nu from estimate_norm().
  /// Halved whenever an expansion step increases f.
  double alpha_bar = 0.0;
  /// Power iterations for the ||A|| estimate when alpha_bar = 0.
  int power_iterations = 30;
  /// Recompute g = Ax - b every this many steps to remove drift of the recursive update.
  int gradient_refresh = 50;
  /// If set, replaces the default stopping test: the solve stops (converged) as soon as it
  /// returns true for the current x, recursive gradient g and ||g_P||. SMALBE-M uses it for
  /// its inner rule ||g_P|| <= min(M ||G mu||, eta).
  std::function<bool(const la::Vector& x, const la::Vector& g, double projected_gradient_norm)> stop{};
  /// If set, called for the start point and after every step.
  std::function<void(const MprgpIterate&)> monitor{};
  /// Optional preconditioner M ~ A^{-1} (symmetric positive definite), applied in the face:
  /// CG and restart directions are z = D_F M D_F phi with D_F the 0/1 mask of the free set
  /// (Dostal 2009, sec. 5.11; Kruzik & Horak 2025). The proportional test, the expansion's
  /// projected gradient step and proportioning stay unpreconditioned. Not owned.
  const la::LinearOperator* preconditioner = nullptr;
};

/// Box-constrained QP solver; see the file comment for the problem and the algorithm.
///
/// The object keeps alpha_bar between solves, so that repeated solves with the same A (the
/// inner solves of SMALBE-M) pay for the norm estimate once; the power iterations are
/// counted in the report of the solve that ran them. With log level `iterations` every step
/// is logged: iteration, step kind, ||g_P||, ||phi||, ||beta||, tolerance, cost.
class Mprgp : public QpSolver
{
public:
  /// @param[in] A        symmetric operator, positive definite on the iterates' span; it
  ///                     is referenced, not copied, and must outlive the Mprgp object.
  /// @param[in] options  parameters; checked here (FETICON_CHECK).
  Mprgp(const la::LinearOperator& A, MprgpOptions options);

  /// @brief Minimizes 1/2 x'Ax - b'x subject to x >= lower.
  /// @param[in]     b      right-hand side, finite, size A.size().
  /// @param[in]     lower  bounds l, size A.size(); -infinity for unbounded components,
  ///                       never NaN or +infinity.
  /// @param[in,out] x      on input the initial guess (finite, size A.size()), projected
  ///                       onto x >= l; on output the last iterate, always feasible.
  /// @return counters and state; converged = false with a reason on max_iterations, a
  ///         non-finite gradient norm or p'Ap <= 0 (A not positive definite).
  /// Throws feticon::Error for sizes or values that violate the above.
  QpReport solve(const la::Vector& b, const la::Vector& lower, la::Vector& x);

  /// @brief Minimizes 1/2 x'Ax - b'x subject to lower <= x <= upper.
  /// @param[in]     b      right-hand side, finite, size A.size().
  /// @param[in]     lower  bounds l, size A.size(); -infinity allowed, never NaN or +infinity.
  /// @param[in]     upper  bounds u, size A.size(); +infinity allowed, never NaN or
  ///                       -infinity; l_i <= u_i (l_i = u_i fixes x_i).
  /// @param[in,out] x      on input the initial guess (finite, size A.size()), projected
  ///                       onto the box; on output the last iterate, always feasible.
  /// @return as the lower-bound solve; with upper = +infinity everywhere the same report and
  ///         iterates, bitwise.
  /// Throws feticon::Error for sizes or values that violate the above, naming the component
  /// of an empty box (l_i > u_i).
  QpReport solve(const la::Vector& b, const la::Vector& lower, const la::Vector& upper, la::Vector& x);

  /// The QpSolver interface: the lower-bound solve when `set.upper` is empty, else the box
  /// solve; MPRGP takes no discs (throws feticon::Error if `set` has any).
  QpReport solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x, la::Vector* gradient) override;
  using QpSolver::solve;

  /// The current expansion step length (0 before the first solve when it is estimated).
  double alpha_bar() const override { return _alpha_bar; }

private:
  /// x, g = Ax - b, the direction p and the work vectors of one solve (mprgp.cpp).
  struct SolveState;

  /// Both solve overloads: `upper` null means no upper bound (u = +infinity, the arithmetic
  /// of the lower-bound algorithm); `gradient` as in QpSolver::solve.
  QpReport solve_box(const la::Vector& b, const la::Vector& lower, const la::Vector* upper, la::Vector& x,
                     la::Vector* gradient = nullptr);

  /// g = Ax - b recomputed: the initial gradient, and every gradient_refresh steps against the
  /// drift of the recursive update.
  void refresh_gradient(SolveState& s) const;
  /// The CG and restart direction: phi, preconditioned in the face when a preconditioner is set.
  void direction(SolveState& s, la::Vector& out) const;
  /// At a proportional x: the CG step along p, or the expansion step where the CG step would
  /// leave the feasible set; a reason if p'Ap <= 0.
  std::optional<std::string> cg_or_expansion_step(SolveState& s, double cost);
  /// x and g moved by alpha_cg along p (within the feasible set), and the next conjugate p.
  void cg_step(SolveState& s, double alpha_cg, double pq) const;
  /// The expansion of the active set by the chosen MprgpExpansion, then p restarted.
  void expansion_step(SolveState& s, double alpha_cg, double alpha_f, la::Index blocking, double cost);
  /// MprgpExpansion::projected_cg: x = P(x - alpha_cg p); false, x and g restored, if f grew.
  bool projected_cg_expansion(SolveState& s, double alpha_cg, double cost) const;
  /// MprgpExpansion::standard: the feasible half step, then the projected gradient step of
  /// length alpha_bar, which is halved if f grew.
  void standard_expansion(SolveState& s, double alpha_f, la::Index blocking, double cost);
  /// At a non-proportional x: the step along the chopped gradient beta, cut at the first
  /// bound it reaches; a reason if beta'A beta <= 0.
  std::optional<std::string> proportioning_step(SolveState& s) const;

  const la::LinearOperator& _A;
  MprgpOptions _options;
  double _alpha_bar;
};
} // namespace feticon::qp
