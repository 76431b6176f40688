#pragma once
/// @file SMALBE-M: semimonotonic augmented Lagrangian for bound and equality constraints
/// with adaptive M (Dostál 2006, 2009; ALGORITHMS.md section 1).
///
/// Solves   min 1/2 x'Ax - b'x   subject to   x in Omega,  C x = 0,
/// where C has orthonormal rows (C C' = I), through the augmented Hessian H = A + rho C'C,
/// which SMALBE-M owns (for FETI: A = P F P, C = G~, so C'C = Q and H = PFP + rho Q), with its
/// preconditioner M_A + C'C / rho_0 when the caller gives M_A ~ A^{-1} on Ker C (rho_0 the
/// initial rho: on Im C' the exact inverse of H until rho is raised, and kept after that,
/// which measured fewer steps than following rho; smalbe.cpp). Outer loop:
///   x <- inner solver (MPRGP for bounds) on (H, b - C'omega, Omega), warm-started, stopped when
///        ||g_P|| <= min(M ||Cx||, eta)   or the final test holds;
///   final test: ||g_P|| <= tol and ||Cx|| <= tol, tol = max(rtol ||b||, absolute_tolerance)
///        (and, if the caller asks, its own measure of Cx below its own tolerance:
///        SmalbeOptions::equality_error);
///   if only the feasibility half fails: the feasibility correction on the face (below),
///        which ends the solve if the final test holds after it;
///   omega <- omega + rho C x;
///   M <- M / beta if L(x, omega) did not increase by at least rho/2 ||Cx||^2;
///   if ||Cx|| has not dropped below feasibility_reduction times its reference value within
///        feasibility_window outer iterations: rho <- rho min(max(q/(1-q), g), g_max), g =
///        rho_growth, g_max = rho_growth_max, q the observed contraction of ||Cx|| per outer iteration (q/(1-q) is
///        the factor that brings the model rate below to 1/2); H and MPRGP's step length
///        bound alpha_bar follow the new rho.
/// Why the rho update: with the bounds active on a face F, the multiplier update is a gradient
/// step on the dual of the face problem, and ||Cx|| contracts per outer iteration by about
/// 1 - rho s/(h + rho s), s = sigma_min(C_F)^2 (C_F: the columns of C on the free set) and h
/// the curvature of H off C along that direction. Without bounds s = 1 and the factor is about
/// 1/2; when a face nearly loses the rank of C (for FETI: inactive contact rows that carried a
/// large share of G), s << 1 and SMALBE-M with fixed rho crawls while the Lagrangian still
/// grows by rho/2 ||Cx||^2, so the M test never fires. Raising rho, as in Dostal's original
/// SMALBE (rho_k nondecreasing and bounded), restores the rate.
/// Usage:
///   qp::Smalbe smalbe(A, C, {.rho = 1}, &preconditioner_of_A);
///   const qp::SmalbeReport r = smalbe.solve(b, {lower, {}, {}}, x);

#include "qp/mprgp.hpp"
#include "qp/qp_state.hpp"

#include <memory>

