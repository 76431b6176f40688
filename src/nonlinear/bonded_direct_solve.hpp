#pragma once
/// @file The direct lower bound of the benchmarks (issue 8): one CHOLMOD solve of the
/// undecomposed linear elastic problem with the contact zone bonded.
///
/// Definition. The contact rows B, c of the problem's pair are built in the reference
/// configuration (u = 0; normalized rows, contact::build_contact_constraints with the
/// settings' formulation and search distance). The rows whose slave node is in a given set
/// (usually the nodes in contact in a contact solution, active_slave_nodes()) form B_A, c_A
/// and get the springs of the primal penalty solver (contact_penalty.hpp):
///   eps_i = eps_n A_i / mean(A),  eps_n = eps_n_factor * max diag K,
///   (K + B_A' E B_A) u = f_ext + B_A' E c_A,  Dirichlet DOFs and linear equations eliminated,
/// with K the linear stiffness of the whole mesh and f_ext the full load. It is the linear
/// system of the primal penalty solver with that active set fixed: the bonded nodes are tied
/// to the master surface at their initial gap, in tension as in compression, so one
/// factorization and one solve replace the contact iteration. A contact solver of the same
/// mesh cannot beat assembling, factorizing and solving this system by much; the benchmarks
/// report contact-solve time / (factorization + solve time).
///
/// Usage:
///   const ContactSolution contact = solve_feti_contact(problem, settings, timers);
///   const BondedSolve direct = bonded_direct_solve(problem, settings, active_slave_nodes(contact));

#include "contact/contact_constraints.hpp"
#include "fem/problem.hpp"
#include "nonlinear/contact_solution.hpp"
#include "nonlinear/solver_settings.hpp"

#include <vector>

namespace feticon::nonlinear
{
struct BondedSolve
{
  la::Vector u;                            ///< displacement, 3 per mesh node (m)
  contact::ContactConstraints constraints; ///< all contact rows at u = 0
  /// Spring multipliers eps_i (B u - c)_i of the bonded rows, 0 on the others (normalized
  /// rows: the slave force is lambda_i / |b_i|; negative where a bond pulls).
  la::Vector contact_lambda;
  int64_t n_bonded = 0;             ///< rows in B_A
  double penalty = 0;               ///< eps_n (N/m)
  double assembly_seconds = 0;      ///< K, contact rows, springs, Dirichlet elimination
  double factorization_seconds = 0; ///< CHOLMOD analysis and numeric factorization
  double solve_seconds = 0;         ///< triangular solves and expansion to all DOFs
  long factor_nonzeros = 0;
};

/// The bonded system of bonded_direct_solve after the elimination, for other solvers of it
/// (bench: PETSc's algebraic multigrid, the iterative floor of issue 40).
struct BondedSystem
{
  la::SparseMatrix A; ///< T' (K + B_A' E B_A) T, both triangles
  la::Vector b;       ///< T' (f_ext + B_A' E c_A - (K + B_A' E B_A) g)
  /// The rigid-body modes as vectors of the free DOFs, orthonormal columns (the near kernel
  /// an algebraic multigrid builds its coarse spaces from); filled by bonded_system only.
  la::Matrix near_kernel;
};

/// @brief The system bonded_direct_solve factorizes, with its near kernel; arguments and
///        errors as there.
BondedSystem bonded_system(const fem::Problem& problem, const SolverSettings& settings,
                           const std::vector<int32_t>& bonded_nodes);

/// @brief Slave nodes of the rows with a positive multiplier (the nodes in contact).
std::vector<int32_t> active_slave_nodes(const ContactSolution& solution);

/// @brief The bonded direct solve of the file comment.
/// @param[in] problem      one contact pair; kinematics are linear whatever `settings` say
/// @param[in] settings     eps_n_factor, formulation and search_distance are used
/// @param[in] bonded_nodes slave nodes to bond; each must have a contact row at u = 0
/// @throws feticon::Error for a listed node without a row, or if the bonded system is
///         singular (a body held only by contact with no bonded node)
BondedSolve bonded_direct_solve(const fem::Problem& problem, const SolverSettings& settings,
                                const std::vector<int32_t>& bonded_nodes);
} // namespace feticon::nonlinear
