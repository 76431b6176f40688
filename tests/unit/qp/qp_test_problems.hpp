#pragma once
/// Small hand-built operators and bound-constrained QPs for the qp unit tests.

#include "la/operator.hpp"
#include "qp/mprgp.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

namespace feticon::test
{
/// A dense symmetric matrix as a LinearOperator that counts its applications, so that the
/// solvers' product counters can be checked against what really happened.
class CountingOperator : public la::LinearOperator
{
public:
  explicit CountingOperator(const la::Matrix& matrix) : _matrix(matrix) {}
  la::Index size() const override { return _matrix.rows(); }
  void apply(const la::Vector& x, la::Vector& y) const override
  {
    ++applications;
    y = _matrix * x;
  }
  mutable int applications = 0;

private:
  const la::Matrix& _matrix;
};

/// Jacobi preconditioner diag(A)^{-1}.
class JacobiOperator : public la::LinearOperator
{
public:
  explicit JacobiOperator(const la::Matrix& A) : _inverse_diagonal(A.diagonal().cwiseInverse()) {}
  la::Index size() const override { return _inverse_diagonal.size(); }
  void apply(const la::Vector& x, la::Vector& y) const override { y = _inverse_diagonal.cwiseProduct(x); }

private:
  la::Vector _inverse_diagonal;
};

/// min 1/2 x'Ax - b'x subject to x >= lower.
struct BoundQp
{
  la::Matrix A;
  la::Vector b;
  la::Vector lower;
};

/// A random n x n orthogonal matrix (Q factor of a Gaussian matrix).
inline la::Matrix random_orthogonal(int n, std::mt19937& generator)
{
  std::normal_distribution<double> normal;
  la::Matrix M(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      M(i, j) = normal(generator);
  return Eigen::HouseholderQR<la::Matrix>(M).householderQ();
}

/// Random SPD A = V diag(lambda) V' with eigenvalues log-spaced in [1, condition]; random b;
/// about `unbounded_fraction` of the bounds are -inf, the others scattered around the
/// unconstrained minimizer A^{-1} b so that a good fraction becomes active.
inline BoundQp random_bound_qp(int n, unsigned seed, double condition = 100.0, double unbounded_fraction = 0.2)
{
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const la::Matrix V = random_orthogonal(n, generator);
  la::Vector lambda(n);
  for (int i = 0; i < n; ++i)
    lambda[i] = std::pow(condition, n > 1 ? static_cast<double>(i) / (n - 1) : 0.0);
  BoundQp qp;
  qp.A = V * lambda.asDiagonal() * V.transpose();
  qp.A = (0.5 * (qp.A + qp.A.transpose())).eval();
  qp.b.resize(n);
  for (int i = 0; i < n; ++i)
    qp.b[i] = normal(generator);
  const la::Vector unconstrained = qp.A.ldlt().solve(qp.b);
  const double spread = std::sqrt(unconstrained.squaredNorm() / n);
  qp.lower.resize(n);
  for (int i = 0; i < n; ++i)
    qp.lower[i] = uniform(generator) < unbounded_fraction ? -std::numeric_limits<double>::infinity()
                                                          : unconstrained[i] + 0.5 * spread * normal(generator);
  return qp;
}

/// min 1/2 x'Ax - b'x subject to lower <= x <= upper.
struct BoxQp
{
  la::Matrix A;
  la::Vector b;
  la::Vector lower;
  la::Vector upper;
};

/// The random SPD A and b of random_bound_qp with each component, at random, bounded on both
/// sides (an interval around a point scattered about the unconstrained minimizer, of width
/// 0 for about one in ten of them: a fixed component), only below, only above, or not at all,
/// so that components become active at either bound.
inline BoxQp random_box_qp(int n, unsigned seed, double condition = 100.0)
{
  const BoundQp base = random_bound_qp(n, seed, condition, 0.0);
  std::mt19937 generator(seed + 7919);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const la::Vector unconstrained = base.A.ldlt().solve(base.b);
  const double spread = std::sqrt(unconstrained.squaredNorm() / n);
  constexpr double infinity = std::numeric_limits<double>::infinity();
  BoxQp qp{base.A, base.b, la::Vector::Constant(n, -infinity), la::Vector::Constant(n, infinity)};
  for (int i = 0; i < n; ++i)
  {
    const double centre = unconstrained[i] + 0.5 * spread * normal(generator);
    const double kind = uniform(generator);
    if (kind < 0.35) // both bounds
    {
      const double half_width = uniform(generator) < 0.1 ? 0.0 : 0.3 * spread * std::abs(normal(generator));
      qp.lower[i] = centre - half_width;
      qp.upper[i] = centre + half_width;
    }
    else if (kind < 0.6)
      qp.lower[i] = centre;
    else if (kind < 0.85)
      qp.upper[i] = centre;
  }
  return qp;
}

/// The 1D obstacle problem -u'' = -15 on (0,1), u(0) = u(1) = 0, u >= sin(4 pi x - pi/6)/2 - 2
/// at n interior points x_i = i h, h = 1/(n+1): A = tridiag(-1, 2, -1)/h^2, b = -15.
inline BoundQp obstacle_problem(int n)
{
  const double h = 1.0 / (n + 1);
  BoundQp qp;
  qp.A = la::Matrix::Zero(n, n);
  qp.b = la::Vector::Constant(n, -15.0);
  qp.lower.resize(n);
  for (int i = 0; i < n; ++i)
  {
    qp.A(i, i) = 2.0 / (h * h);
    if (i > 0)
      qp.A(i, i - 1) = qp.A(i - 1, i) = -1.0 / (h * h);
    const double x = (i + 1) * h;
    qp.lower[i] = 0.5 * std::sin(4.0 * std::numbers::pi * x - std::numbers::pi / 6.0) - 2.0;
  }
  return qp;
}

/// sqrt(sum of squares) of the projected gradient g_P of x (x >= lower assumed).
inline double projected_gradient_norm(const la::Vector& x, const la::Vector& g, const la::Vector& lower)
{
  double sum = 0.0;
  for (la::Index i = 0; i < x.size(); ++i)
  {
    const double gp = x[i] > lower[i] ? g[i] : std::min(g[i], 0.0);
    sum += gp * gp;
  }
  return std::sqrt(sum);
}

/// sqrt(sum of squares) of the projected gradient g_P of x in the box (l <= x <= u assumed):
/// g_i where l_i < x_i < u_i, min(g_i, 0) at x_i = l_i < u_i, max(g_i, 0) at x_i = u_i > l_i.
inline double projected_gradient_norm(const la::Vector& x, const la::Vector& g, const la::Vector& lower,
                                      const la::Vector& upper)
{
  double sum = 0.0;
  for (la::Index i = 0; i < x.size(); ++i)
  {
    double gp = g[i];
    if (lower[i] == upper[i])
      gp = 0.0;
    else if (x[i] == lower[i])
      gp = std::min(g[i], 0.0);
    else if (x[i] == upper[i])
      gp = std::max(g[i], 0.0);
    sum += gp * gp;
  }
  return std::sqrt(sum);
}
/// Sizes and seeds of the random bound-constrained QPs of the MPRGP tests.
inline constexpr int sizes[] = {5, 12, 25, 40, 60};
inline constexpr unsigned seeds[] = {1, 2, 3, 4, 5, 6};
/// Every MPRGP test runs with each expansion step (qp/mprgp.hpp).
inline constexpr qp::MprgpExpansion expansions[] = {qp::MprgpExpansion::standard, qp::MprgpExpansion::projected_cg};
inline std::string expansion_name(qp::MprgpExpansion e) { return e == qp::MprgpExpansion::standard ? "std" : "projcg"; }

/// The largest eigenvalue of a dense symmetric matrix.
inline double largest_eigenvalue(const la::Matrix& A)
{
  return Eigen::SelfAdjointEigenSolver<la::Matrix>(A).eigenvalues().maxCoeff();
}
} // namespace feticon::test
