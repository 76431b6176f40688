/// Tests of build_contact_constraints, contact_forces and slave_normal_forces.
/// References: ALGORITHMS.md section 4 tests (partition of unity, gap change along n, forces of a
/// row sum to zero), the closed-form gaps of flat stacked boxes and of a roof ridge, and central
/// finite differences of the exact gap for the linearization b = -grad_u g.

#include "contact/contact_constraints.hpp"

#include "common/error.hpp"

#include "contact_test_meshes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace feticon::contact
{
namespace
{
using test::upper_on_lower;

/// Row of `constraints` for slave node `node`, or -1.
la::Index row_of(const ContactConstraints& constraints, int32_t node)
{
  for (la::Index i = 0; i < constraints.n_rows(); ++i)
    if (constraints.slave_node[i] == node)
      return i;
  return -1;
}

/// Dense copy of row i.
la::Vector dense_row(const ContactConstraints& constraints, la::Index i)
{
  return la::Vector(constraints.B.row(i).transpose());
}
} // namespace

TEST(ContactConstraints, StackedBoxesGapNormalAndRowNorm)
{
  // Flat surfaces 1e-3 apart, non-matching 4 x 4 master and 3 x 3 slave faces: every slave node
  // projects inside (or onto the boundary of) the master surface with g = 1e-3 and n = +z, the
  // outward normal of the lower (master) body.
  const double gap = 1e-3;
  const mesh::Mesh mesh = test::stacked_boxes(gap);
  const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), upper_on_lower);
  ASSERT_EQ(rows.n_slave_nodes, 16);
  ASSERT_EQ(rows.n_rows(), 16);
  EXPECT_EQ(rows.n_overhanging, 0);
  EXPECT_NEAR(rows.search_distance, std::sqrt(2.0) * 0.25, 1e-15); // largest master diagonal
  EXPECT_EQ(rows.B.rows(), 16);
  EXPECT_EQ(rows.B.cols(), 3 * mesh.n_nodes());
  for (la::Index i = 0; i < rows.n_rows(); ++i)
  {
    EXPECT_EQ(rows.kind[i], ProjectionKind::face);
    // 1 + 1e-3 is not exact in binary: the gap is exact to round-off of the coordinates.
    EXPECT_NEAR(rows.gap[i], gap, 1e-15) << "row " << i;
    EXPECT_NEAR((rows.normal[i] - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
    const Eigen::Vector4d shape = quad_shape_functions(rows.xi[i]);
    EXPECT_NEAR(rows.row_norm[i], std::sqrt(1 + shape.squaredNorm()), 1e-15);
    EXPECT_NEAR(rows.c(i), rows.gap[i] / rows.row_norm[i], 1e-18);
    EXPECT_NEAR(dense_row(rows, i).norm(), 1.0, 1e-14) << "normalized row";
    // Slave z entry is -1/|b|.
    EXPECT_NEAR(rows.B.coeff(i, 3 * rows.slave_node[i] + 2), -1 / rows.row_norm[i], 1e-15);
  }
}

TEST(ContactConstraints, PenetrationGivesNegativeGapInCurrentConfiguration)
{
  // Reference gap 1e-3; the current configuration moves the upper body down by 3e-3, so the gap
  // is -2e-3 (penetration). With u = 0 and a reference overlap of 1e-3 the gap is -1e-3.
  mesh::Mesh mesh = test::stacked_boxes(1e-3);
  la::Vector u = la::Vector::Zero(3 * mesh.n_nodes());
  for (const int32_t node : mesh.node_set("upper_zmin"))
    u(3 * node + 2) = -3e-3;
  const ContactConstraints moved = build_contact_constraints(mesh, u, upper_on_lower);
  ASSERT_EQ(moved.n_rows(), 16);
  for (const double g : moved.gap)
    EXPECT_NEAR(g, -2e-3, 1e-15);

  const ContactConstraints overlap =
      build_contact_constraints(test::stacked_boxes(-1e-3), la::Vector(), upper_on_lower);
  ASSERT_EQ(overlap.n_rows(), 16);
  for (const double g : overlap.gap)
    EXPECT_NEAR(g, -1e-3, 1e-15);
}

TEST(ContactConstraints, RowsOnlyBelowSearchDistance)
{
  // Gap 0.1 against an explicit d_s = 0.05: no row; d_s = 0.2: all rows.
  const mesh::Mesh mesh = test::stacked_boxes(0.1);
  EXPECT_EQ(build_contact_constraints(mesh, la::Vector(), upper_on_lower, {.search_distance = 0.05}).n_rows(), 0);
  EXPECT_EQ(build_contact_constraints(mesh, la::Vector(), upper_on_lower, {.search_distance = 0.2}).n_rows(), 16);
}

TEST(ContactConstraints, NearContactRowsOnlyWhereTheBodiesTouchOrNearlyTouch)
{
  // The upper body tilted about the line x = 0, y free: the gap of a slave node is exactly
  // offset + slope x at x = 0, 1/3, 2/3, 1 (master flat, n = +z), four nodes per column. Master
  // diagonal sqrt(2) / 4, so f = 0.05 allows 0.0177 above the contact level max(g_min, 0).
  const mesh::Mesh mesh = test::stacked_boxes(0);
  const double allowance = 0.05 * std::sqrt(2.0) / 4;
  const auto rows_at = [&](double offset, double slope, double fraction) {
    la::Vector u = la::Vector::Zero(3 * mesh.n_nodes());
    for (const int32_t node : mesh.node_set("upper_zmin"))
      u(3 * node + 2) = offset + slope * mesh.nodes(node, 0);
    const ContactConstraints rows =
        build_contact_constraints(mesh, u, upper_on_lower, {.near_contact_fraction = fraction});
    for (la::Index i = 0; i < rows.n_rows(); ++i)
      EXPECT_NEAR(rows.gap[i], offset + slope * mesh.nodes(rows.slave_node[i], 0), 1e-14);
    return rows;
  };
  const auto expect_columns = [&](const ContactConstraints& rows, double offset, double slope) {
    const double level = std::max(offset, 0.0); // the smallest gap is at x = 0
    int expected = 0;
    for (const int32_t node : mesh.node_set("upper_zmin"))
    {
      const double gap = offset + slope * mesh.nodes(node, 0);
      const bool near = gap < level + allowance;
      expected += near;
      EXPECT_EQ(row_of(rows, node) >= 0, near) << "gap " << gap;
    }
    EXPECT_EQ(rows.n_rows(), expected);
  };
  // Touching at x = 0: the columns at gaps 0 and 0.01 (8 rows), not 0.02 and 0.03.
  const ContactConstraints touching = rows_at(0, 0.03, 0.05);
  EXPECT_EQ(touching.n_rows(), 8);
  expect_columns(touching, 0, 0.03);
  // Apart by 0.1: rows where the bodies are closest, the same two columns.
  const ContactConstraints apart = rows_at(0.1, 0.03, 0.05);
  EXPECT_EQ(apart.n_rows(), 8);
  expect_columns(apart, 0.1, 0.03);
  // Penetrating at x <= 1/3 (gaps -0.03, -0.01, 0.01, 0.03): three columns.
  const ContactConstraints penetrating = rows_at(-0.03, 0.06, 0.05);
  EXPECT_EQ(penetrating.n_rows(), 12);
  expect_columns(penetrating, -0.03, 0.06);
  // Default (infinity): every node within the search distance.
  EXPECT_EQ(rows_at(0, 0.03, std::numeric_limits<double>::infinity()).n_rows(), 16);
}

TEST(ContactConstraints, OverhangingSlaveNodesAreSkipped)
{
  // Upper block shifted by (0.5, 0.5): slave nodes at x, y in {0.5, 0.833, 1.167, 1.5}. The 4 with
  // x, y <= 0.833 get rows; the 5 others with x, y <= 1.167 are within d_s = 0.354 of the master
  // faces but beyond the boundary x = 1 or y = 1 (overhanging); the 7 with x or y = 1.5 have no
  // candidate face at all.
  const mesh::Mesh mesh = test::stacked_boxes(1e-3, 0.5, 0.5);
  const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), upper_on_lower);
  EXPECT_EQ(rows.n_rows(), 4);
  EXPECT_EQ(rows.n_overhanging, 5);
  for (la::Index i = 0; i < rows.n_rows(); ++i)
  {
    EXPECT_LE(mesh.nodes(rows.slave_node[i], 0), 1.0);
    EXPECT_LE(mesh.nodes(rows.slave_node[i], 1), 1.0);
    EXPECT_NEAR(rows.gap[i], 1e-3, 1e-15);
  }
}

