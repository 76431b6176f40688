/// MPRGP with preconditioning in the face (MprgpOptions::preconditioner).

#include "qp/mprgp.hpp"
#include "qp_test_problems.hpp"
#include "reference_qp.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace feticon;

namespace
{
class DenseOperator : public la::LinearOperator
{
public:
  explicit DenseOperator(la::Matrix A) : _A(std::move(A)) {}
  la::Index size() const override { return _A.rows(); }
  void apply(const la::Vector& x, la::Vector& y) const override { y = _A * x; }

private:
  la::Matrix _A;
};
} // namespace

// Reference: the dense active-set solution (reference_qp.hpp), independent of MPRGP. A
// preconditioner changes the path, not the minimizer: with the exact inverse and with a
// Jacobi (diagonal) preconditioner MPRGP must reach the same x to 1e-8, and on a badly
// scaled problem Jacobi must need fewer steps than no preconditioner.
TEST(MprgpPreconditioned, SameMinimizerAndFewerStepsOnABadlyScaledProblem)
{
  for (unsigned seed : {3u, 11u, 29u})
  {
    test::BoundQp problem = test::random_bound_qp(40, seed, 50.0);
    // Bad row/column scaling, which Jacobi undoes.
    la::Vector scale(40);
    for (int i = 0; i < 40; ++i)
      scale(i) = std::pow(10.0, (i % 5) - 2.0);
    problem.A = scale.asDiagonal() * problem.A * scale.asDiagonal();
    problem.b = scale.asDiagonal() * problem.b;
    problem.lower = problem.lower.cwiseQuotient(scale);
    const la::Vector reference = test::reference_bound_qp(problem.A, problem.b, problem.lower);

    const DenseOperator A(problem.A);
    const DenseOperator jacobi(la::Matrix(problem.A.diagonal().cwiseInverse().asDiagonal()));
    const DenseOperator exact(problem.A.inverse());
    int steps[3];
    int k = 0;
    for (const la::LinearOperator* M :
         {static_cast<const la::LinearOperator*>(nullptr), static_cast<const la::LinearOperator*>(&jacobi),
          static_cast<const la::LinearOperator*>(&exact)})
    {
      qp::MprgpOptions options;
      options.rtol = 1e-12;
      options.max_iterations = 100000;
      options.preconditioner = M;
      qp::Mprgp mprgp(A, options);
      la::Vector x = la::Vector::Zero(40);
      const qp::QpReport report = mprgp.solve(problem.b, problem.lower, x);
      ASSERT_TRUE(report.converged) << report.reason;
      EXPECT_LT((x - reference).norm() / reference.norm(), 1e-8) << "seed " << seed << " case " << k;
      EXPECT_TRUE((x.array() >= problem.lower.array()).all());
      steps[k++] = report.iterations;
    }
    std::printf("seed %u: MPRGP steps none %d, Jacobi %d, exact inverse %d\n", seed, steps[0], steps[1], steps[2]);
    EXPECT_LT(steps[1], steps[0]);
  }
}
