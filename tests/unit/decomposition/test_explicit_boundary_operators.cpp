/// The explicit boundary blocks (decomposition/explicit_boundary_operators.hpp) against what
/// the implicit operators compute: (K_s+)_bb column by column from the generalized inverse's
/// own factorization, and S_s = K_bb - K_bi K_ii^-1 K_ib from a dense Cholesky of K_ii.
/// Floating subdomains of a distorted box, both K+ variants, with the fixing nodes on the
/// boundary and off it.

#include "common/error.hpp"
#include "decomposition/explicit_boundary_operators.hpp"
#include "mesh/box.hpp"
#include "tests/support/dense_schur.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace feticon;
using decomposition::GeneralizedInverseMethod;

namespace
{
mesh::Mesh distorted_box()
{
  mesh::BoxParameters p;
  p.lengths = Eigen::Vector3d(2, 1, 1);
  p.nx = 6;
  p.ny = 3;
  p.nz = 3;
  mesh::Mesh m = mesh::generate_box(p);
  for (int32_t i = 0; i < m.n_nodes(); ++i)
    m.nodes.row(i) += 0.04 * Eigen::RowVector3d(std::sin(3.1 * i), std::cos(1.7 * i), std::sin(0.7 * i + 1));
  return m;
}

/// The dense matrix of the operator `apply` on vectors of size n.
template <class Apply>
la::Matrix dense_of(la::Index n, const Apply& apply)
{
  la::Matrix M(n, n);
  for (la::Index j = 0; j < n; ++j)
    M.col(j) = apply(la::Vector::Unit(n, j));
  return M;
}

void check_blocks(GeneralizedInverseMethod method, bool whole_surface_on_boundary, double young = 2e11)
{
  const mesh::Mesh m = distorted_box();
  const decomposition::Decomposition decomp(m, decomposition::partition_structured(m, {3, 1, 1}));
  decomposition::SubdomainSystem system(decomp, {fem::Material{young, 0.3}}, fem::Kinematics::linear, method);
  system.update(la::Vector::Zero(decomp.n_primal()));
  // Boundary: the interfaces alone (fixing nodes, far from each centroid, mostly off it), or
  // every node on the box's surface too.
  std::vector<char> flagged(3 * static_cast<size_t>(m.n_nodes()), 0);
  if (whole_surface_on_boundary)
    for (int32_t i = 0; i < m.n_nodes(); ++i)
      for (int d = 0; d < 3; ++d)
      {
        const double x = m.nodes(i, d), top = d == 0 ? 2 : 1;
        if (std::abs(x) < 0.05 || std::abs(x - top) < 0.05)
          for (int c = 0; c < 3; ++c)
            flagged[3 * static_cast<size_t>(i) + c] = 1;
      }
  const decomposition::SchurComplements boundaries(system, flagged, false);
  const decomposition::ExplicitBoundaryOperators ops(system, boundaries);

  int fixing_off_boundary = 0;
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
  {
    const auto& b = ops.boundary(s);
    const la::Index nb = static_cast<la::Index>(b.size());
    const auto& op = system.operators(s);
    const la::Matrix K(la::SparseMatrix(op.K.selfadjointView<Eigen::Lower>())); // op.K: lower triangle
    // Reference (K+)_bb: K+ applied to the unit vectors of b, by the implicit factorization.
    la::Matrix E = la::Matrix::Zero(K.rows(), nb);
    for (la::Index k = 0; k < nb; ++k)
      E(b[k], k) = 1;
    const la::Matrix K_plus_ref = E.transpose() * op.K_plus.apply(E);
    // Reference S_s by dense elimination of the interior.
    const la::Matrix S_ref = test::dense_schur(K, b);
    for (int32_t dof : op.K_plus.fixing_dofs())
      fixing_off_boundary += !std::binary_search(b.begin(), b.end(), dof);

    const la::Matrix K_plus = dense_of(nb, [&](const la::Vector& v) { return ops.apply_K_plus(s, v); });
    const la::Matrix S = dense_of(nb, [&](const la::Vector& v) { return ops.apply_schur(s, v); });
    EXPECT_LT((K_plus - K_plus_ref).norm() / K_plus_ref.norm(), 1e-12) << "subdomain " << s;
    EXPECT_LT((S - S_ref).norm() / S_ref.norm(), 1e-13) << "subdomain " << s;
    // S_s inherits the rigid-body kernel of the floating K_s.
    EXPECT_LT((S * op.R(b, Eigen::all)).norm() / S.norm(), 1e-13);
  }
  if (!whole_surface_on_boundary)
  {
    EXPECT_GT(fixing_off_boundary, 0) << "the case with fixing DOFs outside b was not exercised";
  }
}
} // namespace