TEST(ContactConstraints, RimExtensionKeepsNodesJustBeyondTheMasterBoundary)
{
  // Upper block shifted by dx along x: its 4 slave nodes at x = 1 + dx are beyond the master rim
  // x = 1 by dx / 0.125 in reference coordinates of the last master face (width 0.25). Within the
  // rim extension 0.05 (dx = 0.002, excess 0.016) they get rim rows with the face gap and normal;
  // beyond it (dx = 0.01, excess 0.08) they are skipped as overhanging.
  for (const double dx : {0.002, 0.01})
  {
    const mesh::Mesh mesh = test::stacked_boxes(1e-3, dx);
    const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), upper_on_lower);
    const bool within = dx / 0.125 <= ContactOptions{}.rim_extension;
    EXPECT_EQ(rows.n_overhanging, within ? 0 : 4) << "dx = " << dx;
    int n_rim = 0;
    for (la::Index i = 0; i < rows.n_rows(); ++i)
    {
      const bool beyond = mesh.nodes(rows.slave_node[i], 0) > 1;
      EXPECT_EQ(rows.kind[i], beyond ? ProjectionKind::rim : ProjectionKind::face);
      n_rim += beyond;
      EXPECT_NEAR(rows.gap[i], 1e-3, 1e-15);
      EXPECT_NEAR((rows.normal[i] - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
      if (beyond)
      {
        EXPECT_NEAR(rows.xi[i].cwiseAbs().maxCoeff(), 1 + dx / 0.125, 1e-12);
      }
    }
    EXPECT_EQ(n_rim, within ? 4 : 0) << "dx = " << dx;
    EXPECT_EQ(rows.n_rows(), within ? 16 : 12) << "dx = " << dx;
  }
  // Without the extension the rim nodes are skipped.
  const ContactConstraints strict =
      build_contact_constraints(test::stacked_boxes(1e-3, 0.002), la::Vector(), upper_on_lower, {.rim_extension = 0});
  EXPECT_EQ(strict.n_rows(), 12);
  EXPECT_EQ(strict.n_overhanging, 4);
}

