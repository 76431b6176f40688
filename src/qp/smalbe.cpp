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
/// one inside FETI's PFP; Smalbe stays FETI-agnostic, and the Hertz dual solve took the same
/// time before and after SMALBE-M formed H itself (0.14-0.15 s for 463 products).
class PlusCoarseTerm : public la::LinearOperator
{
public:
  PlusCoarseTerm(const la::LinearOperator& B, const EqualityOperator& C, double factor)
      : factor(factor), _B(B), _C(C)
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
} // namespace

Smalbe::Smalbe(const la::LinearOperator& A, const EqualityOperator& C, SmalbeOptions options,
               const la::LinearOperator* preconditioner)
    : _A(A), _C(C), _options(std::move(options)), _preconditioner(preconditioner)
{
  FETICON_CHECK(_options.rho > 0 && _options.M0 > 0 && _options.beta > 1 && _options.rtol > 0,
                "SMALBE-M: need rho > 0, M0 > 0, beta > 1, rtol > 0");
  FETICON_CHECK(_options.rho_growth >= 1 && _options.rho_limit >= 1 &&
                    _options.feasibility_reduction > 0 && _options.feasibility_reduction < 1 &&
                    _options.feasibility_window >= 1,
                "SMALBE-M: need rho_growth >= 1, rho_limit >= 1, feasibility_reduction in (0, 1), "
                "feasibility_window >= 1");
}