TEST(ExplicitBoundaryOperators, FixingDofsOnAndOffTheBoundary)
{
  check_blocks(GeneralizedInverseMethod::fixing_dofs, false);
  check_blocks(GeneralizedInverseMethod::fixing_dofs, true);
}

// Moduli far from 1 (issue 36): K+ scales like 1 / E and S like E, and the two share one
// array; S's diagonal was lost to cancellation once diag(K+) outgrew it by 1e16 (E = 1e-30 Pa
// made the Dirichlet preconditioner noise). Same references, same tolerances.
TEST(ExplicitBoundaryOperators, ModuliFarFromOne)
{
  for (const double young : {1e-30, 1e-3, 1e30})
  {
    SCOPED_TRACE(testing::Message() << "E = " << young);
    check_blocks(GeneralizedInverseMethod::fixing_dofs, false, young);
    check_blocks(GeneralizedInverseMethod::fixing_dofs, true, young);
  }
}

TEST(ExplicitBoundaryOperators, Regularization)
{
  check_blocks(GeneralizedInverseMethod::regularization, false);
  check_blocks(GeneralizedInverseMethod::regularization, true);
}

// Reference: the block elimination by hand. S' = [[4, 1, 1], [1, 3, 1], [1, 1, 2]] with b the
// first two rows: S = S'_bb - S'_bg S'_gb / 2 = [[3.5, 0.5], [0.5, 2.5]]. An indefinite or NaN
// S'_gg (a singular or non-finite subdomain) is a one-line error naming the subdomain.
TEST(ExplicitBoundaryOperators, EliminatesFixingDofsAndRefusesASingularSgg)
{
  la::Matrix S_ext(3, 3);
  S_ext << 4, 1, 1, 1, 3, 1, 1, 1, 2;
  const la::Matrix S = decomposition::eliminate_fixing_dofs(S_ext, 2, "subdomain 7");
  la::Matrix expected(2, 2);
  expected << 3.5, 0.5, 0.5, 2.5;
  EXPECT_LT((S - expected).norm(), 1e-15);
  EXPECT_EQ(decomposition::eliminate_fixing_dofs(S_ext, 3, "subdomain 7"), S_ext) << "no fixing DOF outside b";
  for (const double gg : {-1.0, 0.0, std::nan("")})
  {
    la::Matrix singular = S_ext;
    singular(2, 2) = gg;
    try
    {
      decomposition::eliminate_fixing_dofs(singular, 2, "subdomain 7");
      ADD_FAILURE() << "S'_gg = " << gg << " accepted";
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find("S'_gg"), std::string::npos) << message;
      EXPECT_NE(message.find("subdomain 7"), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

// A boundary grown in one subdomain (the box's face x = 0, inside subdomain 0 only): with the
// last operators to reuse, only that subdomain's blocks are formed, and every subdomain's
// products equal those of operators formed from scratch on the grown boundary (exactly: the
// reused blocks are the same arithmetic on the same boundary).
TEST(ExplicitBoundaryOperators, UnchangedBoundariesKeepTheirBlocks)
{
  const mesh::Mesh m = distorted_box();
  const decomposition::Decomposition decomp(m, decomposition::partition_structured(m, {3, 1, 1}));
  decomposition::SubdomainSystem system(decomp, {fem::Material{2e11, 0.3}}, fem::Kinematics::linear,
                                        GeneralizedInverseMethod::fixing_dofs);
  system.update(la::Vector::Zero(decomp.n_primal()));
  std::vector<char> flagged(3 * static_cast<size_t>(m.n_nodes()), 0);
  const decomposition::SchurComplements interfaces(system, flagged, false);
  decomposition::ExplicitBoundaryOperators first(system, interfaces);
  EXPECT_EQ(first.formed(), decomp.n_subdomains());
  for (int32_t i = 0; i < m.n_nodes(); ++i)
    if (std::abs(m.nodes(i, 0)) < 0.05)
      for (int c = 0; c < 3; ++c)
        flagged[3 * static_cast<size_t>(i) + c] = 1;
  const decomposition::SchurComplements grown(system, flagged, false);
  const decomposition::ExplicitBoundaryOperators reused(system, grown, &first);
  const decomposition::ExplicitBoundaryOperators fresh(system, grown);
  EXPECT_EQ(reused.formed(), 1);
  for (int32_t s = 0; s < decomp.n_subdomains(); ++s)
  {
    ASSERT_EQ(reused.boundary(s), fresh.boundary(s));
    const la::Index nb = static_cast<la::Index>(fresh.boundary(s).size());
    const la::Vector v = la::Vector::LinSpaced(nb, -1, 2);
    EXPECT_EQ(reused.apply_K_plus(s, v), fresh.apply_K_plus(s, v)) << "subdomain " << s;
    EXPECT_EQ(reused.apply_schur(s, v), fresh.apply_schur(s, v)) << "subdomain " << s;
  }
}
