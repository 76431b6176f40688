/// ADJUST of a contact pair (contact/adjust.hpp). Reference: the geometry itself: an upper
/// block 2 x 2 cells over a flat lower top face at z = 1; a moved slave node lands on z = 1
/// (a gap of 0 along the master normal e_z), x and y unchanged.

#include "contact/adjust.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace feticon::contact
{
namespace
{
/// Lower unit cube; upper cube over it at z = 1 + gap, its bottom nodes raised by `bump` at
/// x = 0 (so one row of slave nodes is farther away).
fem::Problem blocks(double gap, double bump)
{
  fem::Problem p;
  p.mesh = mesh::generate_box({.nx = 2, .ny = 2, .nz = 2, .body_name = "lower"});
  mesh::append_mesh(p.mesh,
                    mesh::generate_box({.origin = {0, 0, 1 + gap}, .nx = 2, .ny = 2, .nz = 2, .body_name = "upper"}),
                    "upper_");
  for (int32_t n : p.mesh.node_set("upper_zmin"))
    if (p.mesh.nodes(n, 0) == 0)
      p.mesh.nodes(n, 2) += bump;
  p.materials.assign(2, fem::Material{2e11, 0.3});
  p.contacts.push_back({"upper_zmin", "zmax"});
  return p;
}

/// The slave nodes' z, in node order.
std::vector<double> slave_z(const fem::Problem& p)
{
  std::vector<double> z;
  for (int32_t n : p.mesh.node_set("upper_zmin"))
    z.push_back(p.mesh.nodes(n, 2));
  return z;
}

TEST(Adjust, NodesWithinTheDistanceMoveOntoTheMaster)
{
  fem::Problem p = blocks(1e-3, 5e-3); // gaps 1e-3 (6 nodes) and 6e-3 (the 3 at x = 0)
  const mesh::Mesh before = p.mesh;
  p.contacts[0].adjust = 2e-3;
  EXPECT_EQ(adjust_slave_nodes(p), 6);
  for (int32_t n : p.mesh.node_set("upper_zmin"))
  {
    EXPECT_EQ(p.mesh.nodes(n, 0), before.nodes(n, 0));
    EXPECT_EQ(p.mesh.nodes(n, 1), before.nodes(n, 1));
    EXPECT_NEAR(p.mesh.nodes(n, 2), before.nodes(n, 0) == 0 ? 1 + 6e-3 : 1.0, 1e-15);
  }
  // Nothing else moves: the other nodes of the upper block keep their places.
  int moved_elsewhere = 0;
  for (int32_t n = 0; n < p.mesh.n_nodes(); ++n)
    moved_elsewhere += (p.mesh.nodes.row(n) - before.nodes.row(n)).norm() > 0 &&
        !std::binary_search(p.mesh.node_set("upper_zmin").begin(), p.mesh.node_set("upper_zmin").end(), n);
  EXPECT_EQ(moved_elsewhere, 0);
  // Gaps at the distance itself are moved too (CalculiX: smaller than or equal).
  fem::Problem exact = blocks(1e-3, 0);
  exact.contacts[0].adjust = 1e-3;
  EXPECT_EQ(adjust_slave_nodes(exact), 9);
}

TEST(Adjust, PenetratingNodesArePushedOutAndFarOnesStay)
{
  fem::Problem overlap = blocks(-1e-3, 0);
  overlap.contacts[0].adjust = 1e-4; // any distance: a penetration is a clearance below it
  EXPECT_EQ(adjust_slave_nodes(overlap), 9);
  for (double z : slave_z(overlap))
    EXPECT_NEAR(z, 1.0, 1e-15);
  fem::Problem far = blocks(1e-2, 0);
  far.contacts[0].adjust = 5e-3;
  EXPECT_EQ(adjust_slave_nodes(far), 0);
  fem::Problem none = blocks(1e-3, 0); // no ADJUST: the mesh as it is
  EXPECT_EQ(adjust_slave_nodes(none), 0);
}

TEST(Adjust, ANodeSetMovesItsNodesWhateverTheirGap)
{
  fem::Problem p = blocks(1e-3, 5e-3);
  std::vector<int32_t> set;
  for (int32_t n : p.mesh.node_set("upper_zmin"))
    if (p.mesh.nodes(n, 0) == 0)
      set.push_back(n);
  p.mesh.node_sets["raised"] = set;
  p.contacts[0].adjust_nodes = "raised";
  EXPECT_EQ(adjust_slave_nodes(p), 3);
  for (int32_t n : p.mesh.node_set("upper_zmin"))
    EXPECT_NEAR(p.mesh.nodes(n, 2), p.mesh.nodes(n, 0) == 0 ? 1.0 : 1 + 1e-3, 1e-15);
}
} // namespace
} // namespace feticon::contact
