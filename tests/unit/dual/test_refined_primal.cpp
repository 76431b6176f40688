/// FetiOperators::apply_K_plus_refined: K+ f with single-precision factors, refined once
/// against K in double. Reference: the subdomain equations themselves, K_s u_s = f_s for f_s
/// in the range of K_s (the residual computed in double), and the unrefined float solve of the
/// same right-hand side, whose residual is the float factor's backward error (about 1e-7 of
/// |K||u|; Higham, Accuracy and Stability of Numerical Algorithms, thm. 10.4).

#include "decomposition/constraint_rows.hpp"
#include "decomposition/subdomain_operators.hpp"
#include "dual/feti_operators.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
/// Largest relative residual ||f_s - K_s u_s|| / ||f_s|| over the subdomains.
double worst_relative_residual(const decomposition::SubdomainSystem& system, const la::Vector& f, const la::Vector& u)
{
  const auto& decomp = system.decomposition();
  double worst = 0;
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
  {
    const la::Vector f_s = decomp.segment(f, s);
    const la::Vector r = f_s - system.operators(s).K.selfadjointView<Eigen::Lower>() * la::Vector(decomp.segment(u, s));
    worst = std::max(worst, r.norm() / f_s.norm());
  }
  return worst;
}
} // namespace

TEST(RefinedPrimal, SubdomainEquationsSolvedToDoublePrecisionWithFloatFactors)
{
  // Two floating subdomains of 9 x 9 x 9 cells (3 000 DOFs): large enough for CHOLMOD's
  // supernodal factor, which is the one kept in float.
  mesh::BoxParameters p;
  p.lengths = Eigen::Vector3d(2, 1, 1);
  p.nx = 18;
  p.ny = 9;
  p.nz = 9;
  const mesh::Mesh mesh = mesh::generate_box(p);
  const decomposition::Decomposition decomp(mesh, decomposition::partition_structured(mesh, {2, 1, 1}));
  decomposition::SubdomainSystem system(decomp, {fem::Material{}}, fem::Kinematics::linear,
                                        decomposition::GeneralizedInverseMethod::fixing_dofs,
                                        la::FactorPrecision::single_precision);
  system.update(la::Vector::Zero(decomp.n_primal()));
  const decomposition::EqualityRows equality =
      decomposition::build_equality_rows(decomp, fem::collect_dirichlet(mesh, {}));
  const dual::FetiOperators feti(system, equality.rows);

  // A load in the range of each K_s (no net force or moment on a floating subdomain).
  la::Vector f = la::Vector::LinSpaced(decomp.n_primal(), -1.0, 3.0).array().sin().matrix();
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
  {
    const la::Matrix& R = system.operators(s).R;
    ASSERT_EQ(R.cols(), 6);
    auto f_s = decomp.segment(f, s);
    f_s -= R * (R.transpose() * f_s);
  }

  const double unrefined = worst_relative_residual(system, f, feti.apply_K_plus(f));
  const double refined = worst_relative_residual(system, f, feti.apply_K_plus_refined(f));
  EXPECT_GT(unrefined, 1e-9); // the float factor's round-off is there to remove
  EXPECT_LT(refined, 1e-3 * unrefined);
  EXPECT_LT(refined, 1e-10);
}
