/// The three clauses of the outer loop's stopping test and its round-off floor
/// (nonlinear/outer_convergence.hpp): each failing clause alone keeps the loop going.
#include "nonlinear/outer_convergence.hpp"

#include <gtest/gtest.h>

namespace feticon::nonlinear
{
namespace
{
TEST(OuterConvergence, NeedsDisplacementResidualAndAnUnchangedActiveSet)
{
  const OuterConvergence test{1e-4, 1e-4, 2.0};
  const std::set<int32_t> active{1, 2, 3}, grown{1, 2, 3, 4};
  // ||du|| = 1e-6, ||u|| = 1: the displacement clause holds; ||du||_inf 1e-7 is above the floor 2e-9.
  EXPECT_TRUE(test.converged(1e-6, 1.0, 1e-7, 1e-5, active, active));
  EXPECT_FALSE(test.converged(1e-3, 1.0, 1e-4, 1e-5, active, active)) << "displacement";
  EXPECT_FALSE(test.converged(1e-6, 1.0, 1e-7, 1e-3, active, active)) << "residual";
  EXPECT_FALSE(test.converged(1e-6, 1.0, 1e-7, 1e-5, grown, active)) << "active set";
  // A round-off correction (||du||_inf <= 1e-9 L) ends the step whatever the relative figures.
  EXPECT_TRUE(test.converged(1e-12, 1e-12, 1e-12, 0.9, grown, active));
}
} // namespace
} // namespace feticon::nonlinear
