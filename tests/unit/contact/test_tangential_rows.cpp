/// Tests of build_tangential_rows (friction rows from normal contact rows). References: the
/// definitions of contact/tangential_rows.hpp (orthonormal tangents, the normal row's weights)
/// and linear algebra: a held row is a combination of the supports' rows e_k at its nodes.

#include "contact/tangential_rows.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace feticon::contact
{
namespace
{
/// One normal row: slave node 0 with normal n, master nodes 1 and 2 with weights 0.6 and 0.4
/// (row entries w n / |b|, w = -1 on the slave), over 3 nodes; with `fourth` != 0 a master
/// node 3 of that weight (over 4 nodes).
ContactConstraints one_row(const Eigen::Vector3d& n, double fourth = 0)
{
  ContactConstraints rows;
  const double norm = std::sqrt(1 + 0.6 * 0.6 + 0.4 * 0.4 + fourth * fourth);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < 3; ++c)
  {
    t.emplace_back(0, c, -n(c) / norm);
    t.emplace_back(0, 3 + c, 0.6 * n(c) / norm);
    t.emplace_back(0, 6 + c, 0.4 * n(c) / norm);
    if (fourth != 0)
      t.emplace_back(0, 9 + c, fourth * n(c) / norm);
  }
  rows.B.resize(1, fourth != 0 ? 12 : 9);
  rows.B.setFromTriplets(t.begin(), t.end());
  rows.slave_node = {0};
  rows.pair = {0};
  rows.normal = {n};
  rows.row_norm = {norm};
  return rows;
}
} // namespace

TEST(TangentialRows, ThreeDTangentsAreOrthonormalAndShareTheWeights)
{
  const Eigen::Vector3d n = Eigen::Vector3d(0.2, -0.3, 1).normalized();
  const TangentialRows rows = build_tangential_rows(one_row(n), {false, false, false});
  ASSERT_EQ(rows.n_rows(), 2);
  EXPECT_EQ(rows.n_tangents, 2);
  for (int k = 0; k < 2; ++k)
  {
    EXPECT_NEAR(rows.tangent[k].norm(), 1, 1e-14);
    EXPECT_NEAR(rows.tangent[k].dot(n), 0, 1e-14);
    EXPECT_FALSE(rows.held[k]);
    // The row is the normal row with n replaced by t_k.
    const double norm = std::sqrt(1 + 0.6 * 0.6 + 0.4 * 0.4);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(rows.B.coeff(k, c), -rows.tangent[k](c) / norm, 1e-14);
      EXPECT_NEAR(rows.B.coeff(k, 6 + c), 0.4 * rows.tangent[k](c) / norm, 1e-14);
    }
  }
  EXPECT_NEAR(rows.tangent[0].dot(rows.tangent[1]), 0, 1e-14);
}

TEST(TangentialRows, SymmetryPlaneThroughTheContactHoldsTheTangentAcrossIt)
{
  // n in the plane y = 0 and every node of the row held along y (a symmetry plane): t_2 = e_y,
  // held; its row is then -e_y at the slave and w_a e_y at the masters over |b|, a combination
  // of the supports' rows.
  const Eigen::Vector3d n = Eigen::Vector3d(0.1, 0, 1).normalized();
  const std::vector<int64_t> supported = {1, 4, 7}; // y of nodes 0, 1, 2
  const TangentialRows rows = build_tangential_rows(one_row(n), {false, false, false}, supported);
  ASSERT_EQ(rows.n_rows(), 2);
  EXPECT_FALSE(rows.held[0]);
  EXPECT_TRUE(rows.held[1]);
  EXPECT_NEAR(std::abs(rows.tangent[1].y()), 1, 1e-14);
  EXPECT_NEAR(rows.tangent[0].y(), 0, 1e-14);
  EXPECT_NEAR(rows.tangent[0].dot(n), 0, 1e-14);
  for (int node = 0; node < 3; ++node)
  {
    EXPECT_EQ(rows.B.coeff(1, 3 * node), 0.0);
    EXPECT_EQ(rows.B.coeff(1, 3 * node + 2), 0.0);
  }

  // One master node free along y: no symmetry plane, nothing held.
  const TangentialRows free = build_tangential_rows(one_row(n), {false, false, false}, {1, 4});
  EXPECT_FALSE(free.held[0] || free.held[1]);
  // A normal with a component along y: the plane is not a symmetry plane of the contact.
  const TangentialRows tilted =
      build_tangential_rows(one_row(Eigen::Vector3d(0, 0.1, 1).normalized()), {false, false, false}, supported);
  EXPECT_FALSE(tilted.held[0] || tilted.held[1]);
}

