/// A linear run's QP gets only the contact rows near contact (nonlinear/linear_contact_rows.hpp).
/// Reference: the same run with every candidate row within the search distance (band 1e300,
/// the QP of Vondrák et al. 2007). The left-out rows are inactive at the answer, so both QPs have the
/// same solution: displacements and peak pressure agree to the QP tolerance (1e-8 relative on
/// the projected gradient; 1e-6 allows for the conditioning of the two dual problems), and the
/// answer satisfies every candidate row (linearized gap >= 0, multiplier >= 0, zero
/// multiplier on an open row): the KKT conditions of the QP with all of them.

#include "problems/hertz.hpp"
#include "tests/support/feti_contact_run.hpp"

#include <gtest/gtest.h>

#include <cstdio>

using namespace feticon;

namespace
{
test::FetiContactRun run_with_band(const fem::Problem& problem, double band,
                                   dual::DualPreconditioner preconditioner = dual::DualPreconditioner::dirichlet)
{
  nonlinear::SolverSettings s;
  s.kinematics = fem::Kinematics::linear;
  s.load_steps = 1;
  s.dual.preconditioner = preconditioner;
  s.linear_contact_band = band;
  return test::run_feti_contact(problem, s);
}
} // namespace

TEST(LinearContactRows, RowsNearContactGiveTheAnswerOfEveryRow)
{
  problems::HertzParameters parameters;
  parameters.mesh.refinement = 1;
  const fem::Problem problem = problems::hertz_problem(parameters);
  const test::FetiContactRun every = run_with_band(problem, 1e300);
  const test::FetiContactRun near = run_with_band(problem, 0.25);   // the default
  const test::FetiContactRun narrow = run_with_band(problem, 0.02); // too few rows at first: more QPs
  const test::FetiContactRun lumped =
      run_with_band(problem, 0.25, dual::DualPreconditioner::lumped); // no Schur boundary
  std::printf("MPRGP steps: every row %d, band 0.25 %d, band 0.02 %d in %zu QPs; dual sizes %lld / %lld\n", every.mprgp,
              near.mprgp, narrow.mprgp, narrow.solution.history.size(), static_cast<long long>(every.solution.n_dual),
              static_cast<long long>(near.solution.n_dual));
  EXPECT_EQ(every.solution.history.size(), 1u);
  EXPECT_GE(narrow.solution.history.size(), 2u);
  EXPECT_LT(near.solution.n_dual, every.solution.n_dual);
  EXPECT_LT(lumped.solution.n_dual, every.solution.n_dual);
  for (const test::FetiContactRun* r : {&near, &narrow, &lumped})
  {
    EXPECT_LT((r->solution.u - every.solution.u).norm(), 1e-6 * every.solution.u.norm());
    EXPECT_NEAR(r->peak, every.peak, 1e-6 * every.peak);
    // The output holds every candidate row, and the answer satisfies all of them.
    const contact::ContactConstraints& rows = r->solution.constraints;
    ASSERT_EQ(rows.n_rows(), every.solution.constraints.n_rows());
    const la::Vector gap = rows.c - rows.B * r->solution.u; // normalized, m / |b_i|
    const double tolerance = 1e-6 * r->solution.u.cwiseAbs().maxCoeff();
    const double lambda_max = r->solution.contact_lambda.maxCoeff();
    for (la::Index i = 0; i < gap.size(); ++i)
    {
      EXPECT_GT(gap(i), -tolerance) << "row " << i;
      EXPECT_GT(r->solution.contact_lambda(i), -1e-8 * lambda_max) << "row " << i;
      if (gap(i) > tolerance)
      {
        EXPECT_LT(r->solution.contact_lambda(i), 1e-8 * lambda_max) << "row " << i;
      }
    }
  }
}
