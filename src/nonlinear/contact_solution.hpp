#pragma once
/// @file What a contact solve returns: displacement, contact multipliers and history.

#include "contact/contact_constraints.hpp"
#include "contact/tangential_rows.hpp"
#include "fem/plastic_states.hpp"
#include "la/types.hpp"
#include "qp/qp_report.hpp"
#include "qp/qp_state.hpp"

#include <string>
#include <vector>

namespace feticon::nonlinear
{
/// One outer iteration (one QP or linear solve).
struct OuterIteration
{
  int load_step = 0;
  int iteration = 0;
  /// The QP's counters: MPRGP steps (penalty: active-set solves), SMALBE-M updates,
  /// operator and preconditioner applications, the spectrum estimate of its longest CG run.
  qp::QpCounters qp;
  double final_rho = 0; ///< SMALBE-M's rho at the end of the QP (0 for the other methods)
  /// ||t f_ext - f_int - B' lambda|| / max(||t f_ext||, ||f_int||) after the update
  double residual_norm = 0;
  double displacement_change = 0; ///< ||du|| / ||u||
  int64_t active_contacts = 0;
  double feasibility_error = 0;
  double seconds = 0;
};

struct LoadStep
{
  double load_factor = 0;
  int outer_iterations = 0;
  bool converged = false;
  /// Not empty: the step ended at a floor above the residual tolerance (OuterVerdict::floor).
  std::string floor;
  double displacement_change = 0;
  double residual_norm = 0;
  std::vector<int> inner_iterations;
};

/// The warning of load step `number` (1-based) that ended at a floor.
inline std::string floor_warning(int number, const LoadStep& step)
{
  return "load step " + std::to_string(number) + " ended above the residual tolerance: " + step.floor;
}

/// What a run needs to continue after its last converged load step (checkpoint/restart):
/// the stacked displacement and the multipliers that warm-start the next solve.
struct RestartState
{
  int completed_steps = 0;
  la::Vector u_stacked; ///< global stacked displacement (all subdomains)
  /// The last dual solve's state (dual::DualSolution::state): x the equality multipliers by
  /// row id; SMALBE-M's coarse multiplier, M and rho (empty/0 for other methods); ||PFP||.
  qp::QpState dual;
  std::vector<int32_t> contact_slave; ///< slave node of each contact multiplier
  /// Contact pair of each contact multiplier; empty: all pair 0 (a checkpoint of one pair).
  std::vector<int32_t> contact_pair;
  std::vector<double> contact_lambda; ///< contact multiplier by (pair, slave node)
  /// With friction: two tangential multipliers per contact_slave entry; empty without.
  std::vector<double> contact_tangential;
  /// The Dirichlet preconditioner's boundary DOFs (3 node + component) once contact rows made
  /// it grow (ContactSolution::schur_boundary_widened); empty while it has its initial extent.
  /// A restart forms its operators on it, as the uninterrupted run has them.
  std::vector<int32_t> schur_boundary;
  /// The committed J2 states of every plastic cell (fem::MeshPlasticStates::pack); empty without.
  std::vector<double> plastic;
  /// Small displacements: the candidate contact rows the QPs had (LinearContactRows), those
  /// added where a left-out row was penetrated included; empty: the initial selection.
  std::vector<int32_t> linear_rows_selected;
  /// The start values of the DOFs the last completed step's stage holds and the stage before
  /// left free (fem::LoadHistory::start_values); empty: none.
  std::vector<double> stage_start;
  /// The run had switched from K_0 to K_M(u) refreshed at every outer iteration with QPs to
  /// qp.rtol (FetiContactSolve::escalate): a restart continues so.
  bool escalated = false;
};

struct ContactSolution
{
  la::Vector u; ///< global displacement, 3 per mesh node
  /// T - T_0 per mesh node (K) at the load step of u (fem::TemperatureHistory); empty: the
  /// problem has no temperatures. The stresses of the outputs subtract its thermal strain.
  la::Vector temperature_change;
  /// The J2 states committed at the last converged load step, per mesh cell (empty: no plastic
  /// body); every rank holds every cell's.
  fem::MeshPlasticStates plastic;
  contact::ContactConstraints constraints; ///< contact rows of the last solve
  la::Vector contact_lambda;               ///< their (row-normalized) multipliers
  /// With friction: the tangential rows of the last solve (of its contact rows) and their
  /// row-normalized multipliers; empty without.
  contact::TangentialRows tangential;
  la::Vector tangential_lambda;
  std::vector<OuterIteration> history;
  std::vector<LoadStep> steps;
  /// Every load step ran: u and the multipliers are the run's answer.
  bool completed = false;
  /// Completed, and every load step met the outer loop's stopping test.
  bool converged = false;
  std::string reason;                ///< why the run is not converged
  std::vector<std::string> warnings; ///< steps that ended at a floor, one line each
  // Figures of the last solve:
  int64_t n_dual = 0;
  int64_t n_kernel = 0;
  int32_t n_subdomains = 0;
  double feasibility_error = 0;
  /// "explicit" or "implicit" dual operators, and why (dual.operator = auto picks).
  std::string dual_operator = "implicit", dual_operator_reason;
  int64_t explicit_operator_bytes = 0; ///< dense boundary blocks of all ranks (0: implicit)
  /// Whether contact rows left the contact DOFs the Dirichlet preconditioner's boundary started
  /// with, so that it grew by the rows near contact at the current u and the operators of the
  /// subdomains whose boundary changed were formed again (feti_contact_solver.cpp).
  bool schur_boundary_widened = false;
  int schur_boundary_growths = 0; ///< how often it grew in this run (not counting a restart's restore)
  double penalty = 0;             ///< eps_n (N/m) for the primal penalty
  RestartState restart;           ///< state after the last converged load step (FETI solver)
  /// Under MPI with more than one rank: the cells of this rank's subdomains (its piece of
  /// the output); empty otherwise.
  std::vector<int32_t> owned_cells;
};
} // namespace feticon::nonlinear
