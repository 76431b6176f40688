/// Tests of finite-strain J2 plasticity (fem/finite_j2_plasticity.hpp). References: the
/// small-strain radial return (fem/j2_plasticity.hpp), which the model tends to as the strain
/// goes to zero; the model's own invariant (a returned state lies on the yield surface); the
/// tangent against central differences of the stress.
/// The whole model against CalculiX 2.20 at 50 % stretch: tests/cli/plasticity_nlgeom.sh.

#include "fem/finite_j2_plasticity.hpp"

#include <gtest/gtest.h>

namespace feticon::fem
{
namespace
{
Material steel()
{
  Material m{210000., 0.3};
  m.plastic.stress = {250., 450.};
  m.plastic.plastic_strain = {0., 0.5};
  return m;
}
} // namespace

TEST(FiniteJ2, SmallStrainsGiveTheSmallStrainReturn)
{
  // Uniaxial strain 1e-5 (elastic) and 4e-3 (yielded): S within O(strain) of sigma.
  for (const double e : {1e-5, 4e-3})
  {
    const Voigt strain = (Voigt() << e, -0.2 * e, 0.1 * e, 0.3 * e, 0, 0).finished();
    const J2Update small = j2_return(steel(), strain, 0, {});
    const J2Update finite = finite_j2_return(steel(), strain, {});
    EXPECT_EQ(small.plastic, finite.plastic) << e;
    EXPECT_LT((finite.stress - small.stress).norm(), 5 * e * small.stress.norm()) << e;
    EXPECT_NEAR(finite.state.equivalent_plastic_strain, small.state.equivalent_plastic_strain, 5 * e * 1e-2 + 1e-12);
  }
}

TEST(FiniteJ2, ReturnedStateLiesOnTheYieldSurface)
{
  // (Simo's update of b_e bar, which CalculiX's incplas.f uses too, does not keep det b_e bar = 1
  // exactly: no isochoric check here.)
  const Voigt strain = (Voigt() << 0.3, -0.1, -0.12, 0.05, 0.02, -0.04).finished();
  const J2Update update = finite_j2_return(steel(), strain, {});
  ASSERT_TRUE(update.plastic);
  // From the returned state at the same strain the point is elastic, on the yield surface: the
  // same stress.
  const J2Update again = finite_j2_return(steel(), strain, update.state);
  EXPECT_FALSE(again.plastic);
  EXPECT_LT((again.stress - update.stress).norm(), 1e-9 * update.stress.norm());
}

TEST(FiniteJ2, TangentIsTheStressDerivativeOrPositive)
{
  // Elastic and yielded points: the tangent is dS/dE (central differences of the return) where
  // that is positive definite; a yielded point whose dS/dE is not gets a positive one.
  for (const double e : {1e-4, 0.05})
  {
    const Voigt strain = (Voigt() << e, -0.4 * e, -0.4 * e, 0.1 * e, 0, 0).finished();
    Eigen::Matrix<double, 6, 6> tangent;
    const J2Update update = finite_j2_return(steel(), strain, {}, &tangent);
    const bool positive = Eigen::LLT<Eigen::Matrix<double, 6, 6>>(tangent).info() == Eigen::Success;
    EXPECT_TRUE(positive) << e;
    EXPECT_LT((tangent - tangent.transpose()).norm(), 1e-12 * tangent.norm());
    if (!update.plastic)
    {
      Eigen::Matrix<double, 6, 6> differences;
      for (int k = 0; k < 6; ++k)
      {
        Voigt plus = strain, minus = strain;
        plus(k) += 1e-7;
        minus(k) -= 1e-7;
        differences.col(k) =
            (finite_j2_return(steel(), plus, {}).stress - finite_j2_return(steel(), minus, {}).stress) / 2e-7;
      }
      EXPECT_LT((tangent - differences).norm(), 1e-6 * tangent.norm()) << e;
    }
  }
}
} // namespace feticon::fem
