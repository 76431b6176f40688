#include "dual/dual_penalty_problem.hpp"

#include "common/error.hpp"
#include "dual/constraint_scaling.hpp"
#include "dual/primal_recovery.hpp"
#include "dual/projector.hpp"
#include "qp/conjugate_gradient.hpp"
#include "qp/norm_estimate.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>
#include <optional>

namespace feticon::dual
{
namespace
{
/// G~ = L^{-1} G as the equality operator of SMALBE-M.
class GTildeOperator : public qp::EqualityOperator
{
public:
  explicit GTildeOperator(const CoarseProjector& projector) : _projector(projector) {}
  la::Vector apply(const la::Vector& x) const override { return _projector.apply_G_tilde(x); }
  la::Vector apply_transpose(const la::Vector& y) const override { return _projector.apply_G_tilde_t(y); }

private:
  const CoarseProjector& _projector;
};
/// M = s P Y X Y P [+ Q / rho], X = B K B' (lumped) or B S B' (Dirichlet), Y = (B B')^{-1}:
/// the FETI preconditioner on Im P (scaled like F^ = F / s) and, with `rho` > 0, the exact
/// inverse of H = ... + rho Q on Im Q (SMALBE-M adds that term itself, for its current rho).
class DualPreconditionerOperator : public la::LinearOperator
{
public:
  DualPreconditionerOperator(const FetiOperators& feti, const CoarseProjector& projector,
                             const DualPenaltyOptions& options, double s, int64_t n_equality, double rho)
      : _feti(feti), _projector(projector), _options(options), _s(s), _rho(rho)
  {
    if (options.constraint_scaling)
      _scaling.emplace(feti, n_equality);
    FETICON_CHECK(options.preconditioner != DualPreconditioner::dirichlet || options.schur,
                  "the Dirichlet preconditioner needs the subdomain Schur complements");
  }
  la::Index size() const override { return _feti.n_dual(); }
  const la::VectorSpace* space() const override { return &_feti.space(); }
  void apply(const la::Vector& x, la::Vector& y) const override
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

private:
  la::Vector scale(const la::Vector& x) const { return _scaling ? _scaling->apply(x) : x; }

