#include "qp/smalbe.hpp"

#include "common/error.hpp"
#include "common/log.hpp"

#include <chrono>
#include <sstream>

namespace feticon::qp
{
Smalbe::Smalbe(const la::LinearOperator& H, const EqualityOperator& C, SmalbeOptions options)
    : _H(H), _C(C), _options(std::move(options))
{
  FETICON_CHECK(_options.rho > 0 && _options.M0 > 0 && _options.beta > 1 && _options.rtol > 0,
                "SMALBE-M: need rho > 0, M0 > 0, beta > 1, rtol > 0");
}

SmalbeReport Smalbe::solve(const la::Vector& b, const la::Vector& lower, la::Vector& x)
{
  const auto start = std::chrono::steady_clock::now();
  const double b_norm = b.norm() > 0 ? b.norm() : 1.0;
  const double tolerance = _options.rtol * b_norm;
  const double eta = _options.eta_factor * b_norm;
  la::Vector omega = _C.apply(la::Vector::Zero(b.size()));
  omega.setZero();
  double M = _options.M0;
  double previous_L = 0;
  SmalbeReport report;
  bool final_test = false;

  MprgpOptions inner = _options.mprgp;
  inner.stop = [&](const la::Vector& xk, const la::Vector&, double gp)
  {
    const double cx = _C.apply(xk).norm();
    final_test = gp <= tolerance && cx <= tolerance;
    return final_test || gp <= std::min(M * cx, eta);
  };
  Mprgp mprgp(_H, inner);
  for (int k = 0; k < _options.max_outer_iterations; ++k)
  {
    const int remaining = _options.max_inner_iterations - report.iterations;
    if (remaining <= 0)
    {
      report.reason = "SMALBE-M: inner iteration limit reached";
      break;
    }
    final_test = false;
    const QpReport r = mprgp.solve(b - _C.apply_transpose(omega), lower, x);
    report.iterations += r.iterations;
    report.cg_steps += r.cg_steps;
    report.expansion_steps += r.expansion_steps;
    report.proportioning_steps += r.proportioning_steps;
    report.hessian_multiplications += r.hessian_multiplications;
    report.projected_gradient_norm = r.projected_gradient_norm;
    report.outer_iterations = k + 1;
    const la::Vector Cx = _C.apply(x);
    report.equality_residual = Cx.norm() / b_norm;
    if (!r.converged)
    {
      report.reason = "SMALBE-M inner MPRGP: " + r.reason;
      break;
    }
    std::ostringstream line;
    line << "    SMALBE-M outer " << k + 1 << ": MPRGP steps " << r.iterations << ", ||g_P||/||b|| "
         << r.projected_gradient_norm / b_norm << ", ||Cx||/||b|| " << report.equality_residual
         << ", M " << M;
    log::iteration(line.str());
    // r.cost is L(x, omega) = 1/2 x'Hx - b'x + omega'Cx for the multiplier of this solve.
    const double L = r.cost;
    if (r.projected_gradient_norm <= tolerance && Cx.norm() <= tolerance)
    {
      report.converged = true;
      report.reason = "||g_P|| and ||Cx|| <= rtol ||b||";
      break;
    }
    omega += _options.rho * Cx;
    if (k > 0 && L < previous_L + 0.5 * _options.rho * Cx.squaredNorm())
      M /= _options.beta;
    previous_L = L;
  }
  if (!report.converged && report.reason.empty())
    report.reason = "SMALBE-M: outer iteration limit reached";
  la::Vector Hx;
  _H.apply(x, Hx);
  report.hessian_multiplications += 1;
  report.cost = 0.5 * x.dot(Hx) - b.dot(x);
  report.final_M = M;
  report.omega = omega;
  report.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}
} // namespace feticon::qp
