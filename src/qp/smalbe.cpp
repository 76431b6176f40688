#include "qp/smalbe.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/timer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

namespace feticon::qp
{
namespace
{
/// x -> B x + factor C'C x: the augmented Hessian H = A + rho C'C (factor rho), and its
/// preconditioner M_A + C'C / rho_0 (factor 1/rho_0: H^{-1} on Im C' exactly while rho = rho_0,
/// since A C' ~ 0 for FETI's PFP). C'C x is a second coarse projection per product beside the
/// one inside FETI's PFP; Smalbe stays FETI-agnostic at no measurable cost
/// (docs/measurements.md).
class PlusCoarseTerm : public la::LinearOperator
{
public:
  PlusCoarseTerm(const la::LinearOperator& B, const EqualityOperator& C, double factor) : factor(factor), _B(B), _C(C)
  {
  }
  la::Index size() const override { return _B.size(); }
  const la::VectorSpace* space() const override { return _B.space(); }
  void apply(const la::Vector& x, la::Vector& y) const override
  {
    _B.apply(x, y);
    y += factor * _C.apply_transpose(_C.apply(x));
  }
  double factor;

private:
  const la::LinearOperator& _B;
  const EqualityOperator& _C;
};

/// ||A + rho' C'C|| <= ||A + rho C'C|| + (rho' - rho) since ||C'C|| = 1: the step length
/// bound for a raised rho from the one for the current (its norm estimate 1.8/alpha_bar
/// grows by the difference).
double raised_alpha_bar(double alpha_bar, double delta) { return alpha_bar / (1.0 + alpha_bar * delta / 1.8); }
} // namespace

Smalbe::Smalbe(const la::LinearOperator& A, const EqualityOperator& C, SmalbeOptions options,
               const la::LinearOperator* preconditioner)
    : _A(A), _C(C), _options(std::move(options)), _preconditioner(preconditioner)
{
  FETICON_CHECK(_options.rho > 0 && _options.M0 > 0 && _options.beta > 1 && _options.rtol > 0,
                "SMALBE-M: need rho > 0, M0 > 0, beta > 1, rtol > 0");
  FETICON_CHECK(_options.rho_growth >= 1 && _options.rho_limit >= 1 && _options.feasibility_reduction > 0 &&
                    _options.feasibility_reduction < 1 && _options.feasibility_window >= 1,
                "SMALBE-M: need rho_growth >= 1, rho_limit >= 1, feasibility_reduction in (0, 1), "
                "feasibility_window >= 1");
}

/// The outer loop's state (ALGORITHMS.md section 1): the multiplier omega, M and rho with the
/// augmented Hessian H and the inner solver for it, and the reference of the stall test.
struct Smalbe::SolveState
{
  SolveState(const la::LinearOperator& A, const EqualityOperator& C) : H(A, C, 0.0) {} // H.factor: make_inner_solver

