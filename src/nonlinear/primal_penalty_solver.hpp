#pragma once
/// @file The primal penalty method of Vondrák, Dostál, Dobiáš and Pták (DD XVI, 2007,
/// section 2): contact force f_n = eps_n <g>, i.e. a spring of stiffness eps_n on every
/// penetrating contact row, on the undecomposed problem with CHOLMOD; iterated until the
/// active set {violated rows} stops changing.
///
/// For row i (normalized, B_I u <= c_I) the violation is v_i = b_i u - c_i; the penalty
/// energy 1/2 sum eps_i <v_i>^2 adds B_A' E B_A to K and B_A' E c_A to the load, with
/// eps_i = eps_n A_i / mean(A) (A_i the slave node's tributary area: a per-area penalty).
/// The penalty multiplier lambda_i = eps_i <v_i> is comparable with the FETI multipliers.
/// With total Lagrangian kinematics each outer iteration is a full Newton step with K_T
/// and contact rebuilt in the current configuration (an independent reference for FETI).
/// The problem must be coercive once contact springs act (Vondrák et al. 2007: "the primal penalty
/// method cannot treat problems with sub-domains undergoing the rigid body modes").

#include "common/timer.hpp"
#include "fem/problem.hpp"
#include "nonlinear/contact_solution.hpp"
#include "nonlinear/load_stepping.hpp"
#include "nonlinear/solver_settings.hpp"

namespace feticon::nonlinear
{
/// Runs the problem's load history (SolverSettings::load_history: one load step per stage with
/// small displacements); `on_step` after every converged load step, with the solution so far.
ContactSolution solve_primal_penalty(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                                     const StepCallback& on_step = {});
} // namespace feticon::nonlinear
