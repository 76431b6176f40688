/// Contact rows on the Hertz mesh (problems/hertz_mesh.hpp, ALGORITHMS.md section 9):
/// node-to-segment and mortar.
/// References: (1) the analytic gap of the undeformed cylinder over the plane y = 0: the slave
/// nodes lie on the arc y = R1 - sqrt(R1^2 - x^2) and the master surface is exactly y = 0, so
/// g = y_s; (2) a brute-force search that projects every slave node on every master face;
/// (3) for mortar rows on the flat master plane, sum_a M_ja = D_j (HertzRowsAndTiming).
/// The brute-force search projects on quad4 faces: those tests take the hex8 layer's mesh.

#include "contact/contact_constraints.hpp"
#include "contact/mortar_constraints.hpp"
#include "problems/hertz_mesh.hpp"

#include "../unit/contact/contact_row_checks.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>

namespace feticon::contact
{
namespace
{
using row_checks::expect_rows_annihilate_translations;
using row_checks::weight_sum;

const ContactPair hertz_pair{.slave = "cylinder_contact", .master = "block_contact"};

/// The Hertz mesh as one hex8 layer (quad4 contact faces), at `refinement`.
mesh::Mesh hertz_layer(double refinement = 1)
{
  problems::HertzMeshParameters parameters;
  parameters.cells = problems::HertzCells::hex8_layer;
  parameters.refinement = refinement;
  return problems::generate_hertz(parameters);
}

/// Closest accepted projection over all master faces (smallest |g|, first face on ties).
struct BruteForceRow
{
  int32_t face = -1;
  double gap = 0;
  Eigen::Vector2d xi{0, 0};
};

BruteForceRow brute_force(const mesh::Mesh& mesh, const la::Vector& u, int32_t slave)
{
  BruteForceRow best;
  const std::vector<mesh::Face>& faces = mesh.face_set(hertz_pair.master);
  Eigen::Vector3d x_s = mesh.nodes.row(slave).transpose();
  if (u.size() > 0)
    x_s += u.segment<3>(3 * slave);
  for (size_t f = 0; f < faces.size(); ++f)
  {
    const QuadProjection p = project_to_quad(current_face_coordinates(mesh, u, faces[f]), x_s);
    if (p.accepted() && (best.face < 0 || std::abs(p.gap) < std::abs(best.gap)))
      best = {static_cast<int32_t>(f), p.gap, p.xi};
  }
  return best;
}

/// Row of slave node s, or -1.
la::Index row_of(const ContactConstraints& rows, int32_t s)
{
  for (la::Index i = 0; i < rows.n_rows(); ++i)
    if (rows.slave_node[i] == s)
      return i;
  return -1;
}

/// Every slave node with an accepted projection somewhere has a row exactly when the brute-force
/// gap is below d_s, and then the same face, xi and gap (bit for bit: the same projections, the
/// minimum taken in the same order). A node without any accepted projection may only have a rim
/// row: its projection on the row's face lies just outside, within the rim extension.
/// Returns the number of rim rows.
int expect_same_as_brute_force(const mesh::Mesh& mesh, const la::Vector& u, const ContactConstraints& rows)
{
  int n_rim = 0;
  const std::vector<mesh::Face>& faces = mesh.face_set(hertz_pair.master);
  for (const int32_t s : mesh.face_set_nodes(hertz_pair.slave))
  {
    const BruteForceRow reference = brute_force(mesh, u, s);
    const la::Index row = row_of(rows, s);
    if (reference.face < 0)
    {
      if (row < 0)
        continue;
      ++n_rim;
      EXPECT_EQ(rows.kind[row], ProjectionKind::rim) << "node " << s;
      Eigen::Vector3d x_s = mesh.nodes.row(s).transpose();
      if (u.size() > 0)
        x_s += u.segment<3>(3 * s);
      const QuadProjection p = project_to_quad(current_face_coordinates(mesh, u, faces[rows.master_face[row]]), x_s);
      EXPECT_FALSE(p.inside) << "node " << s;
      EXPECT_LE(p.xi.lpNorm<Eigen::Infinity>(), 1 + ContactOptions{}.rim_extension);
      EXPECT_EQ(rows.xi[row], p.xi) << "node " << s;
      EXPECT_EQ(rows.gap[row], p.gap) << "node " << s;
      continue;
    }
    EXPECT_EQ(row >= 0, reference.gap < rows.search_distance) << "node " << s;
    if (row < 0)
      continue;
    EXPECT_EQ(rows.master_face[row], reference.face) << "node " << s;
    EXPECT_EQ(rows.xi[row], reference.xi) << "node " << s;
    EXPECT_EQ(rows.gap[row], reference.gap) << "node " << s;
    EXPECT_EQ(rows.kind[row], ProjectionKind::face);
  }
  return n_rim;
}
} // namespace

TEST(HertzContact, GapsEqualAnalyticArcAndBruteForce)
{
  const mesh::Mesh mesh = hertz_layer();
  const double radius = 1.0;
  const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), hertz_pair);
  const std::vector<int32_t> slave_nodes = mesh.face_set_nodes(hertz_pair.slave);
  ASSERT_EQ(rows.n_slave_nodes, static_cast<int32_t>(slave_nodes.size()));
  EXPECT_EQ(rows.n_overhanging, 0);
  std::cout << "Hertz (refinement 1): " << slave_nodes.size() << " slave nodes, "
            << mesh.face_set(hertz_pair.master).size() << " master faces, d_s = " << rows.search_distance << " m, "
            << rows.n_rows() << " rows\n";

  EXPECT_EQ(expect_same_as_brute_force(mesh, la::Vector(), rows), 0);
  int n_near = 0;
  for (const int32_t s : slave_nodes)
  {
    const double x = mesh.nodes(s, 0);
    const la::Index row = row_of(rows, s);
    if (x <= 0.3)
    {
      ++n_near;
      ASSERT_GE(row, 0) << "slave node at x = " << x << " has no row";
    }
    if (row < 0)
      continue;
    // The node is on the arc and the master surface is y = 0 with n = +y: g = y_s exactly.
    const double analytic = radius - std::sqrt(radius * radius - x * x);
    EXPECT_GE(rows.gap[row], 0);
    EXPECT_NEAR(rows.gap[row], analytic, 1e-12) << "x = " << x;
    EXPECT_NEAR((rows.normal[row] - Eigen::Vector3d(0, 1, 0)).norm(), 0, 1e-15);
  }
  EXPECT_GT(n_near, 50);
}

