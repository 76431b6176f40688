#pragma once
/// @file Linear multi-point constraints (CalculiX / Abaqus *EQUATION, fem::LinearEquation)
/// sum_k a_k u(node_k, component_k) = 0, reduced against the prescribed displacements: what
/// every solver starts from (FETI rows in decomposition/constraint_rows.hpp, elimination for
/// the undecomposed solves in fem/constraint_elimination.hpp).
///
/// A term on a prescribed DOF (a support, or a component eliminated for the whole problem,
/// whose value is 0) has a known value: it moves to the right-hand side, so the reduced
/// equation sum_{k free} a_k u_k = rhs = -sum_{k prescribed} a_k u_k touches free DOFs only.
/// That is the equation orthogonalized against the Dirichlet rows (unit rows on the prescribed
/// DOFs): on their feasible set both say the same. Terms on the same DOF are summed.

#include "fem/problem.hpp"

#include <array>
#include <string>
#include <vector>

namespace feticon::fem
{
/// One equation over free DOFs: sum_k coefficients[k] u(dofs[k]) = rhs.
struct ReducedEquation
{
  std::vector<int64_t> dofs;        ///< global DOFs 3 node + component, increasing
  std::vector<double> coefficients; ///< nonzero
  double rhs = 0;                   ///< -sum of the prescribed terms (m times the coefficients)
};

/// Relative size below which what is left of an equation, once the supports and the equations
/// before it are taken out, counts as nothing: the equation is linearly dependent on them.
/// Far above round-off (1e-16) and far below any coefficient a model would mean.
inline constexpr double equation_dependence_tolerance = 1e-10;

/// The equations reduced against `prescribed` (and the `eliminated` components, zero on every
/// node), in the order given.
/// @param n_dofs 3 per mesh node
/// @param mesh   for the coordinates of the nodes in messages (may be null)
/// @throws feticon::Error naming the equation (describe_equation) if it names a node outside
///         the mesh or has no free term left: every term lies on a prescribed or eliminated
///         component, so the equation repeats the supports or contradicts them.
std::vector<ReducedEquation> reduce_equations(const std::vector<LinearEquation>& equations, int64_t n_dofs,
                                              const ConstrainedDofs& prescribed,
                                              const std::array<bool, 3>& eliminated = {false, false, false},
                                              const mesh::Mesh* mesh = nullptr);

/// "linear equation 2 of 5 (1 u_x at node 17 (1, 0.5, 1) - 1 u_x at node 40 (...) = 0)": for
/// messages (1-based: the order of a deck's *EQUATION blocks; nodes are mesh indices, with their
/// coordinates if `mesh` is given).
std::string describe_equation(const std::vector<LinearEquation>& equations, size_t index,
                              const mesh::Mesh* mesh = nullptr);

/// The one-line message for equation `index`, which is linearly dependent on the supports and the
/// equations before it.
std::string dependent_equation_message(const std::vector<LinearEquation>& equations, size_t index,
                                       const mesh::Mesh* mesh = nullptr);
} // namespace feticon::fem
