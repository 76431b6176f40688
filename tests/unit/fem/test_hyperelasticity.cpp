/// Neo-Hooke and Mooney-Rivlin at one point (issue 66, item 4): S(E) against the closed forms of
/// the principal-stretch Cauchy stress (tests/verification/rubber_closed_forms.hpp) in uniaxial
/// stress and simple shear, the tangent against central differences of S, and the law at
/// E = 0 against Hooke's law of its initial moduli.

#include "../../verification/rubber_closed_forms.hpp"
#include "common/error.hpp"
#include "fem/cell_element.hpp"
#include "fem/material.hpp"
#include "mesh/cell_type.hpp"

#include <gtest/gtest.h>

#include <random>

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

namespace hyperelastic_cells
{
/// The reference cell of `kind` scaled to 10 mm and sheared a little, moved to x >= 10 mm (for
/// axisymmetry), and a displacement of it: in 3D and plane strain an isochoric stretch of 1.2
/// then a rotation by 0.5 rad, in axisymmetry (where a rotation in the r-z plane is no rigid
/// motion) none; plus random node displacements of up to 2 um. Near-isochoric: the rubber's
/// dS/dE is positive definite there (beyond |J - 1| ~ mu_0 / K_0 it is not, and K_M takes its
/// positive definite part).
std::pair<Eigen::MatrixX3d, Eigen::MatrixX3d> deformed_cell(mesh::CellKind kind, mesh::PlanarKind planar)
{
  const auto& nodes = mesh::cell_type(kind).reference_nodes;
  Eigen::Matrix3d A;
  A << 1, 0.1, 0.05, 0.02, 0.9, 0.1, 0.03, 0.04, 1.1;
  const bool is_planar = planar != mesh::PlanarKind::none;
  if (is_planar)
    A.row(2).setZero();
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  if (planar == mesh::PlanarKind::none)
    F = Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
        Eigen::Vector3d(1.2, 1 / std::sqrt(1.2), 1 / std::sqrt(1.2)).asDiagonal();
  else if (planar == mesh::PlanarKind::plane_strain)
    F = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
        Eigen::Vector3d(1.2, 1 / 1.2, 1).asDiagonal();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-2e-6, 2e-6);
  Eigen::MatrixX3d X(nodes.size(), 3), u(nodes.size(), 3);
  for (size_t a = 0; a < nodes.size(); ++a)
  {
    X.row(a) = 0.005 * (A * Eigen::Vector3d(nodes[a][0], nodes[a][1], nodes[a][2])).transpose();
    X(a, 0) += 0.01;
    u.row(a) = ((F - Eigen::Matrix3d::Identity()) * X.row(a).transpose()).transpose();
    u.row(a) += Eigen::RowVector3d(d(rng), d(rng), is_planar ? 0.0 : d(rng));
  }
  return {X, u};
}
} // namespace hyperelastic_cells

// Reference: central differences of f_int (step 1e-9 m; their error ~1e-7 relative) for every
// cell type, 3D and 2D (plane strain, axisymmetry), at stretches of 1.2 and rotations of 0.5 rad,
// where dS/dE is positive definite and K is the exact tangent K_M + K_G.
TEST(Hyperelasticity, ElementTangentIsTheDerivativeOfTheInternalForce)
{
  fem::Material rubber;
  rubber.set_hyperelastic(mooney_rivlin());
  std::vector<std::pair<mesh::CellKind, mesh::PlanarKind>> cases;
  for (const mesh::CellKind kind : mesh::solid_cell_kinds)
    cases.emplace_back(kind, mesh::PlanarKind::none);
  for (const mesh::CellKind kind : mesh::planar_cell_kinds)
    for (const mesh::PlanarKind planar : {mesh::PlanarKind::plane_strain, mesh::PlanarKind::axisymmetric})
      cases.emplace_back(kind, planar);
  for (const auto& [kind, planar_kind] : cases)
  {
    const mesh::Planar planar{planar_kind, 0.002};
    const bool is_planar = planar_kind != mesh::PlanarKind::none;
    const auto [X, u] = hyperelastic_cells::deformed_cell(kind, planar_kind);
    const auto element = [&](const Eigen::MatrixX3d& v, Eigen::MatrixXd* K) {
      Eigen::VectorXd f;
      fem::cell_element(kind, X, v, rubber, fem::Kinematics::total_lagrangian,
                        K ? fem::StiffnessKind::tangent : fem::StiffnessKind::none, fem::Integration::full, f, K, 0,
                        nullptr, nullptr, planar);
      return f;
    };
    Eigen::MatrixXd K;
    element(u, &K);
    const std::string where =
        std::string(mesh::cell_type(kind).name) + " " + std::string(mesh::planar_name(planar_kind));
    EXPECT_LE((K - K.transpose()).norm(), 1e-12 * K.norm()) << where;
    const double h = 1e-9;
    for (Eigen::Index a = 0; a < X.rows(); ++a)
      for (int i = 0; i < (is_planar ? 2 : 3); ++i)
      {
        Eigen::MatrixX3d up = u, um = u;
        up(a, i) += h;
        um(a, i) -= h;
        const Eigen::VectorXd column = (element(up, nullptr) - element(um, nullptr)) / (2 * h);
        EXPECT_LE((column - K.col(3 * a + i)).norm(), 1e-6 * K.norm()) << where << ", node " << a << ", " << i;
      }
  }
}

