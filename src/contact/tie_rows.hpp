#pragma once
/// @file The rows of the problem's ties (fem::Tie: deck *TIE, a PRESSURE-OVERCLOSURE=TIED pair,
/// problem file `ties:`), made once in the reference configuration before a solve.
///
/// Which slave nodes. The node-to-segment closest point of every slave node on the master
/// surface (contact_constraints.hpp) gives its distance g; a node with |g| <= the position
/// tolerance is tied, the others stay free (CalculiX leaves them untied with a warning too),
/// and so does a slave node that is also a master node (it is one node already). With ADJUST
/// (the default, as in CalculiX) the tied nodes first move by -g n onto the master surface.
///
/// The rows. Tied slave node j gets, in every component i that is not eliminated,
///   u_i(j) - sum_a w_ja u_i(a) = 0,
/// with the weights of its dual mortar row (mortar_constraints.hpp: w_ja = M_ja / D_j,
/// renormalized to sum 1 at a rim, Popp's transformed basis on quadratic slave faces) or, for a
/// node-to-segment tie, a node-based slave surface or a node whose mortar overlap is below
/// ContactOptions::mortar_min_overlap, the master shape functions at its closest point. The mortar
/// rows pass the patch test on non-matching meshes: a uniform traction across the tie gives both
/// sides their consistent nodal forces (sum_j M_ja / D_j f_j = int N_a t dA), so a constant
/// stress is the exact solution; node-to-segment rows reproduce any linear displacement but not
/// the forces (ALGORITHMS.md section 10, "Mortar tying").
///
/// Independence, which lets FETI scale the rows one by one instead of orthonormalizing them
/// (decomposition/constraint_rows.hpp): each row has its own slave DOF with coefficient 1.
/// A slave DOF is skipped, and counted, if the supports of every step hold it (the support
/// wins, as in CalculiX), if a linear equation (*EQUATION) names it, or if an earlier tie made
/// it the slave DOF of a row (two ties sharing slave nodes). Chains (a master node of one tie
/// the slave node of another) are fine; a cycle of ties through the same nodes is not detected.
///
/// Usage (app/problem_setup.cpp, after the contact ADJUST):
///   for (const TieReport& r : tie_surfaces(problem)) log::info(describe(r));

#include "fem/problem.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace feticon::contact
{
/// What tie_surfaces did for one tie.
struct TieReport
{
  std::string name;
  double tolerance = 0;            ///< position tolerance used (m)
  int64_t slave_nodes = 0;         ///< of the slave surface (its node set where given)
  int64_t tied_nodes = 0;          ///< within the tolerance
  int64_t moved_nodes = 0;         ///< ADJUST moved them
  int64_t closest_point_nodes = 0; ///< tied by node-to-segment weights in a mortar tie
  int64_t rows = 0;
  int64_t skipped_dofs = 0; ///< held by supports, named by an equation or tied before
};

/// The fraction of the master faces' mean edge length that is the default position tolerance.
inline constexpr double default_tie_tolerance = 0.025;

/// Fills problem.tie_equations from problem.ties (file comment), moving the tied slave nodes
/// where ADJUST asks, and returns one report per tie.
/// @throws feticon::Error naming the tie if no slave node lies within its position tolerance
std::vector<TieReport> tie_surfaces(fem::Problem& problem);

/// "tie T1: 121 of 125 slave nodes tied (position tolerance 2.5e-4 m; 4 beyond it), 363 rows".
std::string describe(const TieReport& report);
} // namespace feticon::contact
