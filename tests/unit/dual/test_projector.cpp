/// Dual operators and projectors (ALGORITHMS.md section 1, tests).
#include "common/error.hpp"

#include "clamped_box.hpp"
#include "dual/feti_operators.hpp"
#include "dual/projector.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
struct ProjectorSetup
{
  std::unique_ptr<test::ClampedBox> box;
  std::unique_ptr<dual::FetiOperators> feti;
};

std::unique_ptr<ProjectorSetup> make_setup()
{
  auto s = std::make_unique<ProjectorSetup>();
  s->box = test::make_clamped_box();
  s->feti = std::make_unique<dual::FetiOperators>(*s->box->system, s->box->equality.rows);
  return s;
}
} // namespace

// Reference: G~ G~' = L^{-1} G G' L^{-T} = I; P is an orthogonal projector onto Ker G:
// P P = P, G P = 0, P Q = 0; G lambda~ = e for the minimal-norm particular solution.
TEST(Projector, OrthonormalCoarseSpaceAndProjectorIdentities)
{
  const auto s = make_setup();
  const dual::CoarseProjector projector(*s->feti);
  const la::Index k = s->feti->n_kernel();
  ASSERT_EQ(k, 18);
  la::Matrix GtGt(k, k);
  for (la::Index j = 0; j < k; ++j)
    GtGt.col(j) = projector.apply_G_tilde(projector.apply_G_tilde_t(la::Vector::Unit(k, j)));
  EXPECT_LT((GtGt - la::Matrix::Identity(k, k)).norm(), 1e-12);

  const la::Vector x = la::Vector::Random(s->feti->n_dual());
  const la::Vector Px = projector.apply_P(x);
  EXPECT_LT((projector.apply_P(Px) - Px).norm(), 1e-12 * x.norm());
  const double G_norm = std::sqrt(s->feti->coarse_matrix().diagonal().sum()); // ||G||_F
  EXPECT_LT(s->feti->apply_G(Px).norm(), 1e-12 * x.norm() * G_norm);
  EXPECT_LT(projector.apply_P(projector.apply_Q(x)).norm(), 1e-12 * x.norm());
  const la::Vector e = la::Vector::Random(k);
  EXPECT_LT((s->feti->apply_G(projector.particular_solution(e)) - e).norm(), 1e-12 * e.norm());
}

// Reference: G~' omega = G' P_o' L^{-T} omega, so the coarse multiplier beta of omega must
// give G' beta = G~' omega, and omega must come back from beta (L is invertible).
TEST(Projector, CoarseMultiplierCarriesTheEqualityMultiplier)
{
  const auto s = make_setup();
  const dual::CoarseProjector projector(*s->feti);
  const la::Vector omega = la::Vector::Random(s->feti->n_kernel());
  const la::Vector beta = projector.coarse_multiplier(omega);
  const la::Vector Gt_omega = projector.apply_G_tilde_t(omega);
  EXPECT_LT((s->feti->apply_Gt(beta) - Gt_omega).norm(), 1e-12 * Gt_omega.norm());
  EXPECT_LT((projector.tilde_multiplier(beta) - omega).norm(), 1e-12 * omega.norm());
}

// Reference: F is symmetric positive semidefinite (B K+ B' with symmetric K+), checked on
// random vectors: x'Fy = y'Fx and x'Fx >= 0; F applied equals B K+ B' built densely.
TEST(FetiOperators, FIsSymmetricAndMatchesDenseProduct)
{
  const auto s = make_setup();
  const la::Index m = s->feti->n_dual();
  const la::Vector x = la::Vector::Random(m), y = la::Vector::Random(m);
  const double xFy = x.dot(s->feti->apply_F(y)), yFx = y.dot(s->feti->apply_F(x));
  EXPECT_NEAR(xFy, yFx, 1e-12 * std::abs(xFy));
  EXPECT_GE(x.dot(s->feti->apply_F(x)), 0.0);
  const la::Vector Fx = s->feti->apply_F(x);
  const la::Vector Fx2 = s->feti->apply_B(s->feti->apply_K_plus(s->feti->apply_Bt(x)));
  EXPECT_LT((Fx - Fx2).norm(), 1e-13 * Fx.norm());
}

// Reference: G G' assembled block by block (coarse_matrix) equals G G' formed from the
// columns G' e_j, which apply_Gt builds by the contribution exchange, and the masked G_A G_A'
// equals the product with the unmasked rows only.
TEST(FetiOperators, CoarseMatrixEqualsProductOfGColumns)
{
  const auto s = make_setup();
  const la::Index k = s->feti->n_kernel(), m = s->feti->n_dual();
  la::Matrix Gt(m, k);
  for (la::Index j = 0; j < k; ++j)
    Gt.col(j) = s->feti->apply_Gt(la::Vector::Unit(k, j));
  const la::Matrix GGt = Gt.transpose() * Gt;
  EXPECT_LT((la::Matrix(s->feti->coarse_matrix()) - GGt).norm(), 1e-13 * GGt.norm());
  std::vector<char> mask(m, 0);
  for (la::Index i = 0; i < m; i += 2)
    mask[i] = 1;
  la::Matrix Gt_A = Gt;
  for (la::Index i = 1; i < m; i += 2)
    Gt_A.row(i).setZero();
  const la::Matrix GGt_A = Gt_A.transpose() * Gt_A;
  EXPECT_LT((la::Matrix(s->feti->coarse_matrix(&mask)) - GGt_A).norm(), 1e-13 * GGt.norm());
  const la::Vector x = la::Vector::Random(m);
  EXPECT_LT((s->feti->apply_G(x, &mask) - Gt_A.transpose() * x).norm(), 1e-13 * GGt.norm() * x.norm());
}

// Failure path: a body without any support leaves rigid motions free; G G' is singular.
TEST(Projector, UnsupportedBodyIsReported)
{
  mesh::BoxParameters p;
  p.nx = 2;
  const auto mesh = mesh::generate_box(p);
  const decomposition::Decomposition decomp(mesh, decomposition::partition_structured(mesh, {2, 1, 1}));
  decomposition::SubdomainSystem system(decomp, {fem::Material{}}, fem::Kinematics::linear,
                                        decomposition::GeneralizedInverseMethod::fixing_dofs);
  system.update(la::Vector::Zero(decomp.n_primal()));
  const auto rows = decomposition::build_equality_rows(decomp, {});
  const dual::FetiOperators feti(system, rows.rows);
  EXPECT_THROW(dual::CoarseProjector projector(feti), feticon::Error);
}