// Reference: the rigid-body modes of the current configuration x = X + u (K_M's kernel, which
// FETI needs) and the eigenvalues of K_M. At a dilatation of 10 % the Mooney-Rivlin rubber
// (K_0 / mu_0 = 250) has an indefinite dS/dE and K_M is indefinite; StiffnessKind::
// material_definite (FETI's fallback) takes each point's positive definite part and is
// symmetric positive semi-definite with exactly the six rigid modes in its kernel.
TEST(Hyperelasticity, MaterialStiffnessStaysPositiveSemiDefiniteWhereTheLawIsNotConvexInE)
{
  const fem::Hyperelastic law = mooney_rivlin();
  Eigen::Matrix<double, 6, 6> D;
  const double stretch = std::cbrt(1.1);
  const Voigt dilated = green_lagrange(stretch * Eigen::Matrix3d::Identity());
  fem::hyperelastic_stress(law, dilated, &D);
  const bool definite = Eigen::LLT<Eigen::Matrix<double, 6, 6>>(D).info() == Eigen::Success;
  ASSERT_FALSE(definite) << "dS/dE is positive definite there: the test would test nothing";
  fem::Material rubber;
  rubber.set_hyperelastic(law);
  const auto& nodes = mesh::cell_type(mesh::CellKind::hex8).reference_nodes;
  Eigen::MatrixX3d X(8, 3), u(8, 3);
  for (int a = 0; a < 8; ++a)
  {
    X.row(a) << 0.005 * nodes[a][0], 0.005 * nodes[a][1], 0.005 * nodes[a][2];
    u.row(a) = (stretch - 1) * X.row(a);
  }
  Eigen::VectorXd f;
  Eigen::MatrixXd K;
  fem::cell_element(mesh::CellKind::hex8, X, u, rubber, fem::Kinematics::total_lagrangian, fem::StiffnessKind::material,
                    fem::Integration::full, f, &K, 0);
  ASSERT_LT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues().minCoeff(), 0) << "K_M is not indefinite";
  fem::cell_element(mesh::CellKind::hex8, X, u, rubber, fem::Kinematics::total_lagrangian,
                    fem::StiffnessKind::material_definite, fem::Integration::full, f, &K, 0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K);
  const double largest = eigen.eigenvalues().maxCoeff();
  EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-10 * largest);
  EXPECT_EQ((eigen.eigenvalues().array() < 1e-10 * largest).count(), 6);
  const Eigen::MatrixX3d x = X + u;
  for (int i = 0; i < 3; ++i)
  {
    Eigen::VectorXd translation = Eigen::VectorXd::Zero(24), rotation = Eigen::VectorXd::Zero(24);
    for (int a = 0; a < 8; ++a)
    {
      translation(3 * a + i) = 1;
      const Eigen::Vector3d r = Eigen::Vector3d::Unit(i).cross(x.row(a).transpose());
      rotation.segment<3>(3 * a) = r;
    }
    EXPECT_LE((K * translation).norm(), 1e-10 * largest);
    EXPECT_LE((K * rotation).norm(), 1e-10 * largest * 0.01);
  }
}