SmalbeReport Smalbe::solve(const la::Vector& b, const la::Vector& lower, la::Vector& x,
                           const SmalbeStart* start)
{
  const auto solve_start = std::chrono::steady_clock::now();
  std::unique_ptr<la::SerialSpace> serial;
  const la::VectorSpace& space = _A.space() ? *_A.space() : *(serial = std::make_unique<la::SerialSpace>(b.size()));
  // ||C x|| is a norm of a replicated coarse vector (no reduction); ||b|| and x'Hx are
  // reduced over the space.
  const double b_raw_norm = la::norm(space, b);
  const double b_norm = b_raw_norm > 0 ? b_raw_norm : 1.0;
  const double tolerance = _options.rtol * b_norm;
  const double eta = _options.eta_factor * b_norm;
  la::Vector omega = _C.apply(la::Vector::Zero(b.size()));
  omega.setZero();
  double M = _options.M0;
  double rho = _options.rho;
  const double rho_max = _options.rho * _options.rho_limit;
  if (start)
  {
    FETICON_CHECK(start->omega.size() == omega.size() && start->M > 0 && start->rho >= _options.rho,
                  "SMALBE-M start: need omega of the size of Cx, M > 0, rho >= the initial rho");
    omega = start->omega;
    M = start->M;
    rho = std::min(start->rho, rho_max);
  }
  double previous_L = 0;
  // Stall test of the feasibility: reference value and the outer iteration it was taken at.
  double reference_feasibility = std::numeric_limits<double>::infinity();
  int reference_iteration = 0;
  SmalbeReport report;
  bool final_test = false;

  auto feasible = [&](const la::Vector& Cx)
  {
    return Cx.norm() <= tolerance &&
           (!_options.equality_error || _options.equality_error(Cx) <= _options.equality_tolerance);
  };
  MprgpOptions inner = _options.mprgp;
  inner.stop = [&](const la::Vector& xk, const la::Vector&, double gp)
  {
    const la::Vector Cx = _C.apply(xk);
    const double cx = Cx.norm();
    final_test = gp <= tolerance && feasible(Cx);
    return final_test || gp <= std::min(M * cx, eta);
  };
  PlusCoarseTerm H(_A, _C, rho);
  std::optional<PlusCoarseTerm> preconditioner;
  if (_preconditioner)
  {
    // With the initial rho, also after rho is raised: the exact inverse on Im C' for the
    // current rho (C'C / rho) was measured to cost more steps than keeping C'C / rho_0
    // (sphere on block, large displacements, rho raised to 10: 420 against 342 MPRGP steps;
    // cantilever_obstacle, rho raised to ~3 000: 472 against 443).
    preconditioner.emplace(*_preconditioner, _C, 1.0 / _options.rho);
    inner.preconditioner = &*preconditioner;
  }
  auto last_progress = std::chrono::steady_clock::now();
  // ||A + rho' C'C|| <= ||A + rho C'C|| + (rho' - rho) since ||C'C|| = 1: the step length
  // bound for a raised rho from the one for the current (its norm estimate 1.8/alpha_bar
  // grows by the difference).
  auto raised_alpha_bar = [](double alpha_bar, double delta)
  { return alpha_bar / (1.0 + alpha_bar * delta / 1.8); };
  if (rho > _options.rho && inner.alpha_bar > 0)
    inner.alpha_bar = raised_alpha_bar(inner.alpha_bar, rho - _options.rho);
  auto mprgp = std::make_unique<Mprgp>(H, inner);
  for (int k = 0; k < _options.max_outer_iterations; ++k)
  {
    const int remaining = _options.max_inner_iterations - report.iterations;
    if (remaining <= 0)
    {
      report.reason = "SMALBE-M: inner iteration limit reached";
      break;
    }
    final_test = false;
    const QpReport r = mprgp->solve(b - _C.apply_transpose(omega), lower, x);
    report += r; // counters; the seconds are the whole solve's, set at the end
    report.projected_gradient_norm = r.projected_gradient_norm;
    report.outer_iterations = k + 1;
    const la::Vector Cx = _C.apply(x);
    const double feasibility = Cx.norm();
    report.equality_residual = feasibility / b_norm;
    if (!r.converged)
    {
      report.reason = "SMALBE-M inner MPRGP: " + r.reason;
      break;
    }
    std::ostringstream line;
    line << "    SMALBE-M outer " << k + 1 << ": MPRGP steps " << r.iterations << ", ||g_P||/||b|| "
         << r.projected_gradient_norm / b_norm << ", ||Cx||/||b|| " << report.equality_residual
         << ", M " << M << ", rho " << rho;
    // Long solves (a minute per QP at 1M DOFs) also report at the summary level, at most
    // every 10 s, so that a user sees progress between the outer-iteration lines.
    if (log::enabled(log::Level::iterations))
      log::iteration(line.str());
    else if (seconds_since(last_progress) >= 10)
    {
      log::info(line.str() + " (total MPRGP steps " + std::to_string(report.iterations) + ")");
      last_progress = std::chrono::steady_clock::now();
    }
    // r.cost is L(x, omega) = 1/2 x'(A + rho C'C)x - b'x + omega'Cx for the multiplier and
    // penalty of this solve.
    const double L = r.cost;
    if (_options.monitor)
      _options.monitor({k, &x, &omega, M, rho, L});
    if (r.projected_gradient_norm <= tolerance && feasible(Cx))
    {
      report.converged = true;
      report.reason = _options.equality_error ? "||g_P||, ||Cx|| <= rtol ||b|| and the equality error <= its tolerance"
                                              : "||g_P|| and ||Cx|| <= rtol ||b||";
      break;
    }
    omega += rho * Cx;
    if (k > 0 && L < previous_L + 0.5 * rho * Cx.squaredNorm())
      M /= _options.beta;
    previous_L = L;

    // Feasibility stall: raise rho (Dostal's SMALBE update; Bertsekas' penalty rule with a
    // window, since inexact inner solves make single outer steps noisy).
    if (feasibility <= _options.feasibility_reduction * reference_feasibility)
    {
      reference_feasibility = feasibility;
      reference_iteration = k;
    }
    else if (k - reference_iteration >= _options.feasibility_window && rho < rho_max &&
             _options.rho_growth > 1)
    {
      // Observed contraction per outer iteration q ~ 1 - rho s/(h + rho s) (see smalbe.hpp);
      // rho q/(1 - q) would make it 1/2. Grow by at least rho_growth, at most rho_growth^3.
      const double q = std::pow(feasibility / reference_feasibility,
                                1.0 / (k - reference_iteration));
      const double wanted = q < 1 ? q / (1 - q) : std::numeric_limits<double>::infinity();
      const double growth = std::clamp(wanted, _options.rho_growth,
                                       std::pow(_options.rho_growth, 3));
      const double new_rho = std::min(rho * growth, rho_max);
      // From the alpha_bar in use (smaller if MPRGP has halved it); MPRGP still halves
      // alpha_bar whenever an expansion step increases the cost.
      MprgpOptions raised = inner;
      raised.alpha_bar = raised_alpha_bar(mprgp->alpha_bar(), new_rho - rho);
      log::iteration("    SMALBE-M: ||Cx|| stalled at " + std::to_string(feasibility / b_norm) +
                     " ||b|| for " + std::to_string(k - reference_iteration) +
                     " outer iterations: rho " + std::to_string(rho) + " -> " +
                     std::to_string(new_rho));
      rho = new_rho;
      H.factor = rho;
      mprgp = std::make_unique<Mprgp>(H, raised);
      ++report.rho_updates;
      reference_feasibility = feasibility;
      reference_iteration = k;
    }
  }
  if (!report.converged && report.reason.empty())
    report.reason = "SMALBE-M: outer iteration limit reached";
  la::Vector Hx;
  H.factor = _options.rho; // the cost is reported for the initial augmentation, as before a raise
  H.apply(x, Hx);
  report.hessian_multiplications += 1;
  const auto [xHx, bx] = la::reduce_sum<2>(space, [&](la::Index i, double* sum)
                                          { sum[0] += x[i] * Hx[i]; sum[1] += b[i] * x[i]; });
  report.cost = 0.5 * xHx - bx;
  report.final_M = M;
  report.final_rho = rho;
  report.omega = omega;
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - solve_start).count();
  return report;
}
} // namespace feticon::qp