namespace feticon::qp
{
/// An operator with orthonormal rows: x -> C x (m rows) and y -> C' y.
class EqualityOperator
{
public:
  virtual ~EqualityOperator() = default;
  virtual la::Vector apply(const la::Vector& x) const = 0;
  virtual la::Vector apply_transpose(const la::Vector& y) const = 0;
};

/// The state after one outer iteration's inner solve, before the updates of omega and M.
struct SmalbeIterate
{
  int outer_iteration = 0;           ///< k, from 0
  const la::Vector* x = nullptr;     ///< the inner solve's result
  const la::Vector* omega = nullptr; ///< the multiplier it used
  double M = 0;                      ///< the M it used
  double rho = 0;                    ///< the rho it used
  double lagrangian = 0;             ///< L(x, omega) with the penalty rho
};

/// Builds the inner solver for the augmented Hessian H (referenced; it outlives the solver)
/// with MprgpOptions's step length, stopping test and preconditioner set by SMALBE-M.
using InnerSolverFactory = std::function<std::unique_ptr<QpSolver>(const la::LinearOperator& H, const MprgpOptions&)>;

struct SmalbeOptions
{
  double rtol = 1e-6; ///< final test on ||g_P|| and ||Cx||, relative to ||b||
  /// The final test's bound on ||g_P|| and ||Cx|| is max(rtol ||b||, absolute_tolerance): a
  /// caller that knows the accuracy it needs in b's units (FETI: force) states it here.
  double absolute_tolerance = 0;
  double rho = 1.0;        ///< the augmentation in H (multiplier update step)
  double M0 = 1.0;         ///< initial M (in units where ||H|| ~ max(1, rho))
  double beta = 2.0;       ///< M <- M / beta when L does not increase enough
  double eta_factor = 0.1; ///< eta = eta_factor ||b||
  int max_outer_iterations = 200;
  int max_inner_iterations = 100000; ///< total MPRGP steps over all outer iterations
  /// Smallest factor by which rho grows when the feasibility stalls; 1 disables the update.
  double rho_growth = 10.0;
  /// Largest factor of one update (at least rho_growth).
  double rho_growth_max = 1000.0;
  /// Stall test: ||Cx|| has not fallen below feasibility_reduction times its reference value
  /// (the value at the last reduction or rho update) within feasibility_window outer iterations.
  double feasibility_reduction = 0.1;
  int feasibility_window = 5;
  /// rho never exceeds rho_limit times the initial rho.
  double rho_limit = 1e4;
  /// When an inner solve meets the gradient half of the final test but not the feasibility
  /// half, try to remove Cx within the face of x (Smalbe::correct_feasibility_on_face) before
  /// another outer iteration; false: only the multiplier updates reduce Cx.
  bool feasibility_correction = true;
  /// gamma, alpha_bar (for H at the initial rho; 0: estimated), monitor; its rtol, stop and
  /// preconditioner are set here.
  MprgpOptions mprgp{};
  /// The inner solver; unset: MPRGP (bounds only).
  InnerSolverFactory inner_solver;
  /// Optional second feasibility test of the final stop, in the caller's units: converged
  /// only when also equality_error(Cx) <= equality_tolerance. For FETI, ||G lambda - e|| in
  /// force units: the rtol ||b|| test alone lets it grow with the gaps of inactive contact
  /// rows in b, and the outer loop's force residual then stalls above its tolerance
  /// (docs/benchmarks.md, hertz3d at 326k DOFs). Unset: only ||Cx|| <= rtol ||b||.
  std::function<double(const la::Vector& Cx)> equality_error;
  double equality_tolerance = 0;
  /// Called after every outer iteration's inner solve (tests check the updates with it).
  std::function<void(const SmalbeIterate&)> monitor;
};

/// QpReport with the counters summed over the inner solves (outer_iterations and
/// rho_updates counted by SMALBE-M itself).
struct SmalbeReport : QpReport
{
  double equality_residual = 0; ///< ||Cx|| / ||b|| at the end
  double final_M = 0;
  double final_rho = 0; ///< rho at the end (the initial rho unless it was raised)
  la::Vector omega;     ///< multiplier of Cx = 0
};

class Smalbe
{
public:
  /// @param A              the Hessian without the augmentation (referenced)
  /// @param C              the equality operator, orthonormal rows (referenced)
  /// @param preconditioner M_A ~ A^{-1} on Ker C, or null for none (referenced)
  Smalbe(const la::LinearOperator& A, const EqualityOperator& C, SmalbeOptions options,
         const la::LinearOperator* preconditioner = nullptr);
  /// @param[in,out] x initial guess on input (projected onto Omega), solution on output
  /// @param start    omega, M and rho of an earlier solve of a nearby problem (its x is not
  ///                 read): omega of the size of Cx, or empty for 0; M = 0 for M0; rho raised
  ///                 to at least the options' rho (H holds the initial rho; the difference is
  ///                 added as in a rho update); null: omega = 0, M0 and rho of the options
  SmalbeReport solve(const la::Vector& b, const SeparableConstraints& set, la::Vector& x,
                     const QpState* start = nullptr);

private:
  /// omega, M, rho, H and the inner solver of one solve (smalbe.cpp).
  struct SolveState;

  /// ||b||, the tolerances, and omega, M and rho from `start` or the options.
  void set_initial_state(SolveState& s, const la::VectorSpace& space, const la::Vector& b, const QpState* start) const;
  /// The inner solver on H = A + rho C'C with the inner stop ||g_P|| <= min(M ||Cx||, eta) or
  /// the final test, and the preconditioner for the initial rho.
  void make_inner_solver(SolveState& s) const;
  /// The inner solver for H: SmalbeOptions::inner_solver's, or MPRGP.
  std::unique_ptr<QpSolver> new_inner_solver(const la::LinearOperator& H, const MprgpOptions& options) const;
  /// The feasibility half of the final test: ||Cx|| <= rtol ||b|| and the caller's equality error.
  bool feasible(const SolveState& s, const la::Vector& Cx) const;
  /// One line per outer iteration (at the summary level every 10 s when iterations are not logged).
  void log_outer_iteration(SolveState& s, int k, const QpReport& r) const;
  /// The rho update: rho raised, with H and MPRGP following it, when ||Cx|| stalled for
  /// feasibility_window outer iterations.
  void raise_rho_if_stalled(SolveState& s, int k, double feasibility) const;
  /// When the inner solve met the gradient half of the final test but not the feasibility
  /// half: x <- x - D C'(C D C')^{-1} C x, D the projector onto the face of x, which removes Cx
  /// without leaving the face; taken (and true returned) only when the bounds hold and the
  /// whole final test holds after it (one more product with H). Why: on a settled face the
  /// last outer iterations only divide ||Cx|| by 7-10 each at 11-15 MPRGP steps, while the
  /// gradient half may already hold (FETI: the equality test in force units asks more of Cx).
  bool correct_feasibility_on_face(SolveState& s, const la::VectorSpace& space, const la::Vector& rhs,
                                   const SeparableConstraints& set, const la::Vector& Cx, la::Vector& x) const;
  /// 1/2 x'Hx - b'x with H at the initial rho (one more product with H).
  double cost_at_initial_rho(SolveState& s, const la::VectorSpace& space, const la::Vector& b,
                             const la::Vector& x) const;

  const la::LinearOperator& _A;
  const EqualityOperator& _C;
  SmalbeOptions _options;
  const la::LinearOperator* _preconditioner;
};
} // namespace feticon::qp