  double b_norm = 0;
  double tolerance = 0;
  double eta = 0;
  la::Vector omega;
  double M = 0;
  double rho = 0;
  double rho_max = 0;
  double previous_L = 0;
  // Stall test of the feasibility: reference value and the outer iteration it was taken at.
  double reference_feasibility = std::numeric_limits<double>::infinity();
  int reference_iteration = 0;
  SmalbeReport report;
  bool final_test = false;
  MprgpOptions inner;
  PlusCoarseTerm H;
  std::optional<PlusCoarseTerm> preconditioner;
  std::unique_ptr<QpSolver> inner_solver;
  std::chrono::steady_clock::time_point last_progress;
};

SmalbeReport Smalbe::solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x, const QpState* start)
{
  const auto solve_start = std::chrono::steady_clock::now();
  std::unique_ptr<la::SerialSpace> serial;
  const la::VectorSpace& space = _A.space() ? *_A.space() : *(serial = std::make_unique<la::SerialSpace>(b.size()));
  SolveState s(_A, _C);
  set_initial_state(s, space, b, start);
  make_inner_solver(s);
  SmalbeReport& report = s.report;
  // g = H x - rhs at x, carried from one inner solve to the next: an update of omega changes
  // rhs by -C' (omega - omega_old) and leaves x, so g follows without a product with H. It is
  // recomputed after a rho update (H changed) and once the steps on the carried gradient
  // reach MPRGP's own refresh period (the recursive update's drift).
  la::Vector g;
  int carried_steps = 0;
  for (int k = 0; k < _options.max_outer_iterations; ++k)
  {
    const int remaining = _options.max_inner_iterations - report.iterations;
    if (remaining <= 0)
    {
      report.reason = "SMALBE-M: inner iteration limit reached";
      break;
    }
    s.final_test = false;
    const la::Vector rhs = b - _C.apply_transpose(s.omega);
    const QpReport r = s.inner_solver->solve(rhs, set, x, &g);
    carried_steps = r.iterations >= s.inner.gradient_refresh ? r.iterations % s.inner.gradient_refresh
                                                             : carried_steps + r.iterations;
    report += r; // counters; the seconds are the whole solve's, set at the end
    report.projected_gradient_norm = r.projected_gradient_norm;
    report.outer_iterations = k + 1;
    const la::Vector Cx = _C.apply(x);
    const double feasibility = Cx.norm();
    report.equality_residual = feasibility / s.b_norm;
    if (!r.converged)
    {
      report.reason = "SMALBE-M inner solve: " + r.reason;
      break;
    }
    log_outer_iteration(s, k, r);
    // r.cost is L(x, omega) = 1/2 x'(A + rho C'C)x - b'x + omega'Cx for the multiplier and
    // penalty of this solve.
    const double L = r.cost;
    if (_options.monitor)
      _options.monitor({k, &x, &s.omega, s.M, s.rho, L});
    if (r.projected_gradient_norm <= s.tolerance &&
        (feasible(s, Cx) ||
         (_options.feasibility_correction && correct_feasibility_on_face(s, space, rhs, set, Cx, x))))
    {
      report.converged = true;
      report.reason = _options.equality_error ? "||g_P||, ||Cx|| <= rtol ||b|| and the equality error <= its tolerance"
                                              : "||g_P|| and ||Cx|| <= rtol ||b||";
      break;
    }
    s.omega += s.rho * Cx;
    if (g.size() == x.size() && carried_steps < s.inner.gradient_refresh)
      g += _C.apply_transpose(s.rho * Cx);
    else
    {
      g.resize(0);
      carried_steps = 0;
    }
    if (k > 0 && L < s.previous_L + 0.5 * s.rho * Cx.squaredNorm())
      s.M /= _options.beta;
    s.previous_L = L;
    const double rho = s.rho;
    raise_rho_if_stalled(s, k, feasibility);
    if (s.rho != rho)
    {
      g.resize(0);
      carried_steps = 0;
    }
  }
  if (!report.converged && report.reason.empty())
    report.reason = "SMALBE-M: outer iteration limit reached";
  report.cost = cost_at_initial_rho(s, space, b, x);
  report.final_M = s.M;
  report.final_rho = s.rho;
  report.omega = s.omega;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - solve_start).count();
  return report;
}

void Smalbe::set_initial_state(SolveState& s, const la::VectorSpace& space, const la::Vector& b,
                               const QpState* start) const
{
  // ||C x|| is a norm of a replicated coarse vector (no reduction); ||b|| and x'Hx are
  // reduced over the space.
  const double b_raw_norm = la::norm(space, b);
  s.b_norm = b_raw_norm > 0 ? b_raw_norm : 1.0;
  s.tolerance = std::max(_options.rtol * s.b_norm, _options.absolute_tolerance);
  s.eta = _options.eta_factor * s.b_norm;
  s.omega = _C.apply(la::Vector::Zero(b.size()));
  s.omega.setZero();
  s.M = _options.M0;
  s.rho = _options.rho;
  s.rho_max = _options.rho * _options.rho_limit;
  if (start)
  {
    FETICON_CHECK((start->omega.size() == 0 || start->omega.size() == s.omega.size()) && start->M >= 0,
                  "SMALBE-M start: need omega of the size of Cx (or none) and M >= 0");
    if (start->omega.size() > 0)
      s.omega = start->omega;
    if (start->M > 0)
      s.M = start->M;
    s.rho = std::min(std::max(start->rho, _options.rho), s.rho_max);
  }
}

std::unique_ptr<QpSolver> Smalbe::new_inner_solver(const la::LinearOperator& H, const MprgpOptions& options) const
{
  if (_options.inner_solver)
    return _options.inner_solver(H, options);
  return std::make_unique<Mprgp>(H, options);
}