TEST(HertzContact, SearchTimeAtRefinement4)
{
  const mesh::Mesh mesh = hertz_layer(4);
  const auto start = std::chrono::steady_clock::now();
  const ContactConstraints rows = build_contact_constraints(mesh, la::Vector(), hertz_pair);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Brute force on the same mesh: the reference for the rows, and timed for comparison.
  const auto brute_start = std::chrono::steady_clock::now();
  EXPECT_EQ(expect_same_as_brute_force(mesh, la::Vector(), rows), 0);
  const double brute_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - brute_start).count();
  EXPECT_EQ(rows.n_overhanging, 0);

  std::cout << "Hertz (refinement 4): " << rows.n_slave_nodes << " slave nodes, "
            << mesh.face_set(hertz_pair.master).size() << " master faces, d_s = " << rows.search_distance << " m, "
            << rows.n_rows() << " rows; build " << seconds * 1e3 << " ms, brute-force check " << brute_seconds * 1e3
            << " ms\n";
}

TEST(HertzContact, DeformedConfigurationMatchesBruteForce)
{
  // A smooth displacement that bends the block surface (u_y = 2e-3 cos(3 x) (1 + z)) and moves
  // the cylinder down by 1e-3 and sideways, so the master faces are no longer in y = 0, slave
  // nodes near x = 0 penetrate, and no gap is exact: only the brute-force search is the
  // reference. The surface also tilts across the thickness (du_y/dz = 2e-3 cos(3x)), so the
  // projections of penetrating nodes on z = 0 land just outside the rim z = 0 of the master
  // surface: rim rows.
  const mesh::Mesh mesh = hertz_layer();
  la::Vector u = la::Vector::Zero(3 * mesh.n_nodes());
  for (int32_t node = 0; node < mesh.n_nodes(); ++node)
  {
    const Eigen::Vector3d x = mesh.nodes.row(node).transpose();
    if (x(1) <= 0)
      u(3 * node + 1) = 2e-3 * std::cos(3 * x(0)) * (1 + x(2));
    else
    {
      u(3 * node) = 1e-4 * x(1);
      u(3 * node + 1) = -1e-3;
    }
  }
  const ContactConstraints rows = build_contact_constraints(mesh, u, hertz_pair);
  const int n_rim = expect_same_as_brute_force(mesh, u, rows);
  EXPECT_GT(n_rim, 0);
  EXPECT_EQ(rows.n_overhanging, 0);
  int n_penetrating = 0;
  for (const double g : rows.gap)
    n_penetrating += g < 0;
  EXPECT_GT(n_penetrating, 0);
  for (const int32_t s : mesh.face_set_nodes(hertz_pair.slave))
  {
    if (mesh.nodes(s, 0) <= 0.3)
    {
      EXPECT_GE(row_of(rows, s), 0) << "slave node at x = " << mesh.nodes(s, 0);
    }
  }
}
TEST(HertzContact, MortarRowsAndTiming)
{
  // References: the master surface is y = 0 and the node-to-segment normal is +y, so the
  // weighted gap n . (x_j - sum_a w_ja x_a) is y_j = R1 - sqrt(R1^2 - x_j^2) whatever the
  // weights; the slave faces are flat rectangles (chords) and their projections on the master
  // plane parallelograms, so sum_a M_ja = D_j to round-off for every node with a row (the master
  // surface extends beyond the slave surface, and candidate master faces are found within d_s).
  // The rows are those of node-to-segment.
  for (const double refinement : {1.0, 4.0})
  {
    problems::HertzMeshParameters parameters;
    parameters.refinement = refinement;
    const mesh::Mesh mesh = problems::generate_hertz(parameters);
    auto time = [&](const ContactOptions& options, ContactConstraints& rows) {
      double best = 1e300;
      for (int repeat = 0; repeat < 3; ++repeat)
      {
        const auto start = std::chrono::steady_clock::now();
        rows = build_contact_constraints(mesh, la::Vector(), hertz_pair, options);
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      }
      return best;
    };
    ContactOptions mortar_options;
    mortar_options.formulation = ContactFormulation::mortar;
    ContactConstraints nts;
    ContactConstraints mortar;
    const double nts_seconds = time({}, nts);
    const double mortar_seconds = time(mortar_options, mortar);
    const MortarCoupling coupling = compute_mortar_coupling(mesh, la::Vector(), hertz_pair, mortar.search_distance);

    ASSERT_EQ(mortar.slave_node, nts.slave_node);
    EXPECT_EQ(mortar.n_overhanging, 0);
    for (la::Index i = 0; i < mortar.n_rows(); ++i)
    {
      const double x = mesh.nodes(mortar.slave_node[i], 0);
      EXPECT_NEAR(mortar.gap[i], 1.0 - std::sqrt(1.0 - x * x), 1e-12) << "x = " << x;
      EXPECT_NEAR(weight_sum(mortar, i), 1.0, 1e-14);
    }
    for (const int32_t s : mortar.slave_node)
    {
      const int32_t j = coupling.slave.index_of(s);
      EXPECT_NEAR(coupling.M.row(j).sum() / coupling.slave.area(j), 1.0, 1e-12);
    }
    expect_rows_annihilate_translations(mortar, mesh.n_nodes());
    std::cout << "Hertz (refinement " << refinement << "): " << mesh.face_set(hertz_pair.slave).size()
              << " slave faces, " << mesh.face_set(hertz_pair.master).size() << " master faces, " << coupling.n_segments
              << " segments, " << mortar.n_rows() << " rows, " << mortar.B.nonZeros() << " nonzeros (node-to-segment "
              << nts.B.nonZeros() << "); build: mortar " << mortar_seconds * 1e3 << " ms, node-to-segment "
              << nts_seconds * 1e3 << " ms\n";
  }
}
} // namespace feticon::contact
