#pragma once
/// @file Extreme eigenvalues of the operator a CG run worked on, from the run's own
/// coefficients (no extra operator products).
///
/// A run of k preconditioned CG steps with step lengths alpha_j and direction coefficients
/// beta_j (p_{j+1} = z_{j+1} + beta_j p_j) is k steps of Lanczos on M A; its tridiagonal
/// (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., sec. 6.7.3)
///
///     T_jj = 1/alpha_j + beta_{j-1}/alpha_{j-1},   T_{j,j+1} = sqrt(beta_j)/alpha_j,
///
/// has eigenvalues (Ritz values) inside the spectrum of M A whose extremes approach its
/// ends as the run grows. MPRGP restarts the recurrence at every expansion and
/// proportioning step, so the estimate keeps the longest run of a solve.

#include "qp/qp_report.hpp"

#include <vector>

namespace feticon::qp
{
class RitzEstimate
{
public:
  /// One CG step of length alpha; beta is the coefficient of the next direction (>= 0 in
  /// exact arithmetic; round-off below 0 is taken as 0).
  void cg_step(double alpha, double beta);
  /// The CG recurrence restarts (a step that is not a CG step).
  void end_run();
  /// The Ritz values of the longest run (the current one included); all 0 when no run
  /// had two steps.
  RitzValues longest_run();

private:
  std::vector<double> _alpha, _beta;           ///< current run
  std::vector<double> _best_alpha, _best_beta; ///< longest finished run
};
} // namespace feticon::qp
