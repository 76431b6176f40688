#pragma once
/// @file Tangential contact rows for friction (issue 39; Dostál et al., J. Comput. Appl. Math.
/// 235 (2010) for 2D, Scalable Algorithms for Contact Problems (2016) for 3D), made from the
/// normal rows of contact_constraints.hpp / mortar_constraints.hpp. A normal row
///   b_i = (-n at slave s, w_a n at master node a) / |b|
/// gives, for each unit tangent t_k of n, the tangential row
///   b_ik = (-t_k at s, w_a t_k at a) / |b|,
/// with the same weights (node-to-segment or dual mortar) and norm, so that B_T B_T' has a unit
/// diagonal like B_I B_I'. Its multiplier lambda_hat_ik is the scaled tangential force: the
/// slave node gets +(lambda_hat_ik / |b|) t_k, the master nodes -(lambda_hat_ik / |b|) w_a t_k.
/// Tangents: in plane strain (one displacement component eliminated, e_k) one, t = e_k x n /
/// |e_k x n|, in the model's plane; in 3D two, t_1 = e x n / |e x n| with e the coordinate axis
/// least aligned with n, and t_2 = n x t_1 (an orthonormal basis of the tangent plane).
///
/// A symmetry plane through the contact (3D): where supports hold a row's slave node along a
/// direction e (a global axis, or a local one of a *TRANSFORM), n is nearly normal to e
/// (|n . e| < 0.05) and the nodes not held along e carry under 5 % of its norm (mortar weights
/// one cell row beside the plane), t_1 = e x n / |e x n| and t_2 = n x t_1 (= e where n . e = 0). The row of t_2 then nearly repeats the supports' rows (B
/// nearly rank-deficient, the QP's solution along it nearly not unique); it is kept for the
/// layout of two rows per node and marked `held`: its multiplier is fixed at 0 (by symmetry no
/// friction acts across the plane) and only t_1 takes friction, |lambda_1| <= g.
///
/// The rows' right-hand sides are the caller's: for friction, c_T = -B_T (u - u_0), the slip
/// of the current outer iteration's start since the last converged load step (u_0), so that
/// B_T du - c_T is the slip increment of the step.

#include "contact/contact_constraints.hpp"
#include "fem/node_frames.hpp"

#include <array>
#include <vector>

namespace feticon::contact
{
struct TangentialRows
{
  /// n_tangents rows per normal row: row n_tangents i + k is tangent k of normal row i, over
  /// the global DOFs 3 * node + component.
  Eigen::SparseMatrix<double, Eigen::RowMajor> B;
  std::vector<Eigen::Vector3d> tangent; ///< unit tangent of each row
  std::vector<int32_t> slave_node;      ///< slave node of each row
  std::vector<int32_t> pair;            ///< contact pair of each row (its normal row's)
  std::vector<char> held;               ///< the row's tangent is held by supports (file comment)
  int n_tangents = 0;                   ///< 1 in plane strain, 2 in 3D

  int64_t n_rows() const { return static_cast<int64_t>(tangent.size()); }
  /// contact_key of row r (its normal row's).
  int64_t key(int64_t r) const { return contact_key(pair[r], slave_node[r]); }
};

/// The unit tangents of the unit normal n: one in the plane normal to the eliminated axis
/// (eliminated[k] for exactly one k), else two (see file comment). Throws feticon::Error if
/// more than one component is eliminated.
std::vector<Eigen::Vector3d> unit_tangents(const Eigen::Vector3d& n, const std::array<bool, 3>& eliminated);

/// The tangential rows of `normal` (see file comment) over the same DOFs; `supported`: the
/// DOFs that supports hold, sorted (none if empty): global ones 3 node + component, and local
/// ones of the nodes `frames` gives local axes (fem/node_frames.hpp).
TangentialRows build_tangential_rows(const ContactConstraints& normal, const std::array<bool, 3>& eliminated,
                                     const std::vector<int64_t>& supported = {},
                                     const fem::NodeFrames* frames = nullptr);

/// The rows of pair p alone (in their order) and, if `lambda` is not empty, their entries of
/// `lambda` in `lambda_p`.
TangentialRows pair_rows(const TangentialRows& rows, int32_t p, const la::Vector& lambda, la::Vector& lambda_p);

/// Tangential forces on the structure (N, per global DOF): -B_T' lambda_hat_T.
la::Vector tangential_forces(const TangentialRows& rows, const la::Vector& lambda_hat, la::Index n_dofs);
} // namespace feticon::contact
