#pragma once
/// @file Settings of the contact solvers (plain struct with documented defaults).

#include "contact/contact_constraints.hpp"
#include "decomposition/generalized_inverse.hpp"
#include "dual/dual_penalty_problem.hpp"
#include "fem/material.hpp"

#include <string>

namespace feticon::nonlinear
{
enum class ContactMethod
{
  smalbe,        ///< FETI, SMALBE-M + MPRGP (G lambda = e exact)
  dual_penalty,  ///< FETI, MPRGP on the seed's problem (9)
  primal_penalty ///< undecomposed, penalty springs eps_n <g>, CHOLMOD
};

/// Which stiffness the FETI outer loop uses (ALGORITHMS.md section 8). Never the full
/// tangent K_T: for a stressed floating subdomain its kernel is not the rigid modes.
enum class StiffnessUpdate
{
  initial,   ///< K_0 assembled and factorized once (the seed's modified Newton–Raphson)
  load_step, ///< K_M(u) with R from x = X + u, refreshed at the start of every load step
  iteration  ///< K_M(u) refreshed at every outer iteration
};

struct SolverSettings
{
  ContactMethod method = ContactMethod::smalbe;
  fem::Kinematics kinematics = fem::Kinematics::linear;
  int load_steps = 1;                  ///< equal load increments
  int max_outer_iterations = 15;       ///< outer (Newton) iterations per load step
  double displacement_tolerance = 1e-6; ///< ||du|| <= tol ||u|| ends a load step
  StiffnessUpdate stiffness = StiffnessUpdate::initial;
  int subdomains = 8;
  bool metis = true;                   ///< METIS, else structured partition
  decomposition::GeneralizedInverseMethod generalized_inverse =
      decomposition::GeneralizedInverseMethod::fixing_dofs;
  dual::DualPenaltyOptions dual{};
  double search_distance = 0;          ///< 0: automatic (about one master element)
  contact::ContactFormulation formulation = contact::ContactFormulation::mortar;
  double eps_n_factor = 100;           ///< primal penalty eps_n = factor * max diag K
};
} // namespace feticon::nonlinear
