/// The three clauses of the outer loop's stopping test (nonlinear/outer_convergence.hpp): each
/// failing clause alone keeps the loop going, and a round-off correction ends the step only
/// with the residual test, or at a floor that the run reports (never "converged" with the
/// residual above eps_r). Reference: the rule as ALGORITHMS.md section 8 states it.
#include "nonlinear/outer_convergence.hpp"

#include <gtest/gtest.h>

namespace feticon::nonlinear
{
namespace
{
TEST(OuterConvergence, NeedsDisplacementResidualAndAnUnchangedActiveSet)
{
  const OuterConvergence test{1e-4, 1e-4, 2.0};
  const std::set<int64_t> active{1, 2, 3}, grown{1, 2, 3, 4};
  // ||du|| = 1e-6, ||u|| = 1: the displacement clause holds; ||du||_inf 1e-7 is above the floor 2e-9.
  EXPECT_EQ(test.verdict(1e-6, 1.0, 1e-7, 1e-5, active, active), OuterVerdict::converged);
  EXPECT_EQ(test.verdict(1e-3, 1.0, 1e-4, 1e-5, active, active), OuterVerdict::iterate) << "displacement";
  EXPECT_EQ(test.verdict(1e-6, 1.0, 1e-7, 1e-3, active, active), OuterVerdict::iterate) << "residual";
  EXPECT_EQ(test.verdict(1e-6, 1.0, 1e-7, 1e-5, grown, active), OuterVerdict::iterate) << "active set";
}

TEST(OuterConvergence, RoundOffCorrectionIsNoShortcutPastTheResidual)
{
  const OuterConvergence test{1e-4, 1e-4, 2.0};
  EXPECT_DOUBLE_EQ(test.roundoff_displacement(), 2e-9);
  const std::set<int64_t> active{1, 2, 3}, grown{1, 2, 3, 4};
  // u near 0: ||du|| / ||u|| = 1 is noise, the round-off correction meets the displacement clause.
  EXPECT_EQ(test.verdict(1e-12, 1e-12, 1e-12, 1e-5, active, active), OuterVerdict::converged);
  // Round-off correction, residual 0.9: not converged. The contact set changed: iterate on.
  EXPECT_EQ(test.verdict(1e-12, 1e-12, 1e-12, 0.9, grown, active), OuterVerdict::iterate);
  // The same set: another iteration repeats this one, a floor the run reports.
  EXPECT_EQ(test.verdict(1e-12, 1.0, 1e-12, 0.9, active, active), OuterVerdict::floor);
  // A correction above round-off never stops at the floor.
  EXPECT_EQ(test.verdict(1e-6, 1.0, 3e-9, 0.9, active, active), OuterVerdict::iterate);
  // Nor does a residual that still at least halved since the iteration before (modified
  // Newton on K_0, contracting linearly: its corrections fall below 1e-9 L first).
  EXPECT_EQ(test.verdict(1e-12, 1.0, 1e-12, 0.9, active, active, 2.0), OuterVerdict::iterate);
  EXPECT_EQ(test.verdict(1e-12, 1.0, 1e-12, 0.9, active, active, 1.0), OuterVerdict::floor);
}
} // namespace
} // namespace feticon::nonlinear
