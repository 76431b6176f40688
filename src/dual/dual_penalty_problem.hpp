#pragma once
/// @file The solve of the contact dual of Vondrák et al. (DD XVI, 2007), their problem (9)
/// (dual::ContactQp: lambda = lambda~ + mu, min 1/2 mu' H mu - mu' b^ s.t. mu_I >= -lambda~_I):
/// by MPRGP with H = P F^ P + rho Q (dual penalty), or with G lambda = e enforced exactly by
/// SMALBE-M (ALGORITHMS.md section 1); the options of both. The primal solution follows
/// from the active rows (primal_recovery.hpp).

#include "dual/feti_operators.hpp"
#include "io/settings.hpp"
#include "qp/qp_state.hpp"
#include "qp/smalbe.hpp"

#include <string>

namespace feticon::dual
{
struct FrictionRows; // contact_qp.hpp

enum class DualMethod
{
  dual_penalty, ///< MPRGP on problem (9): G lambda = e holds up to O(1/rho)
  smalbe        ///< SMALBE-M with MPRGP inside: G lambda = e to the tolerance
};

/// Preconditioner of MPRGP in the face: s P Y X Y P + Q / rho with X = B K B' (lumped) or
/// B S B' (Dirichlet), Y = (B B')^{-1} (constraint_scaling.hpp) and s = ||PFP|| matching the
/// scaled F^: an approximate inverse of H.
enum class DualPreconditioner
{
  none,
  lumped,
  dirichlet
};

/// The options of the dual solve. The values a user sets (rho, smalbe.*, qp.*) come from the
/// settings table (io/settings.cpp), where each default is declared once: a default-built
/// DualPenaltyOptions holds those defaults.
struct DualPenaltyOptions
{
  DualPenaltyOptions();
  /// From `method`, `rho`, `smalbe.M0`, `smalbe.beta`, `qp.rtol`, `qp.force_rtol`, `qp.max_iterations`,
  /// `qp.preconditioner`, `qp.constraint_scaling`, `qp.expansion` and `qp.spectrum_steps`.
  explicit DualPenaltyOptions(const io::Settings& settings);

  DualMethod method;
  double rho;         ///< dimensionless penalty (after scaling by ||PFP||)
  double rtol;        ///< QP tolerance on ||g_P|| (and ||G~ mu||) relative to ||b^||
  int max_iterations; ///< MPRGP steps in total
  /// If > 0 (SMALBE-M): the solve also needs the subdomains' net forces
  /// ||W (G lambda - e)|| <= feasibility_tolerance (N; W = FetiOperators::net_force_weights),
  /// which the outer loop derives from its residual tolerance (qp::SmalbeOptions::equality_error).
  double feasibility_tolerance = 0;
  /// qp.force_rtol: the outer loop's force_tolerance relative to its force scale.
  double force_rtol = 0;
  /// If > 0: the final test also holds when ||g_P|| (SMALBE-M: and ||G~ mu||) is at most this
  /// (force units of the scaled dual; qp::SmalbeOptions::absolute_tolerance), which the outer
  /// loop sets to force_rtol times its force scale.
  double force_tolerance = 0;
  int power_iterations = 30; ///< for ||PFP||
  DualPreconditioner preconditioner;
  /// Schur complements of the Dirichlet preconditioner (not owned; required for it).
  const decomposition::SchurComplements* schur = nullptr;
  /// Y = (B B')^{-1} in the preconditioner; false: Y = I (for comparison).
  bool constraint_scaling;
  qp::MprgpExpansion expansion; ///< MPRGP's expansion step
  double smalbe_M0;             ///< SMALBE-M initial M (scaled units)
  double smalbe_beta;           ///< SMALBE-M: M <- M / beta when L increases too little
  /// SMALBE-M: the least factor of a rho update; 0: auto (the contact solver's rule)
  double smalbe_rho_growth;
  /// If > 0: after the solve, this many preconditioned CG steps on the face of the solution
  /// measure the spectrum of M H there (QpCounters::solution_face): a diagnostic of the
  /// preconditioner, longer than the CG runs between MPRGP's restarts.
  int spectrum_steps;
};

struct DualSolution
{
  /// lambda (state.x: equality rows then contact rows, owned), and for SMALBE-M the
  /// multiplier of G lambda = e as a coarse vector beta (G' beta is the multiplier in the
  /// unscaled dual; indexed by rigid modes, it carries over to the next outer iteration's G)
  /// with the final M and rho; the ||PFP|| estimate used for scaling (operator_norm).
  qp::QpState state;
  la::Vector u;     ///< stacked primal displacement
  la::Vector alpha; ///< rigid-body amplitudes
  /// The QP's counters (summed over SMALBE-M outer steps; outer_iterations 1 for the dual
  /// penalty) with the applications of P F P (+ rho Q) and of the preconditioner timed here
  /// (the norm estimate's applications are in hessian_multiplications only).
  qp::QpReport report;
  double feasibility_error = 0; ///< ||G lambda - e|| / ||e|| (/ ||lambda|| where ||e|| is round-off)
  int64_t active_contacts = 0;  ///< contact rows with lambda_i > 0
};

/// The contact dual (dual::ContactQp) solved by MPRGP (dual penalty) or SMALBE-M, and u from
/// its solution. Vectors are this rank's parts (FetiOperators): dual ones over its owned rows,
/// primal ones over its owned subdomains.
/// @param c             right-hand sides of the owned rows (B u = c_E, B u <= c_I)
/// @param f_stacked     stacked load
/// @param n_equality    global number of equality rows (ids below it are equalities)
/// @param warm          where to start: the state of the solve of a nearby problem (the
///                      previous outer iteration: only the contact rows, the gaps and the
///                      load have changed; its x has this solve's rows), or empty for mu = 0
/// @param friction      tangential rows and slip bounds (contact_qp.hpp), or null
/// @param compliance    per owned row, the compliance of a penalty contact law (contact_qp.hpp),
///                      or null: hard contact
DualSolution solve_contact_dual(const FetiOperators& feti, const la::Vector& c, const la::Vector& f_stacked,
                                int64_t n_equality, const DualPenaltyOptions& options, const qp::QpState& warm = {},
                                const FrictionRows* friction = nullptr, const la::Vector* compliance = nullptr);
} // namespace feticon::dual
