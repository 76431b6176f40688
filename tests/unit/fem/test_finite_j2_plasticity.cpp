/// Tests of finite-strain J2 plasticity (fem/finite_j2_plasticity.hpp). References: the
/// small-strain radial return (fem/j2_plasticity.hpp), which the model tends to as the strain
/// goes to zero; the model's own invariant (a returned state lies on the yield surface); the
/// tangent against central differences of the stress. Kinematic hardening likewise: its
/// small-strain limit is the small-strain kinematic return, and a returned state lies on the
/// moved yield surface.
/// The whole model against CalculiX 2.20 at 50 % stretch: tests/cli/plasticity_nlgeom.sh; the
/// kinematic one over a tension-compression cycle: tests/cli/plasticity_kinematic.sh.

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

Material kinematic_steel()
{
  Material m = steel();
  m.plastic.kinematic = true;
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

TEST(FiniteJ2, KinematicSmallStrainsGiveTheSmallStrainReturn)
{
  // From a state yielded in tension, a strain reversed past the reversed yield (the back stress
  // at work): S, eqps and the back stress within O(strain) of the small-strain return's.
  const Voigt load = (Voigt() << 4e-3, -2e-3, -2e-3, 0, 0, 0).finished();
  const Voigt reverse = (Voigt() << -1e-3, 0.5e-3, 0.5e-3, 1e-4, 0, 0).finished();
  const J2Update small_1 = j2_return(kinematic_steel(), load, 0, {});
  const J2Update finite_1 = finite_j2_return(kinematic_steel(), load, {});
  ASSERT_TRUE(small_1.plastic && finite_1.plastic);
  EXPECT_LT((finite_1.state.back_stress - small_1.state.back_stress).norm(), 2e-2 * small_1.state.back_stress.norm());
  const J2Update small_2 = j2_return(kinematic_steel(), reverse, 0, small_1.state);
  const J2Update finite_2 = finite_j2_return(kinematic_steel(), reverse, finite_1.state);
  ASSERT_TRUE(small_2.plastic && finite_2.plastic);
  EXPECT_LT((finite_2.stress - small_2.stress).norm(), 2e-2 * small_2.stress.norm());
  EXPECT_NEAR(finite_2.state.equivalent_plastic_strain, small_2.state.equivalent_plastic_strain,
              2e-2 * small_2.state.equivalent_plastic_strain);
}

TEST(FiniteJ2, KinematicReturnedStateLiesOnTheMovedYieldSurface)
{
  // Loaded, then reversed beyond the reversed yield: from each returned state at the same strain
  // the point is elastic with the same stress.
  const Voigt load = (Voigt() << 0.3, -0.1, -0.12, 0.05, 0.02, -0.04).finished();
  const Voigt reverse = (Voigt() << -0.1, 0.05, 0.04, -0.02, 0.01, 0.03).finished();
  PlasticPointState state;
  for (const Voigt& strain : {load, reverse})
  {
    const J2Update update = finite_j2_return(kinematic_steel(), strain, state);
    ASSERT_TRUE(update.plastic);
    EXPECT_GT((update.state.back_stress - state.back_stress).norm(), 0) << "the centre moves";
    const J2Update again = finite_j2_return(kinematic_steel(), strain, update.state);
    EXPECT_FALSE(again.plastic);
    EXPECT_LT((again.stress - update.stress).norm(), 1e-9 * update.stress.norm());
    state = update.state;
  }
}
} // namespace feticon::fem
