#include "qp/conjugate_gradient.hpp"

#include <memory>

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/timer.hpp"
#include "qp/ritz_estimate.hpp"
#include "qp/solve_stop.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace feticon::qp
{
namespace
{
using la::Vector;

void check_input(const la::LinearOperator& A, const Vector& b, const Vector& x, const CgOptions& options,
                 const la::LinearOperator* projector)
{
  const la::Index n = A.size();
  FETICON_CHECK(options.rtol >= 0.0, "conjugate_gradient: rtol = " << options.rtol << " must be >= 0");
  FETICON_CHECK(options.max_iterations >= 0,
                "conjugate_gradient: max_iterations = " << options.max_iterations << " must be >= 0");
  FETICON_CHECK(b.size() == n, "conjugate_gradient: b has size " << b.size() << " but the operator has size " << n);
  FETICON_CHECK(x.size() == n,
                "conjugate_gradient: the initial guess has size " << x.size() << " but the operator has size " << n);
  FETICON_CHECK(projector == nullptr || projector->size() == n,
                "conjugate_gradient: the projector has size " << projector->size() << " but the operator has size "
                                                              << n);
  FETICON_CHECK(b.allFinite(), "conjugate_gradient: b has a NaN or infinite entry");
  FETICON_CHECK(x.allFinite(),
                "conjugate_gradient: the initial guess has a NaN or infinite "
                "entry");
}
} // namespace

QpReport conjugate_gradient(const la::LinearOperator& A, const Vector& b, Vector& x, const CgOptions& options,
                            const la::LinearOperator* projector)
{
  const auto start_time = std::chrono::steady_clock::now();
  check_input(A, b, x, options, projector);
  auto project = [projector](const Vector& v, Vector& projected) {
    if (projector)
      projector->apply(v, projected);
    else
      projected = v;
  };

  std::unique_ptr<la::SerialSpace> serial;
  const la::VectorSpace& space = A.space() ? *A.space() : *(serial = std::make_unique<la::SerialSpace>(A.size()));
  QpReport report;
  RitzEstimate ritz; // the run is Lanczos on P M P A: its extreme eigenvalues for free
  // s = b - Ax is kept unprojected so that the cost is exact even for x outside Im P.
  Vector s = b;
  if (space.max(x.size() > 0 ? x.cwiseAbs().maxCoeff() : 0.0) != 0.0)
  {
    Vector ax;
    A.apply(x, ax);
    s -= ax;
    ++report.hessian_multiplications;
  }
  Vector r, q;
  project(b, r);
  const double pb_norm = la::norm(space, r);
  const double tolerance = options.rtol * (pb_norm > 0.0 ? pb_norm : 1.0);
  project(s, r);
  double rr = la::dot(space, r, r);
  // Preconditioned direction z = P M P r (P M P is symmetric on Im P); z = r without M.
  Vector z, mz;
  auto precondition = [&](const Vector& residual, Vector& out) {
    if (!options.preconditioner)
    {
      out = residual;
      return;
    }
    options.preconditioner->apply(residual, mz);
    project(mz, out);
  };
  precondition(r, z);
  double rz = la::dot(space, r, z);
  Vector p = z;

  auto finish = [&](bool converged, std::string reason) {
    report.converged = converged;
    report.reason = std::move(reason);
    report.cg_steps = report.iterations;
    report.ritz = ritz.longest_run();
    report.projected_gradient_norm = std::sqrt(rr);
    report.cost = -0.5 * la::reduce_sum<1>(space, [&](la::Index i, double* sum) { sum[0] += x[i] * (s[i] + b[i]); })[0];
    report.seconds = seconds_since(start_time);
    return report;
  };

  for (;;)
  {
    const double r_norm = std::sqrt(rr);
    if (options.monitor)
      options.monitor(report.iterations, r_norm);
    if (log::enabled(log::Level::iterations))
    {
      char line[96];
      std::snprintf(line, sizeof line, "cg %6d |P r| %.3e tol %.3e", report.iterations, r_norm, tolerance);
      log::iteration(line);
    }
    if (!std::isfinite(r_norm))
      return finish(false,
                    "residual norm is not finite (" + format_number(r_norm) + ") at iteration " +
                        std::to_string(report.iterations));
    if (r_norm <= tolerance)
      return finish(true,
                    "|P r| = " + format_number(r_norm) +
                        " <= " + (pb_norm > 0.0 ? "rtol |P b| = " : "rtol (P b = 0) = ") + format_number(tolerance));
    if (report.iterations >= options.max_iterations)
      return finish(false,
                    "maximum number of iterations (" + std::to_string(options.max_iterations) +
                        ") reached, |P r| = " + format_number(r_norm));

    A.apply(p, q);
    ++report.hessian_multiplications;
    const double pq = la::dot(space, p, q);
    if (!(pq > 0.0))
      return finish(false,
                    "operator is not positive definite on the search direction: "
                    "p'Ap = " +
                        format_number(pq) + " <= 0 at iteration " + std::to_string(report.iterations));
    const double alpha = rz / pq;
    x += alpha * p;
    s -= alpha * q;
    project(s, r);
    rr = la::dot(space, r, r);
    precondition(r, z);
    const double rz_new = la::dot(space, r, z);
    ritz.cg_step(alpha, rz_new / rz);
    p = z + (rz_new / rz) * p;
    rz = rz_new;
    ++report.iterations;
  }
}
} // namespace feticon::qp
