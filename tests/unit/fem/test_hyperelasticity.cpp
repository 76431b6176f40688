/// Neo-Hooke and Mooney-Rivlin at one point (issue 66, item 4): S(E) against the closed forms of
/// the principal-stretch Cauchy stress (tests/verification/rubber_closed_forms.hpp) in uniaxial
/// stress and simple shear, the tangent against central differences of S, and the law at
/// E = 0 against Hooke's law of its initial moduli.

#include "../../verification/rubber_closed_forms.hpp"
#include "common/error.hpp"
#include "fem/material.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace hyperelastic_point
{
using Voigt = Eigen::Matrix<double, 6, 1>;

fem::Hyperelastic neo_hooke() { return {1.0e6, 0.0, 2.0e-8}; }       // mu_0 2 MPa, K_0 100 MPa
fem::Hyperelastic mooney_rivlin() { return {0.8e6, 0.2e6, 4.0e-9}; } // mu_0 2 MPa, K_0 500 MPa

/// Green-Lagrange strain of F, Voigt with engineering shears.
Voigt green_lagrange(const Eigen::Matrix3d& F)
{
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  Voigt v;
  v << E(0, 0), E(1, 1), E(2, 2), 2 * E(0, 1), 2 * E(1, 2), 2 * E(2, 0);
  return v;
}

/// sigma = F S F' / J from the code's S.
Eigen::Matrix3d code_cauchy(const fem::Hyperelastic& law, const Eigen::Matrix3d& F)
{
  const Voigt s = fem::hyperelastic_stress(law, green_lagrange(F));
  Eigen::Matrix3d S;
  S << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
  return F * S * F.transpose() / F.determinant();
}
} // namespace hyperelastic_point

using namespace hyperelastic_point;

// Reference: the principal-stretch closed form, uniaxial stress at stretches 0.5 to 2 (the
// lateral stretch from its own sigma_yy = 0). Tolerance: 1e-9 of mu_0, round-off of the two
// forms.
TEST(Hyperelasticity, UniaxialStressMatchesTheClosedForm)
{
  for (const fem::Hyperelastic& law : {neo_hooke(), mooney_rivlin()})
    for (const double stretch : {0.5, 0.7, 0.9, 1.1, 1.5, 2.0})
    {
      const double lateral = rubber_closed_forms::uniaxial_lateral_stretch(law, stretch);
      const Eigen::Matrix3d F = Eigen::Vector3d(stretch, lateral, lateral).asDiagonal();
      const Eigen::Matrix3d code = code_cauchy(law, F), closed = rubber_closed_forms::cauchy_stress(law, F);
      const double mu0 = law.initial_shear_modulus();
      EXPECT_NEAR(code(0, 0), closed(0, 0), 1e-9 * mu0) << "stretch " << stretch;
      EXPECT_NEAR(code(1, 1), 0.0, 1e-9 * mu0) << "stretch " << stretch;
      EXPECT_NEAR(code(2, 2), 0.0, 1e-9 * mu0) << "stretch " << stretch;
      EXPECT_NEAR(code(0, 1), 0.0, 1e-9 * mu0);
    }
}

// Reference: simple shear (J = 1) of Mooney-Rivlin: sigma_12 = 2 (C10 + C01) gamma exactly
// (Holzapfel 6.6), and the closed form's normal stresses.
TEST(Hyperelasticity, SimpleShearMatchesTheClosedForm)
{
  for (const fem::Hyperelastic& law : {neo_hooke(), mooney_rivlin()})
    for (const double gamma : {0.1, 0.5, 1.0, 2.0})
    {
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      F(0, 1) = gamma;
      const Eigen::Matrix3d code = code_cauchy(law, F), closed = rubber_closed_forms::cauchy_stress(law, F);
      const double mu0 = law.initial_shear_modulus();
      EXPECT_NEAR(code(0, 1), mu0 * gamma, 1e-9 * mu0) << "gamma " << gamma;
      EXPECT_NEAR((code - closed).norm(), 0.0, 1e-9 * mu0) << "gamma " << gamma;
    }
}

// Reference: central differences of S (step 1e-6 of the strain; their error ~1e-7 relative).
TEST(Hyperelasticity, TangentIsTheDerivativeOfTheStress)
{
  Eigen::Matrix3d F;
  F << 1.3, 0.2, -0.1, 0.05, 0.8, 0.15, -0.2, 0.1, 1.1;
  const Voigt E = green_lagrange(F);
  for (const fem::Hyperelastic& law : {neo_hooke(), mooney_rivlin()})
  {
    Eigen::Matrix<double, 6, 6> D;
    fem::hyperelastic_stress(law, E, &D);
    const double h = 1e-6;
    for (int b = 0; b < 6; ++b)
    {
      Voigt plus = E, minus = E;
      plus(b) += h;
      minus(b) -= h;
      const Voigt column = (fem::hyperelastic_stress(law, plus) - fem::hyperelastic_stress(law, minus)) / (2 * h);
      EXPECT_LE((D.col(b) - column).norm(), 1e-6 * D.norm()) << "column " << b;
    }
    EXPECT_LE((D - D.transpose()).norm(), 1e-14 * D.norm());
  }
}

// Reference: Hooke's law of mu_0 = 2 (C10 + C01), K_0 = 2 / D1 (Material::elasticity_matrix of
// the initial Young's modulus and Poisson's ratio), at E = 0 and for S at a strain of 1e-7.
TEST(Hyperelasticity, SmallStrainLimitIsHookesLaw)
{
  for (const fem::Hyperelastic& law : {neo_hooke(), mooney_rivlin()})
  {
    fem::Material m;
    m.set_hyperelastic(law);
    const Eigen::Matrix<double, 6, 6> hooke = m.elasticity_matrix();
    Eigen::Matrix<double, 6, 6> D;
    EXPECT_NEAR(fem::hyperelastic_stress(law, Voigt::Zero(), &D).norm(), 0.0, 1e-20);
    EXPECT_LE((D - hooke).norm(), 1e-12 * hooke.norm());
    Voigt e;
    e << 1e-7, -3e-8, 2e-8, 5e-8, -1e-8, 4e-8;
    EXPECT_LE((fem::hyperelastic_stress(law, e) - hooke * e).norm(), 1e-6 * (hooke * e).norm());
    EXPECT_NEAR(m.lame_mu(), law.initial_shear_modulus(), 1e-9 * law.initial_shear_modulus());
  }
}

TEST(Hyperelasticity, MalformedLawsAreRefused)
{
  EXPECT_THROW((fem::Hyperelastic{-1.0, 0.0, 1e-8}.check("x")), Error);
  EXPECT_THROW((fem::Hyperelastic{1.0, -1.0, 1e-8}.check("x")), Error);
  EXPECT_THROW((fem::Hyperelastic{1.0, 0.0, 0.0}.check("x")), Error);
  EXPECT_THROW((fem::Hyperelastic{1.0, 0.0, -1e-8}.check("x")), Error);
  fem::Material m;
  m.set_hyperelastic(neo_hooke());
  m.expansion = 1e-5;
  EXPECT_THROW(m.check("x"), Error);
}
