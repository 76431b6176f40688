#pragma once
/// @file Estimate of ||A|| = lambda_max(A) of a symmetric positive (semi)definite operator.
///
/// Power iteration v <- Av/||Av|| from a deterministic pseudo-random unit vector; the Rayleigh
/// quotient nu_k = v'Av rises toward lambda_max from below (ALGORITHMS.md section 5, "||A||
/// estimate"). MPRGP uses it to choose its expansion step length alpha_bar = 1.8/nu; the
/// dual layer uses it to scale F.
///
/// Usage:
///   const qp::NormEstimate norm = qp::estimate_norm(A);
///   const double alpha_bar = 1.8 / norm.value;

#include "la/operator.hpp"
#include "la/vector_space.hpp"

namespace feticon::qp
{
/// The estimate and what it cost.
struct NormEstimate
{
  /// Last Rayleigh quotient v'Av with ||v|| = 1: a lower bound of lambda_max for symmetric A.
  double value = 0.0;
  /// Applications of the operator spent (one per power iteration).
  int applications = 0;
};

/// @brief Power iteration for the largest eigenvalue of a symmetric positive (semi)definite
///        operator.
/// @param[in] A               the operator; only apply() is used.
/// @param[in] max_iterations  at most this many applications of A (>= 1).
/// @param[in] rtol            stop once |nu_k - nu_{k-1}| <= rtol |nu_k|.
/// @param[in] seed            seed of the start vector; equal seeds give equal results.
/// @return the estimate; value 0 (and 1 application) when A annihilates the start vector,
///         value 0 with 0 applications when A has size 0. For an indefinite A the value
///         approximates an extreme eigenvalue and may be negative.
///
/// The start vector is a function of the global index in A's space(), so the result does not
/// depend on how the entries are distributed over ranks.
NormEstimate estimate_norm(const la::LinearOperator& A, int max_iterations = 30, double rtol = 1e-3, unsigned seed = 1);
} // namespace feticon::qp