TEST(ContactConstraints, NodeInContactJustOffTheMasterBoundaryTakesTheFaceNormal)
{
  // Slave nodes in contact (gap 1e-10) and 2e-7 beyond the master boundary x = 0: outside the
  // face projection's acceptance (1e-6 of the half-width 0.125) but within the rim tolerance
  // (1e-6 of the diagonal 0.354), as a node of a symmetry plane held there only to the
  // precision of its Dirichlet rows. The master surface is flat, so every row's normal is +z
  // and its gap 1e-10; the direction of the distance vector to the boundary side, (-2e-7, 0,
  // 1e-10), is no normal (it tilted the row by 90 degrees before).
  const mesh::Mesh mesh = test::stacked_boxes(1e-10, -2e-7);
  const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), upper_on_lower);
  ASSERT_EQ(rows.n_rows(), 16);
  int n_off = 0;
  for (la::Index i = 0; i < rows.n_rows(); ++i)
  {
    n_off += mesh.nodes(rows.slave_node[i], 0) < 0;
    EXPECT_NEAR((rows.normal[i] - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-12) << "row " << i;
    EXPECT_NEAR(rows.gap[i], 1e-10, 1e-15) << "row " << i;
  }
  EXPECT_EQ(n_off, 4);
}

TEST(ContactConstraints, RowsAnnihilateRigidTranslations)
{
  // Partition of unity: b . (t, t, ..., t) = -n.t + sum_a N_a n.t = 0 for every translation t.
  const mesh::Mesh mesh = test::wavy_blocks();
  const la::Vector u = test::random_displacement(mesh, 1e-3, 1);
  const ContactConstraints rows = build_contact_constraints(mesh, u, upper_on_lower);
  ASSERT_EQ(rows.n_rows(), rows.n_slave_nodes); // all slave nodes are over the master surface
  for (int component = 0; component < 3; ++component)
  {
    la::Vector translation = la::Vector::Zero(3 * mesh.n_nodes());
    for (int32_t node = 0; node < mesh.n_nodes(); ++node)
      translation(3 * node + component) = 1.0;
    EXPECT_LT((rows.B * translation).lpNorm<Eigen::Infinity>(), 1e-15) << "component " << component;
  }
}

