#pragma once
/// @file What a contact solve returns: displacement, contact multipliers and history.

#include "contact/contact_constraints.hpp"
#include "la/types.hpp"
#include "qp/qp_report.hpp"

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
  double final_rho = 0;  ///< SMALBE-M's rho at the end of the QP (0 for the other methods)
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
  double displacement_change = 0;
  double residual_norm = 0;
  std::vector<int> inner_iterations;
};

/// What a run needs to continue after its last converged load step (checkpoint/restart):
/// the stacked displacement and the multipliers that warm-start the next solve.
struct RestartState
{
  int completed_steps = 0;
  la::Vector u_stacked;                   ///< global stacked displacement (all subdomains)
  la::Vector lambda;                      ///< equality multipliers of the last solve, by row id
  std::vector<int32_t> contact_slave;     ///< slave node of each contact multiplier
  std::vector<double> contact_lambda;     ///< contact multiplier by slave node
  /// SMALBE-M's state after the last solve (dual::DualWarmStart); empty/0 for other methods.
  la::Vector smalbe_coarse_multiplier;
  double smalbe_M = 0, smalbe_rho = 0;
  double pfp_norm = 0; ///< the last ||PFP|| estimate (dual::DualWarmStart)
};

struct ContactSolution
{
  la::Vector u;                              ///< global displacement, 3 per mesh node
  contact::ContactConstraints constraints;   ///< contact rows of the last solve
  la::Vector contact_lambda;                 ///< their (row-normalized) multipliers
  std::vector<OuterIteration> history;
  std::vector<LoadStep> steps;
  bool converged = false;
  std::string reason;
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
  double penalty = 0; ///< eps_n (N/m) for the primal penalty
  RestartState restart; ///< state after the last converged load step (FETI solver)
  /// Under MPI with more than one rank: the cells of this rank's subdomains (its piece of
  /// the output); empty otherwise.
  std::vector<int32_t> owned_cells;
};
} // namespace feticon::nonlinear