bool Smalbe::feasible(const SolveState& s, const la::Vector& Cx) const
{
  return Cx.norm() <= s.tolerance &&
      (!_options.equality_error || _options.equality_error(Cx) <= _options.equality_tolerance);
}

void Smalbe::make_inner_solver(SolveState& s) const
{
  s.inner = _options.mprgp;
  s.inner.stop = [this, &s](const la::Vector& xk, const la::Vector&, double gp) {
    const la::Vector Cx = _C.apply(xk);
    const double cx = Cx.norm();
    s.final_test = gp <= s.tolerance && feasible(s, Cx);
    return s.final_test || gp <= std::min(s.M * cx, s.eta);
  };
  s.H.factor = s.rho;
  if (_preconditioner)
  {
    // With the initial rho, also after rho is raised: the exact inverse on Im C' for the
    // current rho (C'C / rho) was measured to cost more steps than keeping C'C / rho_0
    // (sphere on block, large displacements, rho raised to 10: 420 against 342 MPRGP steps;
    // cantilever_obstacle, rho raised to ~3 000: 472 against 443).
    s.preconditioner.emplace(*_preconditioner, _C, 1.0 / _options.rho);
    s.inner.preconditioner = &*s.preconditioner;
  }
  s.last_progress = std::chrono::steady_clock::now();
  if (s.rho > _options.rho && s.inner.alpha_bar > 0)
    s.inner.alpha_bar = raised_alpha_bar(s.inner.alpha_bar, s.rho - _options.rho);
  s.inner_solver = new_inner_solver(s.H, s.inner);
}

void Smalbe::log_outer_iteration(SolveState& s, int k, const QpReport& r) const
{
  std::ostringstream line;
  line << "    SMALBE-M outer " << k + 1 << ": MPRGP steps " << r.iterations << ", ||g_P||/||b|| "
       << r.projected_gradient_norm / s.b_norm << ", ||Cx||/||b|| " << s.report.equality_residual << ", M " << s.M
       << ", rho " << s.rho;
  // Long solves (a minute per QP at 1M DOFs) also report at the summary level, at most
  // every 10 s, so that a user sees progress between the outer-iteration lines.
  if (log::enabled(log::Level::iterations))
    log::iteration(line.str());
  else if (seconds_since(s.last_progress) >= 10)
  {
    log::info(line.str() + " (total MPRGP steps " + std::to_string(s.report.iterations) + ")");
    s.last_progress = std::chrono::steady_clock::now();
  }
}

void Smalbe::raise_rho_if_stalled(SolveState& s, int k, double feasibility) const
{
  // Feasibility stall: raise rho (Dostal's SMALBE update; Bertsekas' penalty rule with a
  // window, since inexact inner solves make single outer steps noisy).
  if (feasibility <= _options.feasibility_reduction * s.reference_feasibility)
  {
    s.reference_feasibility = feasibility;
    s.reference_iteration = k;
  }
  else if (k - s.reference_iteration >= _options.feasibility_window && s.rho < s.rho_max && _options.rho_growth > 1)
  {
    // Observed contraction per outer iteration q ~ 1 - rho s/(h + rho s) (see smalbe.hpp);
    // rho q/(1 - q) would make it 1/2. Grow by at least rho_growth, at most rho_growth_max.
    const double q = std::pow(feasibility / s.reference_feasibility, 1.0 / (k - s.reference_iteration));
    const double wanted = q < 1 ? q / (1 - q) : std::numeric_limits<double>::infinity();
    const double growth =
        std::clamp(wanted, _options.rho_growth, std::max(_options.rho_growth, _options.rho_growth_max));
    const double new_rho = std::min(s.rho * growth, s.rho_max);
    // From the alpha_bar in use (smaller if MPRGP has halved it); MPRGP still halves
    // alpha_bar whenever an expansion step increases the cost.
    MprgpOptions raised = s.inner;
    raised.alpha_bar = raised_alpha_bar(s.inner_solver->alpha_bar(), new_rho - s.rho);
    log::iteration("    SMALBE-M: ||Cx|| stalled at " + std::to_string(feasibility / s.b_norm) + " ||b|| for " +
                   std::to_string(k - s.reference_iteration) + " outer iterations: rho " + std::to_string(s.rho) +
                   " -> " + std::to_string(new_rho));
    s.rho = new_rho;
    s.H.factor = s.rho;
    s.inner_solver = new_inner_solver(s.H, raised);
    ++s.report.rho_updates;
    s.reference_feasibility = feasibility;
    s.reference_iteration = k;
  }
}