TEST(TangentialRows, MortarWeightsBesideTheSymmetryPlaneDoNotHideIt)
{
  // The dual mortar basis of a slave node on the plane reaches master nodes one cell row
  // beside it: 0.17 % of the row's norm on hertz3d. Node 3 is such a node, free along y.
  const Eigen::Vector3d n = Eigen::Vector3d(0.1, 0, 1).normalized();
  const std::vector<int64_t> supported = {1, 4, 7}; // y of nodes 0, 1, 2
  const TangentialRows beside = build_tangential_rows(one_row(n, 0.002), {false, false, false}, supported);
  EXPECT_FALSE(beside.held[0]);
  EXPECT_TRUE(beside.held[1]);
  // A master node off the plane with a weight of 10 % of the row: not a symmetry plane.
  const TangentialRows off = build_tangential_rows(one_row(n, 0.12), {false, false, false}, supported);
  EXPECT_FALSE(off.held[0] || off.held[1]);
  // The same rows from the transformed dual basis of quadratic faces, which reaches up to
  // 11.2 % of a plane node's row beside the plane (hertz3d hex20): held up to 15 %.
  ContactConstraints spread = one_row(n, 0.12);
  spread.transformed_basis = true;
  const TangentialRows quadratic = build_tangential_rows(spread, {false, false, false}, supported);
  EXPECT_FALSE(quadratic.held[0]);
  EXPECT_TRUE(quadratic.held[1]);
  ContactConstraints wider = one_row(n, 0.2);
  wider.transformed_basis = true;
  EXPECT_FALSE(build_tangential_rows(wider, {false, false, false}, supported).held[1]);
  // The slave node itself free along y: nothing held, whatever the masters.
  const TangentialRows slave_free = build_tangential_rows(one_row(n), {false, false, false}, {4, 7});
  EXPECT_FALSE(slave_free.held[0] || slave_free.held[1]);
  // A normal averaged over the faces on one side of the plane (current configuration): n_y =
  // 1.5e-3 measured on hertz3d's half model; still the symmetry plane: t_2 held (e_y up to
  // the tilt), t_1 = e_y x n in the plane.
  const TangentialRows one_sided =
      build_tangential_rows(one_row(Eigen::Vector3d(0.1, 1.5e-3, 1).normalized()), {false, false, false}, supported);
  EXPECT_TRUE(one_sided.held[1]);
  EXPECT_NEAR(one_sided.tangent[1].y(), 1, 2e-6);
  EXPECT_FALSE(one_sided.held[0]);
  EXPECT_EQ(one_sided.tangent[0].y(), 0.0);
}

TEST(TangentialRows, TwoSymmetryPlanesHoldBothTangents)
{
  // The line x = y = 0 of a quarter model: n = e_z, held along x and y at every node.
  const std::vector<int64_t> supported = {0, 1, 3, 4, 6, 7};
  const TangentialRows rows =
      build_tangential_rows(one_row(Eigen::Vector3d::UnitZ()), {false, false, false}, supported);
  EXPECT_TRUE(rows.held[0]);
  EXPECT_TRUE(rows.held[1]);
}

TEST(TangentialRows, PlaneStrainHasOneTangentAndHoldsNone)
{
  const Eigen::Vector3d n = Eigen::Vector3d(0.1, 1, 0).normalized();
  // z is eliminated (and so supported everywhere); the one tangent lies in the x-y plane.
  const TangentialRows rows = build_tangential_rows(one_row(n), {false, false, true}, {2, 5, 8});
  ASSERT_EQ(rows.n_rows(), 1);
  EXPECT_EQ(rows.n_tangents, 1);
  EXPECT_FALSE(rows.held[0]);
  EXPECT_NEAR(rows.tangent[0].z(), 0, 1e-14);
  EXPECT_NEAR(rows.tangent[0].dot(n), 0, 1e-14);
}
} // namespace feticon::contact

namespace feticon::contact
{
// A symmetry plane whose normal d is no global axis: every node held along its local axis 2
// (a *TRANSFORM, fem/node_frames.hpp), n normal to d. The same as for a global axis: t_2 = d,
// held; t_1 = d x n free. Node 2's local axis is turned 3 degrees (the next node of a thin
// sector whose circumferential direction a cylindrical system holds): still along d.
TEST(TangentialRows, SymmetryPlaneAlongALocalAxisHoldsTheTangentAcrossIt)
{
  const double angle = 0.3, turned = angle + 3 * std::acos(-1.0) / 180;
  const Eigen::Vector3d d(std::cos(angle), std::sin(angle), 0);
  const Eigen::Vector3d n =
      (Eigen::Vector3d(-std::sin(angle), std::cos(angle), 0) + 10 * Eigen::Vector3d::UnitZ()).normalized();
  fem::NodeFrames frames;
  frames.nodes = {0, 1, 2};
  for (const double a : {angle, angle, turned})
  {
    Eigen::Matrix3d axes;
    axes.row(0) = Eigen::Vector3d(-std::sin(a), std::cos(a), 0);
    axes.row(1) = Eigen::Vector3d(std::cos(a), std::sin(a), 0);
    axes.row(2) = Eigen::Vector3d(0, 0, -1);
    frames.axes.push_back(axes);
  }
  // Local component 1 (0-based) of frames 0, 1, 2: DOFs 3 (3 + k) + 1 for 3 mesh nodes.
  const std::vector<int64_t> supported = {10, 13, 16};
  const TangentialRows rows = build_tangential_rows(one_row(n), {false, false, false}, supported, &frames);
  ASSERT_EQ(rows.n_rows(), 2);
  EXPECT_FALSE(rows.held[0]);
  EXPECT_TRUE(rows.held[1]);
  EXPECT_NEAR(std::abs(rows.tangent[1].dot(d)), 1, 1e-14);
  EXPECT_NEAR(rows.tangent[0].dot(d), 0, 1e-14);
  EXPECT_NEAR(rows.tangent[0].dot(n), 0, 1e-14);
  // Node 2 held along another direction (its local axis 0): no symmetry plane.
  const TangentialRows other = build_tangential_rows(one_row(n), {false, false, false}, {10, 13, 15}, &frames);
  EXPECT_FALSE(other.held[0] || other.held[1]);
}
} // namespace feticon::contact