  const FetiOperators& _feti;
  const CoarseProjector& _projector;
  const DualPenaltyOptions& _options;
  double _s, _rho;
  std::optional<ConstraintScaling> _scaling;
};

/// Particular solution of G lambda = e (ALGORITHMS.md 1): variant B, lambda~ = [lambda~_E; 0]
/// from the equality rows alone, when they fix every rigid mode; then the contact bounds
/// are simply lambda_I >= 0 and mu = 0 is feasible. Otherwise (a body held only by
/// contact, like the Hertz cylinder) variant A, the minimal-norm G'(GG')^{-1} e.
la::Vector particular_solution(const FetiOperators& feti, const CoarseProjector& projector, const la::Vector& e,
                               int64_t n_equality)
{
  // Either variant must satisfy G lambda~ = e. The pivot test of G_E G_E' can miss a
  // mode that only contact holds once that matrix is large (a 1 025-subdomain punch: the
  // round-off pivot passed, lambda~ missed the punch's load and SMALBE-M "converged" to a
  // zero contact force), so the equation itself decides.
  const double tolerance = 1e-6 * std::max(e.norm(), 1e-300);
  if (n_equality < feti.n_dual_global())
  {
    std::vector<char> equality_mask(feti.n_dual(), 0);
    for (int64_t i = 0; i < feti.n_dual(); ++i)
      equality_mask[i] = feti.row_id(i) < n_equality;
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
/// D_F x: the components outside the face F set to 0, an orthogonal projector.
class FaceRestriction : public la::LinearOperator
{
public:
  explicit FaceRestriction(const std::vector<char>& free) : _free(free) {}
  la::Index size() const override { return static_cast<la::Index>(_free.size()); }
  void apply(const la::Vector& x, la::Vector& y) const override
  {
    y = x;
    for (la::Index i = 0; i < y.size(); ++i)
      if (!_free[i])
        y(i) = 0;
  }

private:
  const std::vector<char>& _free;
};

/// The extreme eigenvalues of M H on the face F of the solution (equality rows and positive
/// contact multipliers), H = P F^ P + rho Q and M its preconditioner for the same rho (exact
/// on Im Q), from `steps` preconditioned CG steps on D_F H D_F x = D_F r: what MPRGP's CG
/// steps see once the active set has settled, from a run longer than MPRGP's, which restarts
/// at every change of the active set, and the step at which that run met the QP's rtol. r has
/// entries from a hash of the row id, so the estimate is the same on any number of ranks.
void measure_solution_face(const FetiOperators& feti, const CoarseProjector& projector, const FOperator& F,
                           const DualPenaltyOptions& options, double s, int64_t n_equality, double rho,
                           const std::vector<char>& free, qp::QpCounters& out)
{
  const ProjectedOperator H(F, projector, rho);
  std::optional<DualPreconditionerOperator> M;
  if (options.preconditioner != DualPreconditioner::none)
    M.emplace(feti, projector, options, s, n_equality, rho);
  const FaceRestriction face(free);
  la::Vector r = la::Vector::Zero(feti.n_dual());
  for (la::Index i = 0; i < r.size(); ++i)
  {
    uint64_t h = static_cast<uint64_t>(feti.row_id(i)) * 0x9E3779B97F4A7C15ull; // splitmix64
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    r(i) = static_cast<double>((h ^ (h >> 31)) >> 11) * 0x1.0p-53 - 0.5;
  }
  la::Vector x = la::Vector::Zero(r.size());
  qp::CgOptions cg;
  cg.rtol = 1e-13; // beyond that the recurrence is round-off
  cg.max_iterations = options.spectrum_steps;
  cg.preconditioner = M ? &*M : nullptr;
  // The step at which the residual first meets the QP's own tolerance: the PCG count on the
  // final face (an active-set method's floor), read off the same run.
  double initial = 0;
  out.solution_face_steps_to_rtol = 0;
  cg.monitor = [&](int iteration, double residual) {
    if (iteration == 0)
      initial = residual;
    else if (out.solution_face_steps_to_rtol == 0 && residual <= options.rtol * initial)
      out.solution_face_steps_to_rtol = iteration;
  };
  la::Vector face_r;
  face.apply(r, face_r);
  out.solution_face = qp::conjugate_gradient(H, face_r, x, cg, &face).ritz;
}

/// ||PFP||, the scale of the dual: the caller's last estimate, or power iterations.
qp::NormEstimate pfp_norm_estimate(const la::LinearOperator& PFP_raw, const DualPenaltyOptions& options,
                                   const DualWarmStart& warm)
{
  // ||PFP|| changes little when only the contact rows change (ALGORITHMS.md section 8): the
  // caller passes the last estimate while F is the same, and the power iterations (6-7
  // products per QP on Hertz) are skipped. It only scales F; a too small value makes an
  // expansion step too long, which MPRGP detects and halves.
  const qp::NormEstimate norm = warm.pfp_norm > 0 ? qp::NormEstimate{warm.pfp_norm, 0}
                                                  : qp::estimate_norm(PFP_raw, options.power_iterations, 1e-3, 1);
  FETICON_CHECK(norm.value > 0 && std::isfinite(norm.value), "||PFP|| estimate " << norm.value << " is not positive");
  return norm;
}

/// The bounds of the homogenized unknown mu = lambda - lambda~: mu_I >= -lambda~_I on the
/// contact rows, none on the equality rows.
la::Vector contact_lower_bound(const FetiOperators& feti, const la::Vector& lambda_tilde, int64_t n_equality)
{
  const int64_t m = feti.n_dual();
  la::Vector lower = la::Vector::Constant(m, -std::numeric_limits<double>::infinity());
  for (int64_t i = 0; i < m; ++i)
    if (feti.row_id(i) >= n_equality)
      lower(i) = -lambda_tilde(i);
  return lower;
}

/// MPRGP's options for the scaled dual, with the step length bound known from the scaling.
qp::MprgpOptions mprgp_options(const DualPenaltyOptions& options)
{
  qp::MprgpOptions mprgp;
  mprgp.rtol = options.rtol;
  mprgp.max_iterations = options.max_iterations;
  mprgp.expansion = options.expansion;
  // After scaling, ||H|| = max(||P F^ P||, rho) ~ max(1, rho): no second power iteration.
  mprgp.alpha_bar = 1.8 / std::max(1.0, options.rho);
  return mprgp;
}

/// SMALBE-M's options, with the equality error in the subdomains' net forces when the caller
/// asks for a feasibility tolerance.
qp::SmalbeOptions smalbe_options(const FetiOperators& feti, const CoarseProjector& projector,
                                 const DualPenaltyOptions& options, const qp::MprgpOptions& mprgp)
{
  qp::SmalbeOptions smalbe;
  smalbe.rtol = options.rtol;
  smalbe.rho = options.rho;
  smalbe.M0 = options.smalbe_M0;
  smalbe.beta = options.smalbe_beta;
  smalbe.max_inner_iterations = options.max_iterations;
  smalbe.mprgp = mprgp;
  if (options.feasibility_tolerance > 0)
  {
    // x = mu (force units: b and H carry the same scale), so G mu = G lambda - e, and the
    // weights turn it into the subdomains' net forces (FetiOperators::net_force_weights).
    smalbe.equality_error = [&projector, w = feti.net_force_weights()](const la::Vector& Cx) {
      return projector.from_tilde(Cx).cwiseProduct(w).norm();
    };
    smalbe.equality_tolerance = options.feasibility_tolerance;
  }
  return smalbe;
}

/// SMALBE-M's start from the warm start's coarse multiplier, M and rho, if it has one for
/// this coarse space.
std::optional<qp::SmalbeStart> smalbe_start(const FetiOperators& feti, const CoarseProjector& projector,
                                            const DualPenaltyOptions& options, const DualWarmStart& warm, double scale)
{
  // The multiplier of G~ mu = 0 in the scaled dual is scale times the unscaled one.
  std::optional<qp::SmalbeStart> start;
  if (warm.coarse_multiplier.size() == feti.n_kernel())
    start = qp::SmalbeStart{projector.tilde_multiplier(scale * warm.coarse_multiplier),
                            warm.M > 0 ? warm.M : options.smalbe_M0, std::max(warm.rho, options.rho)};
  return start;
}

/// The rows of primal recovery (ALGORITHMS.md section 1): the equalities and the contact rows
/// with a positive multiplier; `active_contacts` counts the latter over all ranks.
std::vector<char> active_rows(const FetiOperators& feti, const la::Vector& lambda, int64_t n_equality,
                              int64_t& active_contacts)
{
  // Active rows: equalities and contact rows with a positive multiplier. MPRGP keeps
  // bound components exactly at the bound, so lambda_i = 0 there up to round-off; the
  // threshold only guards against round-off-sized values.
  const int64_t m = feti.n_dual();
  auto is_contact = [&](int64_t i) { return feti.row_id(i) >= n_equality; };
  double lambda_max = 0;
  for (int64_t i = 0; i < m; ++i)
    if (is_contact(i))
      lambda_max = std::max(lambda_max, lambda(i));
  lambda_max = feti.space().max(lambda_max);
  std::vector<char> active(m, 1);
  int64_t local_active = 0;
  for (int64_t i = 0; i < m; ++i)
    if (is_contact(i))
    {
      active[i] = lambda(i) > 1e-12 * lambda_max;
      local_active += active[i];
    }
  active_contacts = feti.comm().sum(local_active);
  return active;
}

/// Why no contact force holds a body, for recover_primal's message when the active rows
/// leave one free: empty unless the load is below what the QP resolves.
std::string unheld_body_message(const FetiOperators& feti, const la::Vector& b, double e_norm, int64_t active_contacts,
                                double rtol)
{
  // If the active rows leave a body free (recover_primal refuses): a load far below the force
  // that would close the initial gaps elastically (b, in force units like lambda) is the likely
  // cause, since the QP's tolerances, relative to ||b||, then admit lambda = 0 (on Hertz from
  // a ratio of about 1 / qp.rtol on: docs/benchmarks.md, magnitudes).
  std::string unheld;
  const double b_norm = active_contacts == 0 && e_norm > 0 ? la::norm(feti.space(), b) : 0.0; // a reduction only then
  if (b_norm * rtol >= e_norm && e_norm > 0)
  {
    std::ostringstream why;
    why << "the load on a body that only contact holds (" << e_norm << " N) is " << b_norm / e_norm
        << " times smaller than the force that would close the initial contact gaps elastically (" << b_norm
        << " N), beyond what the dual QP resolves at its tolerance (rtol " << rtol
        << "): it found no contact force. A softer material, a larger load, or bodies that touch where the load "
           "presses them";
    unheld = why.str();
  }
  return unheld;
}
} // namespace

DualSolution solve_contact_dual(const FetiOperators& feti, const la::Vector& c, const la::Vector& f_stacked,
                                int64_t n_equality, const DualPenaltyOptions& options, const DualWarmStart& warm)
{
  const int64_t m = feti.n_dual();
  FETICON_CHECK(c.size() == m && n_equality <= feti.n_dual_global(), "dual problem: sizes do not match");
  FETICON_CHECK(options.rho > 0, "rho = " << options.rho << " must be positive");
  const CoarseProjector projector(feti);
  const la::Vector e = feti.apply_Rt(f_stacked);
  const la::Vector lambda_tilde = particular_solution(feti, projector, e, n_equality);
  const la::Vector d = feti.apply_B(feti.apply_K_plus(f_stacked)) - c;

  DualSolution out;
  const FOperator F_raw(feti);
  const ProjectedOperator PFP_raw(F_raw, projector, 0.0);
  const qp::NormEstimate norm = pfp_norm_estimate(PFP_raw, options, warm);
  out.pfp_norm = norm.value;
  const double scale = 1.0 / norm.value;
  const FOperator F(feti, scale);
  // The dual penalty's Hessian is H = P F^ P + rho Q; SMALBE-M gets A = P F^ P and adds
  // rho Q = rho G~'G~ itself (for the rho it has at the time).
  const bool smalbe_method = options.method == DualMethod::smalbe;
  const ProjectedOperator H_untimed(F, projector, smalbe_method ? 0.0 : options.rho);
  const la::TimedOperator H(H_untimed);
  const la::Vector b = projector.apply_P(scale * (d - feti.apply_F(lambda_tilde)));

  const la::Vector lower = contact_lower_bound(feti, lambda_tilde, n_equality);
  // Warm start projected onto Ker G: when K_M(u) or the contact rows change, G changes and
  // lambda_start - lambda~ is far from Ker G, which SMALBE-M would then repair slowly
  // through its multiplier (the inner stop ||g_P|| <= M ||G~ mu|| passes at once).
  la::Vector mu =
      warm.lambda.size() == m ? projector.apply_P(warm.lambda - lambda_tilde) : la::Vector(la::Vector::Zero(m));

  qp::MprgpOptions mprgp = mprgp_options(options);
  std::optional<DualPreconditionerOperator> preconditioner;
  std::optional<la::TimedOperator> timed_preconditioner;
  if (options.preconditioner != DualPreconditioner::none)
    timed_preconditioner.emplace(
        preconditioner.emplace(feti, projector, options, norm.value, n_equality, smalbe_method ? 0.0 : options.rho));
  if (!smalbe_method)
  {
    mprgp.preconditioner = timed_preconditioner ? &*timed_preconditioner : nullptr;
    qp::Mprgp solver(H, mprgp);
    out.report = solver.solve(b, lower, mu);
    out.report.outer_iterations = 1;
  }
  else
  {
    const GTildeOperator C(projector);
    qp::Smalbe solver(H, C, smalbe_options(feti, projector, options, mprgp),
                      timed_preconditioner ? &*timed_preconditioner : nullptr);
    const std::optional<qp::SmalbeStart> start = smalbe_start(feti, projector, options, warm, scale);
    const qp::SmalbeReport r = solver.solve(b, lower, mu, start ? &*start : nullptr);
    out.report = r;
    out.coarse_multiplier = projector.coarse_multiplier(r.omega) / scale;
    out.smalbe_M = r.final_M;
    out.smalbe_rho = r.final_rho;
  }
  out.report.hessian_multiplications += norm.applications;
  out.report.operator_applications = H.applications();
  out.report.operator_seconds = H.seconds();
  if (timed_preconditioner)
  {
    out.report.preconditioner_applications = timed_preconditioner->applications();
    out.report.preconditioner_seconds = timed_preconditioner->seconds();
  }
  out.lambda = lambda_tilde + mu;
  const double e_norm = e.norm();
  out.feasibility_error = (feti.apply_G(out.lambda) - e).norm() / (e_norm > 0 ? e_norm : 1.0);

  const std::vector<char> active = active_rows(feti, out.lambda, n_equality, out.active_contacts);
  const std::string unheld = unheld_body_message(feti, b, e_norm, out.active_contacts, options.rtol);
  if (options.spectrum_steps > 0)
    measure_solution_face(feti, projector, F, options, norm.value, n_equality,
                          smalbe_method ? out.smalbe_rho : options.rho, active, out.report);
  PrimalSolution primal = recover_primal(feti, f_stacked, c, out.lambda, active, unheld);
  out.u = std::move(primal.u);
  out.alpha = std::move(primal.alpha);
  return out;
}
} // namespace feticon::dual