bool Smalbe::correct_feasibility_on_face(SolveState& s, const la::VectorSpace& space, const la::Vector& rhs,
                                         const SeparableConstraints& set, const la::Vector& Cx, la::Vector& x) const
{
  // (C D C') y = C x by CG on the coarse vector (replicated: every rank takes the same steps),
  // D the orthogonal projector onto the face of x. C D C' = I - C (I - D) C' has its spectrum
  // in [sigma_min(C_F)^2, 1]; a face that nearly loses the rank of C converges slowly, and the
  // step limit then leaves the correction to SMALBE-M's updates.
  // The set functions below read u; SMALBE-M's callers may leave it empty (no upper bounds).
  SeparableConstraints bounded;
  const SeparableConstraints& region = set.upper.size() == x.size()
      ? set
      : (bounded = {set.lower, la::Vector::Constant(x.size(), std::numeric_limits<double>::infinity()), set.discs});
  const auto face_operator = [&](const la::Vector& y) {
    la::Vector v = _C.apply_transpose(y);
    project_onto_face(region, x, v);
    return _C.apply(v);
  };
  la::Vector y = la::Vector::Zero(Cx.size());
  la::Vector r = Cx;
  la::Vector p = r;
  double rr = r.squaredNorm();
  const double target = 1e-8 * rr;
  for (int k = 0; k < 100 && rr > target; ++k)
  {
    const la::Vector q = face_operator(p);
    const double pq = p.dot(q);
    if (!(pq > 0)) // C D C' is semidefinite: a direction in its kernel ends the iteration
      break;
    const double alpha = rr / pq;
    y += alpha * p;
    r -= alpha * q;
    const double rr_next = r.squaredNorm();
    p = r + (rr_next / rr) * p;
    rr = rr_next;
  }
  la::Vector delta = _C.apply_transpose(y);
  project_onto_face(region, x, delta);
  // The free components stay off their bounds, or the correction is not taken.
  la::Index blocking = -1;
  const double bound_step = -space.max(-max_bound_step(region, x, delta, blocking));
  const double disc_step = -space.max(-max_disc_step(region, x, delta, false, blocking));
  if (std::min(bound_step, disc_step) < 1)
    return false;
  la::Vector corrected = x - delta;
  project(region, corrected); // back onto active circles, which a tangential step leaves at second order
  la::Vector g;
  s.H.apply(corrected, g);
  s.report.hessian_multiplications += 1;
  // With the multiplier update omega + rho Cx taken with it, the penalty's response rho C'C delta
  // = rho C'Cx cancels in the gradient, which changes by A delta only.
  g -= rhs - s.rho * _C.apply_transpose(Cx);
  la::Vector phi, beta;
  free_gradient(region, corrected, g, phi);
  chopped_gradient(region, corrected, g, beta);
  const double gp = la::norm(space, phi + beta);
  const la::Vector C_corrected = _C.apply(corrected);
  const bool accepted = gp <= s.tolerance && feasible(s, C_corrected);
  std::ostringstream line;
  line << "    SMALBE-M feasibility correction on the face: ||Cx||/||b|| " << Cx.norm() / s.b_norm << " -> "
       << C_corrected.norm() / s.b_norm << ", ||g_P||/||b|| " << gp / s.b_norm
       << (accepted ? ": converged" : ": not taken");
  log::iteration(line.str());
  if (!accepted)
    return false;
  x = std::move(corrected);
  s.omega += s.rho * Cx;
  s.report.projected_gradient_norm = gp;
  s.report.equality_residual = C_corrected.norm() / s.b_norm;
  ++s.report.feasibility_corrections;
  return true;
}

double Smalbe::cost_at_initial_rho(SolveState& s, const la::VectorSpace& space, const la::Vector& b,
                                   const la::Vector& x) const
{
  la::Vector Hx;
  s.H.factor = _options.rho; // the cost is reported for the initial augmentation, as before a raise
  s.H.apply(x, Hx);
  s.report.hessian_multiplications += 1;
  const auto [xHx, bx] = la::reduce_sum<2>(space, [&](la::Index i, double* sum) {
    sum[0] += x[i] * Hx[i];
    sum[1] += b[i] * x[i];
  });
  return 0.5 * xHx - bx;
}
} // namespace feticon::qp
