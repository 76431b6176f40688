#include "dual/dual_penalty_problem.hpp"

#include "common/error.hpp"
#include "dual/contact_qp.hpp"
#include "dual/dual_preconditioner.hpp"
#include "qp/conjugate_gradient.hpp"
#include "qp/mpgp.hpp"
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
                           const std::vector<char>& free, const std::vector<char>& held, qp::QpCounters& out)
{
  const ProjectedOperator H(F, projector, rho);
  std::optional<DualPreconditionerOperator> M;
  if (options.preconditioner != DualPreconditioner::none)
    M.emplace(feti, projector, options, s, n_equality, rho, held);
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
  smalbe.absolute_tolerance = options.force_tolerance;
  smalbe.rho = options.rho;
  smalbe.M0 = options.smalbe_M0;
  smalbe.beta = options.smalbe_beta;
  if (options.smalbe_rho_growth > 0) // else auto: the contact solver sets it; SmalbeOptions' own here
    smalbe.rho_growth = options.smalbe_rho_growth;
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

/// The rows of primal recovery (ALGORITHMS.md section 1): the equalities, the normal contact
/// rows with a positive multiplier and the tangential rows that stick (|lambda_i| < g_i: the
/// slip there is zero; a sliding row's force is known, its slip not); `active_contacts` counts
/// the normal ones over all ranks.
std::vector<char> active_rows(const FetiOperators& feti, const ContactQp& qp, const la::Vector& lambda,
                              int64_t& active_contacts)
{
  // MPRGP keeps bound components exactly at the bound, so lambda_i = 0 (or |lambda_i| = g_i)
  // there up to round-off; the threshold only guards against round-off-sized values.
  const int64_t m = feti.n_dual();
  const std::vector<RowKind>& kinds = qp.kinds();
  double lambda_max = 0;
  for (int64_t i = 0; i < m; ++i)
    if (kinds[i] != RowKind::equality)
      lambda_max = std::max(lambda_max, std::abs(lambda(i)));
  lambda_max = feti.space().max(lambda_max);
  std::vector<char> active(m, 1);
  int64_t local_active = 0;
  for (int64_t i = 0; i < m; ++i)
    if (kinds[i] == RowKind::normal)
    {
      active[i] = lambda(i) > 1e-12 * lambda_max;
      local_active += active[i];
    }
    else if (kinds[i] == RowKind::tangential) // a held row's direction is the supports'
      active[i] = !qp.held(i) && std::abs(lambda(i)) < qp.slip_bound(i) - 1e-12 * lambda_max;
  for (const qp::Disc& disc : qp.constraints().discs) // 3D: the pair's norm
    active[disc.i] = active[disc.j] = std::hypot(lambda(disc.i), lambda(disc.j)) < disc.radius - 1e-12 * lambda_max;
  active_contacts = feti.comm().sum(local_active);
  return active;
}

/// The owned friction rows at their bound (primal_recovery.hpp): discs with the direction
/// across their slide, and single rows.
SlidingRows sliding_rows(const ContactQp& qp, const la::Vector& lambda, const std::vector<char>& active)
{
  SlidingRows out;
  std::vector<char> in_disc(active.size(), 0);
  for (const qp::Disc& disc : qp.constraints().discs)
  {
    in_disc[disc.i] = in_disc[disc.j] = 1;
    const double t_i = lambda(disc.i), t_j = lambda(disc.j); // the disc's centre is 0 in lambda
    const double size = std::hypot(t_i, t_j);
    if (!active[disc.i] && size > 0)
      out.discs.push_back({disc.i, disc.j, -t_j / size, t_i / size});
  }
  for (size_t i = 0; i < active.size(); ++i)
  {
    const auto row = static_cast<la::Index>(i);
    if (qp.kinds()[i] == RowKind::tangential && !in_disc[i] && !active[i] && !qp.held(row))
      out.boxes.push_back(row);
  }
  return out;
}

/// Whether friction rows exist on some rank and none of them sticks.
bool sliding_only(const FetiOperators& feti, const ContactQp& qp, const std::vector<char>& active)
{
  int64_t tangential = 0, sticking = 0;
  for (size_t i = 0; i < active.size(); ++i)
    if (qp.kinds()[i] == RowKind::tangential && !qp.held(static_cast<la::Index>(i)))
    {
      ++tangential;
      sticking += active[i];
    }
  return feti.comm().sum(tangential) > 0 && feti.comm().sum(sticking) == 0;
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
                                int64_t n_equality, const DualPenaltyOptions& options, const qp::QpState& warm,
                                const FrictionRows* friction, const la::Vector* compliance)
{
  FETICON_CHECK(options.rho > 0, "rho = " << options.rho << " must be positive");
  const ContactQp qp(feti, c, f_stacked, n_equality, options, warm.operator_norm, friction, compliance);
  la::Vector mu = qp.mu(warm.x);
  DualSolution out;
  qp::MprgpOptions mprgp = mprgp_options(options);
  const bool smalbe_method = options.method == DualMethod::smalbe;
  qp::SmalbeReport smalbe_report;
  // MPRGP for bounds; MPGP where 3D friction adds discs, on every rank if any rank has one
  // (the two solvers' collectives differ: a rank owning no disc row must run MPGP too).
  const bool discs = feti.comm().max(qp.constraints().discs.empty() ? 0.0 : 1.0) > 0;
  const auto inner_solver = [discs](const la::LinearOperator& H,
                                    const qp::MprgpOptions& o) -> std::unique_ptr<qp::QpSolver> {
    if (discs)
      return std::make_unique<qp::Mpgp>(H, o);
    return std::make_unique<qp::Mprgp>(H, o);
  };
  if (!smalbe_method)
  {
    mprgp.preconditioner = qp.preconditioner();
    // The looser of rtol ||b|| and the outer loop's force tolerance, as SMALBE-M's final test
    // (qp::SmalbeOptions::absolute_tolerance); the penalty's G lambda - e is rho's to bound.
    if (options.force_tolerance > 0)
      mprgp.stop = [tol = std::max(options.rtol * la::norm(feti.space(), qp.rhs()), options.force_tolerance)](
                       const la::Vector&, const la::Vector&, double projected_gradient_norm) {
        return projected_gradient_norm <= tol;
      };
    out.report = inner_solver(qp.hessian(), mprgp)->solve(qp.rhs(), qp.constraints(), mu);
    out.report.outer_iterations = 1;
  }
  else
  {
    qp::SmalbeOptions smalbe = smalbe_options(feti, qp.projector(), options, mprgp);
    smalbe.inner_solver = inner_solver;
    qp::Smalbe solver(qp.hessian(), qp.equality(), smalbe, qp.preconditioner());
    const std::optional<qp::QpState> start = qp.inner_start(warm);
    smalbe_report = solver.solve(qp.rhs(), qp.constraints(), mu, start ? &*start : nullptr);
    out.report = smalbe_report;
  }
  out.report.hessian_multiplications += qp.norm_applications();
  out.report.operator_applications = qp.hessian().applications();
  out.report.operator_seconds = qp.hessian().seconds();
  if (const la::TimedOperator* M = qp.preconditioner())
  {
    out.report.preconditioner_applications = M->applications();
    out.report.preconditioner_seconds = M->seconds();
  }
  la::Vector lambda = qp.lambda(mu);
  out.feasibility_error = qp.feasibility_error(lambda);
  const std::vector<char> active = active_rows(feti, qp, lambda, out.active_contacts);
  // Every friction row sliding leaves the body free along the slide: the limit Q = mu P, whose
  // slide is undetermined, or beyond it no equilibrium, where the QP does not converge.
  const bool sliding = sliding_only(feti, qp, active);
  const std::string sliding_message =
      "every tangential (friction) row slides: the tangential load reaches or exceeds what friction can carry (mu "
      "times the normal force, or Tresca's g times the contact area), and a body sliding under a force has no "
      "unique equilibrium; lower the tangential load, or prescribe the displacement that drives the slide";
  FETICON_CHECK(out.report.converged || !sliding, sliding_message << " (dual QP: " << out.report.reason << ")");
  const std::string unheld = sliding
      ? sliding_message
      : unheld_body_message(feti, qp.rhs(), qp.load_norm(), out.active_contacts, options.rtol);
  if (options.spectrum_steps > 0)
    measure_solution_face(feti, qp.projector(), qp.scaled_F(), options, qp.pfp_norm(), n_equality,
                          smalbe_method ? smalbe_report.final_rho : options.rho, active, qp.held_rows(), out.report);
  PrimalSolution primal = qp.recover(lambda, active, unheld, sliding_rows(qp, lambda, active));
  out.u = std::move(primal.u);
  out.alpha = std::move(primal.alpha);
  if (smalbe_method)
    out.state = qp.outer_state(std::move(lambda), smalbe_report);
  else
    out.state = {std::move(lambda), {}, 0, 0, qp.pfp_norm()};
  return out;
}
} // namespace feticon::dual