TEST(ContactConstraints, ForcesOfEveryRowSumToZero)
{
  // -B' e_i: slave force +n/|b| and master forces -N_a n/|b|, summed over all nodes = 0.
  const mesh::Mesh mesh = test::wavy_blocks();
  const la::Vector u = test::random_displacement(mesh, 1e-3, 2);
  const ContactConstraints rows = build_contact_constraints(mesh, u, upper_on_lower);
  const int64_t n_dofs = 3 * mesh.n_nodes();
  ASSERT_GT(rows.n_rows(), 0);
  for (la::Index i = 0; i < rows.n_rows(); ++i)
  {
    const la::Vector unit = la::Vector::Unit(rows.n_rows(), i);
    const la::Vector forces = contact_forces(rows, unit, n_dofs);
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> nodal(forces.data(),
                                                                                            mesh.n_nodes(), 3);
    EXPECT_LT(nodal.colwise().sum().norm(), 1e-15) << "row " << i;
    // The slave force is (lambda_hat / |b|) n, pointing from the master towards the slave.
    const Eigen::Vector3d slave_force = nodal.row(rows.slave_node[i]).transpose();
    const double magnitude = slave_normal_forces(rows, unit)(i);
    EXPECT_NEAR(magnitude, 1 / rows.row_norm[i], 1e-15);
    EXPECT_NEAR((slave_force - magnitude * rows.normal[i]).norm(), 0, 1e-15) << "row " << i;
  }
}

TEST(ContactConstraints, MovingSlaveAlongNormalChangesGapByDelta)
{
  // x_s + delta n keeps xi_bar stationary (r_alpha = -delta x_,alpha . n = 0), so g -> g + delta.
  const mesh::Mesh mesh = test::wavy_blocks();
  const la::Vector u = test::random_displacement(mesh, 1e-3, 3);
  const ContactConstraints rows = build_contact_constraints(mesh, u, upper_on_lower);
  for (la::Index i = 0; i < rows.n_rows(); ++i)
    for (const double delta : {-5e-3, 2e-3})
    {
      la::Vector moved = u;
      moved.segment<3>(3 * rows.slave_node[i]) += delta * rows.normal[i];
      const ContactConstraints after = build_contact_constraints(mesh, moved, upper_on_lower);
      const la::Index j = row_of(after, rows.slave_node[i]);
      ASSERT_GE(j, 0);
      EXPECT_EQ(after.master_face[j], rows.master_face[i]);
      EXPECT_NEAR(after.c(j) * after.row_norm[j], rows.gap[i] + delta, 1e-13) << "row " << i << " delta " << delta;
    }
}

TEST(ContactConstraints, RowIsMinusGapGradient)
{
  // Central differences of the exact gap: g(u + eps du) - g(u - eps du) = -2 eps b du + O(eps^3).
  const mesh::Mesh mesh = test::wavy_blocks();
  const la::Vector u = test::random_displacement(mesh, 1e-3, 4);
  const la::Vector du = test::random_displacement(mesh, 1.0, 5);
  const ContactConstraints rows = build_contact_constraints(mesh, u, upper_on_lower);
  const double eps = 1e-6;
  const ContactConstraints plus = build_contact_constraints(mesh, u + eps * du, upper_on_lower);
  const ContactConstraints minus = build_contact_constraints(mesh, u - eps * du, upper_on_lower);
  const la::Vector slope = rows.B * du; // normalized: b du / |b|
  int n_checked = 0;
  for (la::Index i = 0; i < rows.n_rows(); ++i)
  {
    const la::Index p = row_of(plus, rows.slave_node[i]);
    const la::Index m = row_of(minus, rows.slave_node[i]);
    ASSERT_TRUE(p >= 0 && m >= 0);
    if (plus.master_face[p] != rows.master_face[i] || minus.master_face[m] != rows.master_face[i])
      continue; // moved across a face boundary: one-sided
    ++n_checked;
    const double difference = (plus.gap[p] - minus.gap[m]) / (2 * eps);
    // Error: curvature of g times eps^2 (~1e-12) plus round-off 1e-16 / eps (~1e-10).
    EXPECT_NEAR(difference, -slope(i) * rows.row_norm[i], 1e-8) << "row " << i;
  }
  EXPECT_GT(n_checked, rows.n_rows() / 2);
}

