/// Tests of the dual mortar rows (mortar_constraints.hpp; the integration building blocks are
/// tested in test_mortar_integration.cpp).
/// References: closed-form parallelogram nodal areas and overlap areas, node-to-segment rows on
/// matching meshes, and the consistent nodal loads int N_a dA of a
/// uniform pressure computed independently on each master face (axis-aligned sub-rectangles
/// before an affine map, 3 x 3 Gauss: no clipping, no inverse maps, no triangle rule).

#include "contact/mortar_constraints.hpp"

#include "common/error.hpp"

#include "contact_row_checks.hpp"
#include "contact_test_meshes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace feticon::contact
{
namespace
{
using row_checks::expect_rows_annihilate_translations;
using row_checks::weight_sum;

using test::upper_on_lower;

ContactOptions mortar_options()
{
  ContactOptions options;
  options.formulation = ContactFormulation::mortar;
  return options;
}

/// Flat lower box [0,1]^2 x [0,1] (master top "lower_zmax") and upper box (slave bottom
/// "upper_zmin") over [origin, origin + lengths] at z = 1 + gap, then the affine map
/// x -> map x + shift (a rotation times a shear, det = 1) applied to every node, so that both
/// surfaces are tilted and meshed by parallelograms. `reference` keeps the unmapped mesh.
struct FlatPair
{
  mesh::Mesh mesh;
  mesh::Mesh reference;
  Eigen::Matrix3d map;
  /// Area factor of the map on planes z = const: |map e_x x map e_y|.
  double area_factor = 1;
};

FlatPair flat_pair(std::array<int, 2> master_cells, std::array<int, 2> slave_cells, const Eigen::Vector2d& origin,
                   const Eigen::Vector2d& lengths, double gap)
{
  FlatPair pair;
  mesh::append_mesh(
      pair.reference,
      mesh::generate_box(
          {.lengths = {1, 1, 1}, .nx = master_cells[0], .ny = master_cells[1], .nz = 1, .body_name = "lower"}),
      "lower_");
  mesh::append_mesh(pair.reference,
                    mesh::generate_box({.origin = {origin(0), origin(1), 1 + gap},
                                        .lengths = {lengths(0), lengths(1), 0.5},
                                        .nx = slave_cells[0],
                                        .ny = slave_cells[1],
                                        .nz = 1,
                                        .body_name = "upper"}),
                    "upper_");
  Eigen::Matrix3d shear;
  shear << 1, 0.3, 0, 0, 1, 0, 0, 0, 1;
  pair.map = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() * shear;
  pair.area_factor = (pair.map.col(0).cross(pair.map.col(1))).norm();
  pair.mesh = pair.reference;
  for (int32_t node = 0; node < pair.mesh.n_nodes(); ++node)
    pair.mesh.nodes.row(node) =
        (pair.map * pair.reference.nodes.row(node).transpose() + Eigen::Vector3d(0.1, -0.2, 0.3)).transpose();
  return pair;
}

/// Axis-aligned bounds of a face of the unmapped mesh (the faces of both sets are rectangles).
struct Rectangle
{
  Eigen::Vector2d lower = Eigen::Vector2d::Constant(1e300);
  Eigen::Vector2d upper = Eigen::Vector2d::Constant(-1e300);
};

Rectangle rectangle_of(const FlatPair& pair, const mesh::Face& face)
{
  Rectangle rectangle;
  for (const int32_t node : face)
  {
    const Eigen::Vector2d corner = pair.reference.nodes.row(node).head<2>().transpose();
    rectangle.lower = rectangle.lower.cwiseMin(corner);
    rectangle.upper = rectangle.upper.cwiseMax(corner);
  }
  return rectangle;
}

/// Bilinear shape function of corner `node` of the rectangle at `point`: a product of 1D hats.
double hat(const FlatPair& pair, int32_t node, const Rectangle& rectangle, const Eigen::Vector2d& point)
{
  const Eigen::Vector2d corner = pair.reference.nodes.row(node).head<2>().transpose();
  const Eigen::Vector2d value =
      Eigen::Vector2d::Ones() - (point - corner).cwiseAbs().cwiseQuotient(rectangle.upper - rectangle.lower);
  return value.prod();
}

/// Calls visit(point, weight) at the 3 x 3 Gauss points of the intersection of two rectangles
/// (exact for degree 5 per direction), with the weights scaled by the area factor of the map.
template <class Visit>
void integrate_intersection(const FlatPair& pair, const Rectangle& first, const Rectangle& second, Visit&& visit)
{
  const Eigen::Vector2d low = first.lower.cwiseMax(second.lower);
  const Eigen::Vector2d high = first.upper.cwiseMin(second.upper);
  if (!(low.array() < high.array()).all())
    return;
  const double node = std::sqrt(0.6);
  const std::array<std::pair<double, double>, 3> line = {{{-node, 5.0 / 9}, {0.0, 8.0 / 9}, {node, 5.0 / 9}}};
  const Eigen::Vector2d mid = 0.5 * (low + high);
  const Eigen::Vector2d half = 0.5 * (high - low);
  for (const auto& [s, weight_s] : line)
    for (const auto& [t, weight_t] : line)
      visit(Eigen::Vector2d(mid + Eigen::Vector2d(s * half(0), t * half(1))),
            weight_s * weight_t * half.prod() * pair.area_factor);
}

/// int N_a dA over the part of every master face covered by the rectangle [lower, upper] (before
/// the map), per master node (m^2).
la::Vector consistent_master_loads(const FlatPair& pair, const Eigen::Vector2d& lower, const Eigen::Vector2d& upper)
{
  la::Vector loads = la::Vector::Zero(pair.mesh.n_nodes());
  for (const mesh::Face& face : pair.reference.face_set(upper_on_lower.master))
  {
    const Rectangle rectangle = rectangle_of(pair, face);
    integrate_intersection(pair, rectangle, Rectangle{lower, upper}, [&](const Eigen::Vector2d& point, double weight) {
      for (const int32_t node : face)
        loads(node) += weight * hat(pair, node, rectangle, point);
    });
  }
  return loads;
}

/// M_ja = int Phi_j N_a^m dA by intersecting the rectangles of every slave and master face before
/// the map: Phi_j N_a^m is biquadratic there, so 3 x 3 Gauss is exact. Phi_j = sum_k A_jk N_k
/// with A from dual_basis (tested on its own). Rows: slave nodes in `slave_nodes` order.
Eigen::MatrixXd reference_coupling(const FlatPair& pair, const std::vector<int32_t>& slave_nodes)
{
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(static_cast<la::Index>(slave_nodes.size()), pair.mesh.n_nodes());
  for (const mesh::Face& slave : pair.reference.face_set(upper_on_lower.slave))
  {
    const Rectangle slave_rectangle = rectangle_of(pair, slave);
    const DualBasis dual = dual_basis(current_face_coordinates(pair.mesh, la::Vector(), slave));
    for (const mesh::Face& master : pair.reference.face_set(upper_on_lower.master))
    {
      const Rectangle master_rectangle = rectangle_of(pair, master);
      integrate_intersection(pair, slave_rectangle, master_rectangle, [&](const Eigen::Vector2d& point, double weight) {
        Eigen::Vector4d shape;
        for (int k = 0; k < 4; ++k)
          shape(k) = hat(pair, slave[k], slave_rectangle, point);
        const Eigen::Vector4d dual_shape = dual.coefficients * shape;
        for (int k = 0; k < 4; ++k)
        {
          const auto j = std::ranges::lower_bound(slave_nodes, slave[k]) - slave_nodes.begin();
          for (const int32_t a : master)
            coupling(j, a) += weight * dual_shape(k) * hat(pair, a, master_rectangle, point);
        }
      });
    }
  }
  return coupling;
}

/// Dense copy of row i of B.
} // namespace

TEST(MortarConstraints, PartitionOfUnityOnNonMatchingSurfaces)
{
  // Reference: sum_a N_a^m = 1 at every point makes sum_a M_ja = int Phi_j dA = D_j for a support
  // entirely over the master surface, and the renormalization makes sum_a w_ja = 1 exactly
  // elsewhere; then b . (t, ..., t) = (-1 + sum_a w_ja) n . t = 0 for every translation t.
  // (1) Curved, warped, non-matching faces (wavy blocks, all slave supports over the master).
  const mesh::Mesh wavy = test::wavy_blocks();
  const la::Vector u = test::random_displacement(wavy, 1e-3, 1);
  const ContactConstraints rows = build_contact_constraints(wavy, u, upper_on_lower, mortar_options());
  ASSERT_EQ(rows.n_rows(), rows.n_slave_nodes);
  for (la::Index i = 0; i < rows.n_rows(); ++i)
    EXPECT_NEAR(weight_sum(rows, i), 1.0, 1e-14) << "row " << i;
  expect_rows_annihilate_translations(rows, wavy.n_nodes());
  const MortarCoupling coupling = compute_mortar_coupling(wavy, u, upper_on_lower, rows.search_distance);
  double worst = 0;
  for (la::Index j = 0; j < coupling.M.rows(); ++j)
    worst = std::max(worst, std::abs(coupling.M.row(j).sum() / coupling.slave.area(j) - 1));
  // Not exact on warped faces (J_s / J_p and the inverse maps are not polynomial): measured
  // 9e-12; the bound sits 2 orders above and far below any effect on a (renormalized) row.
  std::cout << "wavy blocks: max |sum_a M_ja / D_j - 1| = " << worst << "\n";
  EXPECT_LT(worst, 1e-9);

  // (2) Flat non-matching faces, the slave block shifted half out of the master surface: the
  // boundary nodes overlap only in part, are renormalized, or skipped below the minimum overlap.
  const mesh::Mesh shifted = test::stacked_boxes(1e-3, 0.3, 0.2);
  const ContactConstraints partial = build_contact_constraints(shifted, la::Vector(), upper_on_lower, mortar_options());
  const MortarCoupling partial_coupling =
      compute_mortar_coupling(shifted, la::Vector(), upper_on_lower, partial.search_distance);
  int n_renormalized = 0;
  for (la::Index i = 0; i < partial.n_rows(); ++i)
  {
    EXPECT_NEAR(weight_sum(partial, i), 1.0, 1e-14) << "row " << i;
    const int32_t j = partial_coupling.slave.index_of(partial.slave_node[i]);
    const double overlap = partial_coupling.M.row(j).sum() / partial_coupling.slave.area(j);
    EXPECT_GE(overlap, ContactOptions{}.mortar_min_overlap);
    n_renormalized += overlap < 1 - 1e-12;
  }
  EXPECT_GT(n_renormalized, 0);
  expect_rows_annihilate_translations(partial, shifted.n_nodes());
}

TEST(MortarConstraints, CouplingOfGivenRowNodesEqualsTheFullOneBitForBit)
{
  // Reference: the full computation. Only the faces around the given nodes are integrated, and
  // those are all the faces that contribute to their D_j and M_ja.
  const mesh::Mesh wavy = test::wavy_blocks();
  const la::Vector u = test::random_displacement(wavy, 1e-3, 2);
  const MortarCoupling full = compute_mortar_coupling(wavy, u, upper_on_lower, 0.3);
  const std::vector<int32_t> row_nodes{full.slave.nodes[0], full.slave.nodes[7]};
  const MortarCoupling part = compute_mortar_coupling(wavy, u, upper_on_lower, 0.3, {}, &row_nodes);
  for (const int32_t node : row_nodes)
  {
    const la::Index j = full.slave.index_of(node);
    EXPECT_EQ(part.slave.area(j), full.slave.area(j));
    const la::Vector full_row = full.M.row(j).transpose(), part_row = part.M.row(j).transpose();
    EXPECT_EQ((full_row - part_row).cwiseAbs().maxCoeff(), 0.0) << "node " << node;
    EXPECT_GT(full_row.norm(), 0);
  }
  EXPECT_LT(part.n_segments, full.n_segments);
}

TEST(MortarConstraints, MatchingFlatMeshesGiveNodeToSegmentRows)
{
  // Reference: on matching flat meshes every slave node coincides with a master node, so the
  // node-to-segment weights are N_a(xi_bar) = delta, and biorthogonality gives
  // M_ja = int Phi_j N_j = D_j for the coincident node and 0 otherwise: the same rows.
  // Tolerance: round-off of the segment sums (about 100 terms of size D_j) and of the mapped
  // coordinates, well below 1e-12.
  const FlatPair pair = flat_pair({3, 4}, {3, 4}, {0, 0}, {1, 1}, 1e-3);
  const Eigen::Vector3d normal = (pair.map.inverse().transpose() * Eigen::Vector3d::UnitZ()).normalized();
  la::Vector press = la::Vector::Zero(3 * pair.mesh.n_nodes());
  for (const int32_t node : pair.mesh.face_set_nodes(upper_on_lower.slave))
    press.segment<3>(3 * node) = -3e-3 * normal; // penetration of 2e-3
  for (const la::Vector& u : {la::Vector(), press})
  {
    const ContactConstraints nts = build_contact_constraints(pair.mesh, u, upper_on_lower);
    const ContactConstraints mortar = build_contact_constraints(pair.mesh, u, upper_on_lower, mortar_options());
    ASSERT_EQ(nts.n_rows(), 20);
    ASSERT_EQ(mortar.n_rows(), nts.n_rows());
    EXPECT_EQ(mortar.slave_node, nts.slave_node);
    for (la::Index i = 0; i < nts.n_rows(); ++i)
    {
      EXPECT_NEAR((mortar.normal[i] - normal).norm(), 0, 1e-14);
      EXPECT_NEAR(mortar.gap[i], nts.gap[i], 1e-12) << "row " << i;
      EXPECT_NEAR(mortar.gap[i], u.size() > 0 ? -2e-3 : 1e-3, 1e-12) << "row " << i;
      EXPECT_NEAR(mortar.row_norm[i], std::sqrt(2.0), 1e-12) << "row " << i;
      EXPECT_NEAR(mortar.row_norm[i], nts.row_norm[i], 1e-12) << "row " << i;
      EXPECT_NEAR(mortar.c(i), nts.c(i), 1e-12) << "row " << i;
      EXPECT_EQ(mortar.slave_area[i], nts.slave_area[i]);
    }
    EXPECT_LT(Eigen::MatrixXd(mortar.B - nts.B).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(MortarConstraints, SegmentationReproducesMasterIntegrals)
{
  // Reference: sum_j Phi_j = 1, so sum_j M_ja = int_overlap N_a^m dA, computed independently by
  // consistent_master_loads (axis-aligned sub-rectangles before the affine map, exact 3 x 3
  // Gauss), and each M_ja by reference_coupling (the same on slave x master rectangles). The
  // faces are parallelograms in a tilted plane, so all maps are affine and the segment quadrature
  // (degree 8 on triangles, integrand degree 4) is exact: the tolerance 1e-12 (areas are
  // O(0.01 - 1) m^2) covers round-off only. The slave surface hangs over the master rim in both
  // configurations (partial overlap), with the slave coarser and then finer.
  struct Case
  {
    std::array<int, 2> master_cells, slave_cells;
    Eigen::Vector2d origin, lengths;
  };
  for (const Case& test_case :
       {Case{{4, 4}, {3, 3}, {0.3, -0.2}, {1.0, 0.9}}, Case{{3, 2}, {5, 7}, {-0.1, 0.15}, {0.8, 1.2}}})
  {
    const FlatPair pair =
        flat_pair(test_case.master_cells, test_case.slave_cells, test_case.origin, test_case.lengths, 2e-3);
    const Eigen::Vector2d lower = test_case.origin;
    const Eigen::Vector2d upper = test_case.origin + test_case.lengths;
    const MortarCoupling coupling = compute_mortar_coupling(pair.mesh, la::Vector(), upper_on_lower, 0.5);
    const la::Vector reference = consistent_master_loads(pair, lower, upper);
    const la::Vector column_sums = la::Vector(Eigen::RowVectorXd::Ones(coupling.M.rows()) * coupling.M).transpose();
    EXPECT_GT(reference.maxCoeff(), 0.01);
    EXPECT_LT((column_sums - reference).lpNorm<Eigen::Infinity>(), 1e-12);
    // Total: the overlap area.
    const Eigen::Vector2d overlap = upper.cwiseMin(Eigen::Vector2d::Ones()) - lower.cwiseMax(Eigen::Vector2d::Zero());
    EXPECT_NEAR(coupling.M.sum(), overlap.prod() * pair.area_factor, 1e-12);
    // Entry by entry against the rectangle intersections: the degree of the segment rule matters
    // here (the sums above only integrate N_a^m).
    const Eigen::MatrixXd entries = reference_coupling(pair, coupling.slave.nodes);
    EXPECT_GT(entries.cwiseAbs().maxCoeff(), 0.01);
    EXPECT_LT((Eigen::MatrixXd(coupling.M) - entries).cwiseAbs().maxCoeff(), 1e-12);

    // D_j: a quarter of each adjacent parallelogram; and sum_a M_ja = D_j where the support of j
    // lies entirely over the master surface [0, 1]^2 (before the map).
    const Eigen::Vector2d slave_cell(test_case.lengths(0) / test_case.slave_cells[0],
                                     test_case.lengths(1) / test_case.slave_cells[1]);
    int n_inside = 0;
    for (size_t j = 0; j < coupling.slave.nodes.size(); ++j)
    {
      const Eigen::Vector2d x = pair.reference.nodes.row(coupling.slave.nodes[j]).head<2>().transpose();
      const Eigen::Vector2d from_lower = (x - lower).cwiseQuotient(slave_cell);
      const Eigen::Vector2d to_upper = (upper - x).cwiseQuotient(slave_cell);
      int n_faces = 1;
      for (int axis = 0; axis < 2; ++axis)
        n_faces *= (from_lower(axis) > 0.5 ? 1 : 0) + (to_upper(axis) > 0.5 ? 1 : 0);
      EXPECT_NEAR(coupling.slave.area(j), n_faces * slave_cell.prod() * pair.area_factor / 4, 1e-14);
      const Eigen::Vector2d support_low = (x - slave_cell).cwiseMax(lower);
      const Eigen::Vector2d support_high = (x + slave_cell).cwiseMin(upper);
      if ((support_low.array() >= 0).all() && (support_high.array() <= 1).all())
      {
        ++n_inside;
        EXPECT_NEAR(coupling.M.row(j).sum(), coupling.slave.area(j), 1e-14);
      }
    }
    EXPECT_GT(n_inside, 0);
  }
}

TEST(MortarConstraints, UniformPressureGivesConsistentNodalForces)
{
  // Reference (the contact patch test): with lambda_j = p D_j on every row the constraint forces
  // -B' lambda_hat are +p D_j n on slave node j and -p int_overlap N_a^m dA n on master node a,
  // i.e. the consistent nodal forces of the uniform pressure p on both surfaces (D_j and the
  // master integrals from closed forms and consistent_master_loads). Slave block strictly inside
  // the master surface, so no row is renormalized. Tolerance: round-off, relative 1e-12 of
  // p * 1 m^2. The node-to-segment rows on the same mesh must violate the master balance: the
  // check is not vacuous.
  const FlatPair pair = flat_pair({4, 4}, {3, 3}, {0.1, 0.15}, {0.8, 0.7}, 0);
  const Eigen::Vector3d normal = (pair.map.inverse().transpose() * Eigen::Vector3d::UnitZ()).normalized();
  const double pressure = 2.5e6;
  const la::Vector master_loads = consistent_master_loads(pair, {0.1, 0.15}, {0.9, 0.85});
  const int64_t n_dofs = 3 * pair.mesh.n_nodes();
  const std::vector<int32_t> master_nodes = pair.mesh.face_set_nodes(upper_on_lower.master);

  double nts_error = 0;
  for (const ContactFormulation formulation : {ContactFormulation::mortar, ContactFormulation::node_to_segment})
  {
    ContactOptions options;
    options.formulation = formulation;
    const ContactConstraints rows = build_contact_constraints(pair.mesh, la::Vector(), upper_on_lower, options);
    ASSERT_EQ(rows.n_rows(), 16);
    la::Vector lambda_hat(rows.n_rows());
    for (la::Index i = 0; i < rows.n_rows(); ++i)
      lambda_hat(i) = pressure * rows.slave_area[i] * rows.row_norm[i];
    const la::Vector forces = contact_forces(rows, lambda_hat, n_dofs);
    double master_error = 0;
    for (const int32_t a : master_nodes)
      master_error = std::max(master_error, (forces.segment<3>(3 * a) + pressure * master_loads(a) * normal).norm());
    if (formulation == ContactFormulation::node_to_segment)
    {
      nts_error = master_error;
      continue;
    }
    EXPECT_LT(master_error, 1e-12 * pressure);
    const Eigen::Vector2d slave_cell(0.8 / 3, 0.7 / 3);
    for (la::Index i = 0; i < rows.n_rows(); ++i)
    {
      const Eigen::Vector2d x = pair.reference.nodes.row(rows.slave_node[i]).head<2>().transpose();
      const bool edge_x = std::abs(x(0) - 0.1) < 1e-9 || std::abs(x(0) - 0.9) < 1e-9;
      const bool edge_y = std::abs(x(1) - 0.15) < 1e-9 || std::abs(x(1) - 0.85) < 1e-9;
      const double area = (edge_x ? 1 : 2) * (edge_y ? 1 : 2) * slave_cell.prod() * pair.area_factor / 4;
      EXPECT_NEAR((forces.segment<3>(3 * rows.slave_node[i]) - pressure * area * normal).norm(), 0, 1e-12 * pressure);
    }
  }
  std::cout << "uniform pressure: largest master nodal force error of node-to-segment rows " << nts_error / pressure
            << " m^2 * p\n";
  EXPECT_GT(nts_error, 1e-3 * pressure);
}

TEST(MortarConstraints, InvalidInputThrows)
{
  const mesh::Mesh mesh = test::stacked_boxes(1e-3);
  for (const double overlap : {0.0, -0.1, 1.5})
  {
    ContactOptions options = mortar_options();
    options.mortar_min_overlap = overlap;
    EXPECT_THROW(build_contact_constraints(mesh, la::Vector(), upper_on_lower, options), Error);
  }
  EXPECT_THROW(compute_mortar_coupling(mesh, la::Vector(), upper_on_lower, 0), Error);
  EXPECT_THROW(compute_mortar_coupling(mesh, la::Vector::Zero(4), upper_on_lower, 0.1), Error);
  EXPECT_THROW(build_contact_constraints(mesh, la::Vector(), {.slave = "upper_zmin", .master = "x"}, mortar_options()),
               Error);
}

} // namespace feticon::contact
