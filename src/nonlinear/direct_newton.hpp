#pragma once
/// @file Full Newton–Raphson on the undecomposed problem with a direct CHOLMOD solve.
///
/// The reference solver for verification: Dirichlet conditions by elimination, dead loads
/// applied in equal load steps (or along a fem::LoadHistory of several stages), consistent
/// tangent K_T (ALGORITHMS.md section 7). With linear kinematics it is one direct solve per
/// load step. No contact here; see primal_penalty for that.

#include "fem/assembler.hpp"
#include "fem/constraint_elimination.hpp"
#include "fem/dirichlet.hpp"
#include "fem/load_history.hpp"

#include <vector>

namespace feticon::nonlinear
{
struct DirectNewtonOptions
{
  int load_steps = 1;      ///< equal increments of load and prescribed displacement (one stage)
  int max_iterations = 30; ///< Newton iterations per load step
  double rtol = 1e-10;     ///< converged when ||du|| <= rtol ||u||
  /// Linear equations (*EQUATION, mesh node numbering: a whole-mesh assembler), eliminated
  /// exactly with the supports (fem/constraint_elimination.hpp).
  std::vector<fem::LinearEquation> equations;
};

struct DirectNewtonReport
{
  bool converged = false;
  std::vector<int> iterations; ///< per load step
  double residual_norm = 0;    ///< ||r_free|| / ||f_free|| before the last correction
};

/// Solves f_int(u) = f_ext with u = prescribed values on `constrained` DOFs.
/// @param[in]  f_ext       full external load (N), global DOFs
/// @param[in,out] u        initial guess on input (usually zero), solution on output
DirectNewtonReport solve_direct_newton(const fem::Assembler& assembler, const fem::ConstrainedDofs& constrained,
                                       const la::Vector& f_ext, la::Vector& u, const DirectNewtonOptions& options = {});

/// Solves f_int(u) = f(t_n) with u = u_D(t_n) on history.dofs() at every load step n of
/// `history` (options.load_steps unused: the history has its steps).
/// @param[in,out] u  initial guess on input (usually zero), solution at the last step on output
DirectNewtonReport solve_direct_newton(const fem::Assembler& assembler, const fem::LoadHistory& history, la::Vector& u,
                                       const DirectNewtonOptions& options = {});
} // namespace feticon::nonlinear
