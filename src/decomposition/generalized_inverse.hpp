#pragma once
/// @file Generalized inverse K+ (K K+ K = K) of a floating subdomain stiffness.
///
/// Two exact variants (ALGORITHMS.md section 2), both with one CHOLMOD factorization that
/// is reused for every application:
///  - fixing_dofs: remove k DOFs (k = dim ker K) at three far-apart fixing nodes, chosen by
///    a pivoted QR of R restricted to those nodes so that the removed block of R is well
///    conditioned; then K+ = P' [K_rr^{-1} 0; 0 0] P. Same sparsity as K.
///  - regularization: K_rho = K + rho C C' with C = R on the fixing-node DOFs and zero
///    elsewhere, rho = max diag K; K_rho^{-1} is a generalized inverse of K (and SPD, so
///    K+ is symmetric positive definite). Fills one small block between fixing nodes.
/// With k = 0 (a subdomain with no kernel) both reduce to K^{-1}.

#include "la/cholmod.hpp"
#include "la/types.hpp"

#include <vector>

namespace feticon::decomposition
{
enum class GeneralizedInverseMethod
{
  fixing_dofs,
  regularization
};

/// Three far-apart, non-collinear nodes: a farthest from the centroid, b farthest from a,
/// c maximizing the area of triangle abc.
std::vector<int32_t> choose_fixing_nodes(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& coords);

class GeneralizedInverse
{
public:
  /// @param K                 symmetric positive semidefinite stiffness (active DOFs)
  /// @param R                 orthonormal kernel basis of K
  /// @param fixing_candidates active DOFs of the fixing nodes
  /// @param what              name used in error messages (e.g. "subdomain 3")
  /// @param precision         what the factor is kept in (la/single_precision_factor.hpp)
  void setup(const la::SparseMatrix& K, const la::Matrix& R, const std::vector<int32_t>& fixing_candidates,
             GeneralizedInverseMethod method, const std::string& what,
             la::FactorPrecision precision = la::FactorPrecision::double_precision);

  /// K+ b.
  la::Vector apply(const la::Vector& b) const;
  la::Matrix apply(const la::Matrix& B) const;
  /// Nonzeros of the Cholesky factor.
  long factor_nonzeros() const { return _factor.factor_nonzeros(); }

  /// What defines K+ besides K, for forming it on a set of DOFs another way
  /// (explicit_boundary_operators.hpp): the method; fixing_dofs: the removed DOFs;
  /// regularization: the fixing-node DOFs and rho C C' on them.
  GeneralizedInverseMethod method() const { return _method; }
  const std::vector<int32_t>& fixing_dofs() const { return _fixing; }
  const la::Matrix& regularization() const { return _regularization; }

private:
  GeneralizedInverseMethod _method = GeneralizedInverseMethod::fixing_dofs;
  la::Index _n = 0;
  std::vector<int32_t> _fixing;
  la::Matrix _regularization;
  std::vector<int32_t> _kept; ///< fixing_dofs: DOFs kept in K_rr, in order
  la::CholmodFactor _factor;
};
} // namespace feticon::decomposition
