/// Tests of local coordinate systems of nodes (fem/node_frames.hpp). References: CalculiX's
/// *TRANSFORM definitions (user's manual; transformatrix.f for a point on the cylinder axis),
/// worked by hand below.

#include "fem/node_frames.hpp"

#include "common/error.hpp"

#include <gtest/gtest.h>

namespace feticon::fem
{
TEST(NodeFrames, RectangularSystemOfTheManualsExample)
{
  // "*TRANSFORM, NSET=No1, TYPE=R / 0.,1.,0.,0.,0.,1.": local x and y are the global y and z.
  const Eigen::Matrix3d axes = rectangular_axes({0, 1, 0}, {0, 0, 1});
  EXPECT_TRUE(axes.row(0).isApprox(Eigen::RowVector3d(0, 1, 0), 1e-15));
  EXPECT_TRUE(axes.row(1).isApprox(Eigen::RowVector3d(0, 0, 1), 1e-15));
  EXPECT_TRUE(axes.row(2).isApprox(Eigen::RowVector3d(1, 0, 0), 1e-15));
  EXPECT_THROW(rectangular_axes({0, 0, 0}, {0, 1, 0}), Error);
  EXPECT_THROW(rectangular_axes({1, 0, 0}, {2, 0, 0}), Error);
}

TEST(NodeFrames, CylindricalSystemIsRadialTangentialAxial)
{
  // Axis z through the origin; at (0, 2, 5): radial y, tangential -x (z x y), axial z.
  const Eigen::Matrix3d axes = cylindrical_axes({0, 0, 0}, {0, 0, 1}, {0, 2, 5});
  EXPECT_TRUE(axes.row(0).isApprox(Eigen::RowVector3d(0, 1, 0), 1e-15));
  EXPECT_TRUE(axes.row(1).isApprox(Eigen::RowVector3d(-1, 0, 0), 1e-15));
  EXPECT_TRUE(axes.row(2).isApprox(Eigen::RowVector3d(0, 0, 1), 1e-15));
  // On the axis, CalculiX's choice: e3 = z, so e1 = (1, 0, -e3x / e3z) = x.
  const Eigen::Matrix3d on_axis = cylindrical_axes({0, 0, 0}, {0, 0, 1}, {0, 0, 3});
  EXPECT_TRUE(on_axis.row(0).isApprox(Eigen::RowVector3d(1, 0, 0), 1e-15));
  EXPECT_THROW(cylindrical_axes({1, 1, 1}, {1, 1, 1}, {0, 0, 0}), Error);
}

TEST(NodeFrames, HeldComponentsAreGlobalAlongGlobalAxesAndLocalElse)
{
  NodeFrames frames;
  frames.nodes = {4};
  frames.axes = {cylindrical_axes({0, 0, 0}, {0, 0, 1}, {std::sqrt(0.5), std::sqrt(0.5), 0})};
  const int32_t n_nodes = 10;
  // Axial: global z of node 4, same value. Radial: local DOF 3 (10 + 0) + 0 = 30.
  EXPECT_EQ(frames.held(n_nodes, 4, 2, 0.5), (std::pair<int64_t, double>{14, 0.5}));
  EXPECT_EQ(frames.held(n_nodes, 4, 0, 0.5), (std::pair<int64_t, double>{30, 0.5}));
  EXPECT_TRUE(NodeFrames::is_local(n_nodes, 30));
  EXPECT_EQ(frames.node_of(n_nodes, 31), 4);
  EXPECT_TRUE(frames.direction_of(n_nodes, 31).isApprox(Eigen::Vector3d(-std::sqrt(0.5), std::sqrt(0.5), 0), 1e-15));
  // A frame whose local x is -x globally: the value changes sign.
  NodeFrames flipped;
  flipped.nodes = {1};
  flipped.axes = {rectangular_axes({-1, 0, 0}, {0, -1, 0})};
  EXPECT_EQ(flipped.held(n_nodes, 1, 0, 0.5), (std::pair<int64_t, double>{3, -0.5}));
  // u extended with the local components of node 4.
  la::Vector u = la::Vector::Zero(3 * n_nodes);
  u.segment<3>(12) = Eigen::Vector3d(1, 1, 2);
  const la::Vector extended = frames.extended(u);
  ASSERT_EQ(extended.size(), 3 * n_nodes + 3);
  EXPECT_NEAR(extended(30), std::sqrt(2.0), 1e-15); // radial
  EXPECT_NEAR(extended(31), 0, 1e-15);              // tangential
  EXPECT_NEAR(extended(32), 2, 1e-15);              // axial
}
} // namespace feticon::fem
