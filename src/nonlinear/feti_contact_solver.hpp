#pragma once
/// @file Contact by Total FETI with the dual penalty / SMALBE-M, inside the
/// modified Newton–Raphson outer loop (Vondrák et al. 2007, section 5; ALGORITHMS.md section 8).
///
/// Per load step t_n of the problem's load history (fem/load_history.hpp; one step per load
/// stage with small displacements) and outer iteration k:
///   r = f(t_n) - f_int(u)  (no contact forces),  contact rows B_I, c_I = g(u) built in
///   the current configuration x = X + u,  c_E = u_D(t_n) - B_E u,
///   solve the dual QP for du with lambda the total multipliers (warm-started),
///   u <- u + du,  stop when ||du|| <= tol ||u||.
/// By default K (and so F, K+, R) is assembled and factorized once (K_0, Vondrák et al.'s initial
/// step) and kept; only B_I, c_I and G change. Optionally K_M(u) with R(X + u) is refreshed
/// per load step or per iteration. With linear kinematics one solve is exact.
///
/// Under MPI every rank calls this with the same problem: each assembles and factorizes its
/// own subdomains, the dual vector is distributed (dual/feti_operators.hpp), the contact rows
/// are built on every rank from the gathered displacement of the mesh and kept where they
/// touch the rank's subdomains. The returned solution (global u, contact multipliers,
/// history) is the same on every rank, bitwise for any number of ranks.

#include "common/timer.hpp"
#include "fem/problem.hpp"
#include "nonlinear/contact_solution.hpp"
#include "nonlinear/load_stepping.hpp"
#include "nonlinear/solver_settings.hpp"
#include "par/communicator.hpp"

#include <vector>

namespace feticon::nonlinear
{
/// Bytes a rank holds while it forms its explicit blocks (decomposition/explicit_boundary_operators.hpp),
/// beyond the blocks it keeps: each of its `threads` threads forms one subdomain at a time and
/// holds arrays of |b_s|^2 doubles (la::schur_complement's dense trailing factor block, its U
/// and result; the inverse and the Schur block formed from it), counted for the largest
/// subdomains in `boundary_sizes` (the |b_s| of the rank's subdomains). The memory guard's
/// model and dual.operator = auto's budget use it.
double explicit_forming_bytes(std::vector<double> boundary_sizes, int threads);

/// @param previous if given, continue after its completed load steps (its history and steps
///                 are taken from `previous`, the solution of the interrupted run; its step
///                 count names a point of the same load history, which is checked)
ContactSolution solve_feti_contact(const fem::Problem& problem, const SolverSettings& settings, TimerTable& timers,
                                   const StepCallback& on_step = {}, const ContactSolution* previous = nullptr,
                                   par::Communicator comm = par::Communicator::world());
} // namespace feticon::nonlinear