TEST(ContactConstraints, ConvexRidgeBlindSpotUsesNodeToEdgeRow)
{
  // Slave nodes at x = 0.5 (z = 1.1) lie straight above the ridge x = 0.5, z = 1: their
  // projections fall outside both roof faces, so they get edge rows with n = +z, g = 0.1.
  // Slave nodes at x = 0.25 and 0.75 project inside a roof face: the face plane through
  // (0, ., 0.8) and (0.5, ., 1) has normal (-0.4, 0, 1)/sqrt(1.16), so g = 0.2/sqrt(1.16).
  const mesh::Mesh mesh = test::roof_and_block();
  const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), upper_on_lower);
  ASSERT_EQ(rows.n_rows(), 6);
  EXPECT_EQ(rows.n_overhanging, 0);
  int n_edge = 0;
  for (la::Index i = 0; i < rows.n_rows(); ++i)
  {
    const double x = mesh.nodes(rows.slave_node[i], 0);
    if (std::abs(x - 0.5) < 1e-12)
    {
      ++n_edge;
      EXPECT_EQ(rows.kind[i], ProjectionKind::edge);
      EXPECT_NEAR(rows.gap[i], 0.1, 1e-14);
      EXPECT_NEAR((rows.normal[i] - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-14);
      // The ridge ends are corners: one master node carries N = 1, |b| = sqrt(2).
      EXPECT_NEAR(rows.row_norm[i], std::sqrt(2.0), 1e-14);
    }
    else
    {
      EXPECT_EQ(rows.kind[i], ProjectionKind::face);
      EXPECT_NEAR(rows.gap[i], 0.2 / std::sqrt(1.16), 1e-14);
    }
  }
  EXPECT_EQ(n_edge, 2);

  // Edge rows are -grad_u g too: move a ridge slave node sideways within the blind spot, where
  // g = sqrt(dx^2 + 0.1^2) (distance to the ridge line), and compare with b du.
  const la::Index i = [&] {
    for (la::Index k = 0; k < rows.n_rows(); ++k)
      if (rows.kind[k] == ProjectionKind::edge)
        return k;
    return la::Index(-1);
  }();
  ASSERT_GE(i, 0);
  la::Vector u = la::Vector::Zero(3 * mesh.n_nodes());
  const double dx = 0.01; // within the blind spot: |dx| / 0.1 < tan(atan(0.4)) = 0.4
  u(3 * rows.slave_node[i]) = dx;
  const ContactConstraints moved = build_contact_constraints(mesh, u, upper_on_lower);
  const la::Index j = row_of(moved, rows.slave_node[i]);
  ASSERT_GE(j, 0);
  EXPECT_EQ(moved.kind[j], ProjectionKind::edge);
  EXPECT_NEAR(moved.gap[j], std::hypot(dx, 0.1), 1e-14);
  const Eigen::Vector3d expected_normal = Eigen::Vector3d(dx, 0, 0.1).normalized();
  EXPECT_NEAR((moved.normal[j] - expected_normal).norm(), 0, 1e-14);
  // Lateral sensitivity dg/dx_s = dx / g equals -b_x (unnormalized) of the moved row.
  EXPECT_NEAR(-moved.B.coeff(j, 3 * rows.slave_node[i]) * moved.row_norm[j], dx / std::hypot(dx, 0.1), 1e-14);
}

TEST(ContactConstraints, InvalidInputThrows)
{
  const mesh::Mesh mesh = test::stacked_boxes(1e-3);
  EXPECT_THROW(build_contact_constraints(mesh, la::Vector::Zero(5), upper_on_lower), Error);
  EXPECT_THROW(build_contact_constraints(mesh, la::Vector(), upper_on_lower, {.search_distance = -1}), Error);
  EXPECT_THROW(build_contact_constraints(mesh, la::Vector(), upper_on_lower, {.rim_extension = -0.1}), Error);
  EXPECT_THROW(build_contact_constraints(mesh, la::Vector(), upper_on_lower, {.near_contact_fraction = 0}), Error);
  EXPECT_THROW(build_contact_constraints(mesh, la::Vector(), {.slave = "upper_zmin", .master = "nope"}), Error);
  const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), upper_on_lower);
  EXPECT_THROW(contact_forces(rows, la::Vector::Zero(rows.n_rows() + 1), 3 * mesh.n_nodes()), Error);
  EXPECT_THROW(contact_forces(rows, la::Vector::Zero(rows.n_rows()), 7), Error);
}
} // namespace feticon::contact
