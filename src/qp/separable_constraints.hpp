#pragma once
/// @file The feasible set of a contact QP: separable convex constraints, one set per component
/// or per pair of components. Bounds l_i <= x_i <= u_i hold the normal contact multipliers
/// (lambda_N >= 0) and, in 2D, Tresca's tangential box |lambda_T| <= g; a disc
/// ||(x_i, x_j)|| <= r holds the two tangential multipliers of one contact node in 3D.
/// MPRGP solves QPs on bounds, MPGP on bounds and discs (qp::QpSolver).

#include "la/types.hpp"

#include <vector>

namespace feticon::qp
{
/// ||(x_i, x_j)|| <= radius, radius >= 0; i and j have no bounds.
struct Disc
{
  la::Index i = 0, j = 0;
  double radius = 0;
};

struct SeparableConstraints
{
  la::Vector lower; ///< l, -infinity where unbounded
  /// u, +infinity where unbounded; empty: no upper bounds (MPRGP then runs the arithmetic of
  /// its lower-bound algorithm, which equals the box algorithm with u = +infinity bitwise).
  la::Vector upper;
  std::vector<Disc> discs;
};
} // namespace feticon::qp
