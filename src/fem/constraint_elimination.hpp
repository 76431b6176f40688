#pragma once
/// @file Prescribed DOFs and linear equations (*EQUATION) eliminated for the direct solves of
/// undecomposed problems (direct Newton, primal penalty, bonded direct solve).
///
///   u = T v + g,   (T' K T) v = T' (f - K g),
///
/// v the independent free DOFs. Each equation (fem/linear_equations.hpp: reduced against the
/// prescribed DOFs) makes one free DOF dependent, u_p = sum_j e_j u_j + e_0 over independent
/// DOFs j: Gauss-Jordan elimination over the equations in order, the pivot of each being its
/// largest coefficient once the earlier dependent DOFs are substituted (partial pivoting, as
/// for a master-slave transformation; CalculiX takes the first term instead). T' K T is
/// symmetric positive definite whenever the constrained problem is well posed, so CHOLMOD
/// applies, and the constraint holds exactly (to round-off), unlike a penalty, which would
/// add an O(1/penalty) error and worsen the conditioning. Without equations, T selects the
/// free DOFs and every operation is DirichletElimination's, to the bit.

#include "fem/dirichlet.hpp"
#include "fem/problem.hpp"

#include <vector>

namespace feticon::fem
{
class ConstraintElimination
{
public:
  /// @param n_dofs     3 per mesh node
  /// @param prescribed prescribed DOFs and values (for a whole problem: all_constrained_dofs(),
  ///                   which holds the eliminated components too)
  /// @param equations  linear equations on the mesh's nodes (none: Dirichlet elimination alone)
  /// @param mesh       for the node coordinates in messages (may be null)
  /// @throws feticon::Error naming the equation if one has no free term or is linearly
  ///         dependent on the supports and the equations before it
  ConstraintElimination(int64_t n_dofs, const ConstrainedDofs& prescribed,
                        const std::vector<LinearEquation>& equations = {}, const mesh::Mesh* mesh = nullptr);

  int64_t n_free() const;
  /// T' K T (K in full symmetric storage).
  la::SparseMatrix reduce_matrix(const la::SparseMatrix& K) const;
  /// T' (f - K g).
  la::Vector reduce_rhs(const la::SparseMatrix& K, const la::Vector& f) const;
  /// T' r: a force on all DOFs as a force on v (the free part without equations).
  la::Vector reduce_force(const la::Vector& r) const;
  /// T v + g.
  la::Vector expand(const la::Vector& v) const;
  /// Sets the prescribed values of u and its dependent DOFs from its independent ones, so that u
  /// satisfies every constraint.
  void impose(la::Vector& u) const;

private:
  int64_t _n_dofs;
  DirichletElimination _dirichlet;
  bool _with_equations = false;
  la::SparseMatrix _T;               ///< n_dofs x n_free
  la::SparseMatrix _Tt;              ///< T'
  la::Vector _g;                     ///< prescribed values and the equations' constants
  std::vector<int64_t> _independent; ///< the DOF of every column of T
};
} // namespace feticon::fem
