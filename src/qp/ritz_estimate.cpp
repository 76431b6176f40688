#include "qp/ritz_estimate.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace feticon::qp
{
void RitzEstimate::cg_step(double alpha, double beta)
{
  _alpha.push_back(alpha);
  _beta.push_back(std::max(beta, 0.0));
}

void RitzEstimate::end_run()
{
  if (_alpha.size() > _best_alpha.size())
  {
    _best_alpha.swap(_alpha);
    _best_beta.swap(_beta);
  }
  _alpha.clear();
  _beta.clear();
}

RitzValues RitzEstimate::longest_run()
{
  end_run();
  // The first 500 steps: the leading block of the Lanczos matrix is that of a 500-step run, so
  // its Ritz values are exact for it, and the dense solver below stays small and fast whatever
  // the run's length (a stalled QP of 20 000 steps: docs/measurements.md).
  constexpr Eigen::Index max_steps = 500;
  constexpr double ghost_tolerance = 1e-3;
  const Eigen::Index k = std::min(static_cast<Eigen::Index>(_best_alpha.size()), max_steps);
  if (k < 2)
    return {};
  // The last beta belongs to a direction the run never used.
  Eigen::VectorXd diagonal(k), off_diagonal(k - 1);
  for (Eigen::Index j = 0; j < k; ++j)
  {
    diagonal[j] = 1.0 / _best_alpha[j];
    if (j > 0)
    {
      diagonal[j] += _best_beta[j - 1] / _best_alpha[j - 1];
      off_diagonal[j - 1] = std::sqrt(_best_beta[j - 1]) / _best_alpha[j - 1];
    }
  }
  // The dense solver, not computeFromTridiagonal: Eigen 3.4's tridiagonal QR reported no
  // convergence on a 53-step run of a Hertz QP whose dense eigenvalues are [1.00007, 66.68],
  // and the estimate went missing; k is at most max_steps.
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(k, k);
  T.diagonal() = diagonal;
  T.diagonal(1) = off_diagonal;
  T.diagonal(-1) = off_diagonal;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(T, Eigen::EigenvaluesOnly);
  if (eigen.info() != Eigen::Success)
    return {};
  const Eigen::VectorXd& values = eigen.eigenvalues(); // ascending
  std::vector<double> distinct;
  for (const double value : values)
    if (distinct.empty() || value > distinct.back() * (1 + ghost_tolerance))
      distinct.push_back(value);
  return {values[0], values[k - 1], static_cast<int>(k), std::move(distinct)};
}
} // namespace feticon::qp
