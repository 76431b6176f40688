/// The rows of a tie (contact/tie_rows.hpp). Reference: the geometry itself: an upper block of
/// 2 x 2 cells a side over a lower one whose top is flat at z = 1. Where the meshes match, the
/// dual mortar weight of a slave node is 1 on the master node below it (biorthogonality);
/// any weights sum to 1 (a rigid translation satisfies the rows).

#include "contact/tie_rows.hpp"

#include "common/error.hpp"
#include "mesh/box.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace feticon::contact
{
namespace tie_rows_test
{
/// Lower unit cube of 2 x 2 x 2 cells; upper cube of n x n x 2 over it at z = 1 + gap, its
/// bottom nodes at x = 0 raised by `bump`.
fem::Problem blocks(int n, double gap, double bump)
{
  fem::Problem p;
  p.mesh = mesh::generate_box({.nx = 2, .ny = 2, .nz = 2, .body_name = "lower"});
  mesh::append_mesh(p.mesh,
                    mesh::generate_box({.origin = {0, 0, 1 + gap}, .nx = n, .ny = n, .nz = 2, .body_name = "upper"}),
                    "upper_");
  for (int32_t node : p.mesh.node_set("upper_zmin"))
    if (p.mesh.nodes(node, 0) == 0)
      p.mesh.nodes(node, 2) += bump;
  p.materials.assign(2, fem::Material{2e11, 0.3});
  p.ties.push_back({"T", "upper_zmin", "zmax"});
  return p;
}
} // namespace tie_rows_test

TEST(TieRows, MatchingMeshesTieEachSlaveNodeToTheNodeBelow)
{
  fem::Problem p = tie_rows_test::blocks(2, 0, 0);
  const std::vector<TieReport> reports = tie_surfaces(p);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].slave_nodes, 9);
  EXPECT_EQ(reports[0].tied_nodes, 9);
  EXPECT_EQ(reports[0].rows, 27);
  EXPECT_EQ(reports[0].moved_nodes, 0);
  EXPECT_DOUBLE_EQ(reports[0].tolerance, default_tie_tolerance * 0.5); // mean master edge 0.5
  ASSERT_EQ(p.tie_equations.size(), 27u);
  for (const fem::LinearEquation& row : p.tie_equations)
  {
    const auto& slave = row.terms.front();
    EXPECT_EQ(slave.coefficient, 1.0);
    double largest = 0;
    int32_t below = -1;
    for (size_t k = 1; k < row.terms.size(); ++k)
    {
      EXPECT_EQ(row.terms[k].component, slave.component);
      if (-row.terms[k].coefficient > largest)
      {
        largest = -row.terms[k].coefficient;
        below = row.terms[k].node;
      }
    }
    EXPECT_NEAR(largest, 1.0, 1e-12);
    EXPECT_LT((p.mesh.nodes.row(below) - p.mesh.nodes.row(slave.node)).norm(), 1e-14);
  }
}

TEST(TieRows, AdjustMovesTiedNodesAndTheToleranceLeavesFarOnes)
{
  // Gap 1e-3 everywhere, 2e-2 at x = 0 (4 nodes); tolerance 5e-3 ties the 12 near ones only.
  fem::Problem p = tie_rows_test::blocks(3, 1e-3, 1.9e-2);
  p.ties[0].position_tolerance = 5e-3;
  const TieReport report = tie_surfaces(p).front();
  EXPECT_EQ(report.slave_nodes, 16);
  EXPECT_EQ(report.tied_nodes, 12);
  EXPECT_EQ(report.moved_nodes, 12);
  for (int32_t node : p.mesh.node_set("upper_zmin"))
    EXPECT_DOUBLE_EQ(p.mesh.nodes(node, 2), p.mesh.nodes(node, 0) == 0 ? 1.02 : 1.0);
  for (const fem::LinearEquation& row : p.tie_equations)
  {
    double sum = 0;
    for (size_t k = 1; k < row.terms.size(); ++k)
      sum -= row.terms[k].coefficient;
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }

  fem::Problem kept = tie_rows_test::blocks(3, 1e-3, 0);
  kept.ties[0].adjust = false;
  kept.ties[0].position_tolerance = 5e-3;
  EXPECT_EQ(tie_surfaces(kept).front().moved_nodes, 0);
  for (int32_t node : kept.mesh.node_set("upper_zmin"))
    EXPECT_DOUBLE_EQ(kept.mesh.nodes(node, 2), 1.001);
}

TEST(TieRows, SupportsAndEquationsKeepTheirDofs)
{
  fem::Problem p = tie_rows_test::blocks(2, 0, 0);
  p.steps.front().dirichlet.push_back({"upper_xmin", {0.0, std::nullopt, std::nullopt}}); // 3 slave nodes
  p.equations.push_back({{{p.mesh.node_set("upper_zmin").back(), 2, 1.0}}});
  const TieReport report = tie_surfaces(p).front();
  EXPECT_EQ(report.skipped_dofs, 4);
  EXPECT_EQ(report.rows, 23);
}

TEST(TieRows, NoSlaveNodeWithinTheToleranceIsAnError)
{
  fem::Problem p = tie_rows_test::blocks(2, 0.1, 0);
  try
  {
    tie_surfaces(p);
    FAIL() << "expected an error";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("tie T: no node of slave surface 'upper_zmin' lies within the position "
                                         "tolerance"),
              std::string::npos)
        << e.what();
  }
}
} // namespace feticon::contact
