/// Y = (B B')^{-1} of the preconditioners (dual/constraint_scaling.hpp).
#include "clamped_box.hpp"
#include "dual/constraint_scaling.hpp"
#include "dual/feti_operators.hpp"

#include <gtest/gtest.h>

using namespace feticon;

namespace
{
struct Setup
{
  std::unique_ptr<test::ClampedBox> box;
  decomposition::ConstraintRows rows;
  int64_t n_equality = 0;
  std::unique_ptr<dual::FetiOperators> feti;
};

/// The clamped box with `extra` rows after the equality rows that play contact rows:
/// node-to-segment-like rows -n' on one node and +n'/2 on two others, over nodes on and off
/// the subdomain interfaces (not orthogonal to the gluing rows or to each other).
/// `near_copy`: one more row, the first one plus `near_copy` times e_x at a fourth node.
std::unique_ptr<Setup> make_setup(int extra, double near_copy = 0)
{
  auto s = std::make_unique<Setup>();
  s->box = test::make_clamped_box();
  const mesh::Mesh& mesh = s->box->mesh;
  s->rows = s->box->equality.rows;
  s->n_equality = s->box->equality.n_global();
  if (extra > 0)
  {
    // Nodes along the top edge y = 1, z = 1 at x = 0.5, 1, ..., 3 (x = 1 and x = 2 on the
    // interfaces), each row pulling one node against its two neighbours.
    std::vector<int32_t> top;
    for (int32_t n = 0; n < mesh.n_nodes(); ++n)
      if (mesh.nodes(n, 1) == 1.0 && mesh.nodes(n, 2) == 1.0 && mesh.nodes(n, 0) > 0)
        top.push_back(n);
    std::ranges::sort(top, [&](int32_t a, int32_t b) { return mesh.nodes(a, 0) < mesh.nodes(b, 0); });
    const Eigen::Vector3d normal = Eigen::Vector3d(0, 1, 1).normalized();
    std::vector<Eigen::Triplet<double>> triplets;
    for (int r = 0; r < extra; ++r)
    {
      const int32_t centre = top[1 + r], left = top[r], right = top[2 + r];
      for (int k = 0; k < 3; ++k)
      {
        triplets.emplace_back(r, 3 * centre + k, -normal(k));
        triplets.emplace_back(r, 3 * left + k, 0.5 * normal(k));
        triplets.emplace_back(r, 3 * right + k, 0.5 * normal(k));
      }
    }
    const int n_rows = extra + (near_copy != 0 ? 1 : 0);
    if (near_copy != 0)
    {
      for (int k = 0; k < 3; ++k)
      {
        triplets.emplace_back(extra, 3 * top[1] + k, -normal(k));
        triplets.emplace_back(extra, 3 * top[0] + k, 0.5 * normal(k));
        triplets.emplace_back(extra, 3 * top[2] + k, 0.5 * normal(k));
      }
      triplets.emplace_back(extra, 3 * top[3], near_copy);
    }
    Eigen::SparseMatrix<double, Eigen::RowMajor> B(n_rows, 3 * mesh.n_nodes());
    B.setFromTriplets(triplets.begin(), triplets.end());
    s->rows.append(decomposition::rows_from_global(*s->box->decomp, B, la::Vector::Zero(n_rows)), s->n_equality);
  }
  s->feti = std::make_unique<dual::FetiOperators>(*s->box->system, s->rows);
  return s;
}
} // namespace

// Reference: the definition Y = (B B')^{-1}, with B B' applied as B (B' v) by the
// FETI operators (independent of the block assembly): Y (B B' v) = v for random v.
TEST(ConstraintScaling, InvertsBBtWithContactRows)
{
  const auto s = make_setup(4);
  const dual::ConstraintScaling Y(*s->feti, s->n_equality);
  ASSERT_TRUE(Y.factorized());
  // The 4 extra rows and the gluing rows of the interface nodes they touch.
  EXPECT_GT(Y.block_size(), 4);
  EXPECT_LT(Y.block_size(), s->feti->n_dual());
  const la::Vector v = la::Vector::Random(s->feti->n_dual());
  const la::Vector BBt_v = s->feti->apply_B(s->feti->apply_Bt(v));
  EXPECT_GT((BBt_v - v).norm(), 0.1 * v.norm()); // the rows are far from orthonormal
  EXPECT_LT((Y.apply(BBt_v) - v).norm(), 1e-12 * v.norm());
}

// Reference: B_E B_E' = I (Helmert gluing rows, unit Dirichlet rows), so without contact
// rows Y is the identity and no block is formed.
TEST(ConstraintScaling, IsTheIdentityForOrthonormalEqualityRows)
{
  const auto s = make_setup(0);
  const dual::ConstraintScaling Y(*s->feti, s->n_equality);
  EXPECT_EQ(Y.block_size(), 0);
  const la::Vector v = la::Vector::Random(s->feti->n_dual());
  EXPECT_LT((s->feti->apply_B(s->feti->apply_Bt(v)) - v).norm(), 1e-12 * v.norm());
  EXPECT_EQ(Y.apply(v), v);
}

// Reference: two rows of norm^2 1.5 that differ by d = 1e-3 e_x at one node: B B' has an
// eigenvalue of about d^2 / 2 (measured 2.5e-7 with the gluing rows), far below
// 1 / max_amplification, so Y would amplify by ~1e6; it falls back to the identity as for
// dependent rows. With d = 0.5 the scaling stays.
TEST(ConstraintScaling, FallsBackToTheIdentityForNearlyDependentRows)
{
  const auto nearly = make_setup(2, 1e-3);
  const dual::ConstraintScaling Y(*nearly->feti, nearly->n_equality);
  EXPECT_FALSE(Y.factorized());
  EXPECT_EQ(Y.block_size(), 0);
  const la::Vector v = la::Vector::Random(nearly->feti->n_dual());
  EXPECT_EQ(Y.apply(v), v);

  const auto apart = make_setup(2, 0.5);
  const dual::ConstraintScaling Z(*apart->feti, apart->n_equality);
  EXPECT_TRUE(Z.factorized());
  EXPECT_GT(Z.block_size(), 3);
}
