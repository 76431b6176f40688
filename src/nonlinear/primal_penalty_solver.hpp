#pragma once
/// @file The seed's primal penalty method (section 2): contact force f_n = eps_n <g>, i.e. a
/// spring of stiffness eps_n on every penetrating contact row, on the undecomposed problem
/// with CHOLMOD; iterated until the active set {violated rows} stops changing.
///
/// For row i (normalized, B_I u <= c_I) the violation is v_i = b_i u - c_i; the penalty
/// energy 1/2 eps_n sum <v_i>^2 adds eps_n B_A'B_A to K and eps_n B_A'c_A to the load.
/// The penalty multiplier lambda_i = eps_n <v_i> is comparable with the FETI multipliers.
/// With total Lagrangian kinematics each outer iteration is a full Newton step with K_T
/// and contact rebuilt in the current configuration (an independent reference for FETI).
/// The problem must be coercive once contact springs act (the seed: "the primal penalty
/// method cannot treat problems with sub-domains undergoing the rigid body modes").

#include "common/timer.hpp"
#include "fem/problem.hpp"
#include "nonlinear/contact_solution.hpp"
#include "nonlinear/solver_settings.hpp"

namespace feticon::nonlinear
{
ContactSolution solve_primal_penalty(const fem::Problem& problem, const SolverSettings& settings,
                                     TimerTable& timers);
} // namespace feticon::nonlinear
