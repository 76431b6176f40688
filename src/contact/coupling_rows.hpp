#pragma once
/// @file The rows of the problem's kinematic couplings (fem::Coupling, fem/coupling.hpp: *RIGID
/// BODY, *COUPLING with *KINEMATIC), appended to fem::Problem::tie_equations after the ties' rows
/// (contact/tie_rows.hpp), as the same kind of row: its own slave DOF with coefficient 1, the
/// only row where that DOF comes first, so that FETI scales them one by one.
///
/// Each coupled component but the coupling's anchors gets u_s - sum_a alpha_a u_a = 0. A slave
/// DOF is skipped, and counted, if the supports of every step hold it, an equation (*EQUATION)
/// names it, or a tie or an earlier coupling made it the slave DOF of a row (a node in two rigid
/// bodies: the second one's rows leave it to the first).
///
/// Usage (app/problem_setup.cpp, after contact::tie_surfaces):
///   for (const CouplingReport& r : couple_surfaces(problem)) log::info(describe(r));

#include "fem/problem.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace feticon::contact
{
/// What couple_surfaces did for one coupling.
struct CouplingReport
{
  std::string name;
  bool pretension = false;  ///< a pretension section (its nodes are pairs, its rank the gap)
  int64_t nodes = 0;        ///< coupled nodes
  int64_t anchors = 0;      ///< components that carry the rigid motion (its rank)
  int64_t rows = 0;         ///< one per other coupled component
  int64_t skipped_dofs = 0; ///< held by supports, named by an equation or slave of a row before
};

/// Appends the kinematic couplings' and pretension sections' rows to problem.tie_equations (tie_of_equation -1 - the
/// coupling's index) and
/// returns one report per kinematic coupling.
std::vector<CouplingReport> couple_surfaces(fem::Problem& problem);

/// The rows and held combinations of a load step's equality block at displacement u with finite
/// rotations: `ties` (problem.tie_equations_in_force of the step) with the rows of every rank-6
/// kinematic coupling linearized at u (each with its rhs), and problem.held_combinations() with
/// those couplings' reference DOFs linearized at u (with their offsets). Rebuilt every outer
/// iteration, the rows hold x_i = X_ref + t + R (X_i - X_ref) once the iteration has converged.
struct CouplingLinearization
{
  std::vector<fem::LinearEquation> ties;
  std::vector<fem::DofCombination> held;
};
CouplingLinearization linearize_couplings(const fem::Problem& problem, std::vector<fem::LinearEquation> ties,
                                          const la::Vector& u);

/// "rigid body RB1: 25 nodes, 6 anchors, 69 rows".
std::string describe(const CouplingReport& report);
} // namespace feticon::contact
