/// Tests of the Gmsh cross-sections (2D and extruded) and of the mesh quality measures. References:
/// exact areas of the sections, the circle of an arc, outward normals from the geometry, and
/// hand-computed shape measures of box cells.

#include "mesh/box.hpp"
#include "mesh/cross_section.hpp"
#include "mesh/mesh_quality.hpp"
#include "mesh/rectangle.hpp"

#include "common/error.hpp"

#include "hex_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace feticon::mesh
{
namespace
{
/// The unit square with a quarter disc of radius 0.5 about (1, 1) cut off: sides "bottom",
/// "right" (to y = 0.5), the arc "arc", "top" (from x = 0.5) and "left".
CrossSection notched_square()
{
  CrossSection s{"plate", {0, 0}, {}};
  s.curves = {
      {{1, 0}, "bottom"}, {{1, 0.5}, "right"}, {{0.5, 1}, "arc", true, {1, 1}}, {{0, 1}, "top"}, {{0, 0}, "left"}};
  return s;
}

TEST(CrossSection, AreaSetsAndOrientation)
{
  const double thickness = 0.1;
  const Mesh mesh = extrude_cross_section(
      notched_square(), [](double, double) { return 0.05; }, thickness);
  ASSERT_GT(mesh.n_cells(), 100);
  EXPECT_EQ(mesh.n_bodies(), 1);
  // Every node belongs to a cell (Gmsh's node at the arc's centre does not).
  std::vector<char> used(mesh.n_nodes(), 0);
  for (const auto cell : mesh.cells)
    for (int32_t n : cell)
      used[n] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), mesh.n_nodes());
  double volume = 0;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
  {
    EXPECT_GT(centre_jacobian_determinant(mesh, c), 0);
    volume += test::cell_volume(mesh, mesh.cells[c]);
  }
  // The arc nodes lie on the circle; each chord of length l, inside the cut-off disc, adds a
  // circular segment of about l^3 / (12 R) to the plate.
  const double exact = (1 - M_PI / 16) * thickness;
  EXPECT_NEAR(volume, exact, 5e-4 * exact);
  EXPECT_GT(volume, exact);
  for (int32_t n : mesh.node_set("arc"))
    EXPECT_NEAR(std::hypot(mesh.nodes(n, 0) - 1, mesh.nodes(n, 1) - 1), 0.5, 1e-12);

  // Each side's faces point out of the plate; together they cover the side's length.
  const std::map<std::string, Eigen::Vector3d> normals = {{"bottom", {0, -1, 0}}, {"right", {1, 0, 0}},
                                                          {"top", {0, 1, 0}},     {"left", {-1, 0, 0}},
                                                          {"zmin", {0, 0, -1}},   {"zmax", {0, 0, 1}}};
  for (const auto& [set, normal] : normals)
  {
    double area = 0;
    for (const Face& f : mesh.face_set(set))
    {
      const Eigen::Vector3d a = mesh.nodes.row(f[1]) - mesh.nodes.row(f[0]);
      const Eigen::Vector3d b = mesh.nodes.row(f[3]) - mesh.nodes.row(f[0]);
      const Eigen::Vector3d n = a.cross(b);
      EXPECT_NEAR(n.normalized().dot(normal), 1, 1e-12) << set;
      // Area of the planar quad: half the cross product of its diagonals.
      const Eigen::Vector3d d1 = mesh.nodes.row(f[2]) - mesh.nodes.row(f[0]);
      const Eigen::Vector3d d2 = mesh.nodes.row(f[3]) - mesh.nodes.row(f[1]);
      area += 0.5 * d1.cross(d2).norm();
    }
    const double expected = set == "zmin" || set == "zmax" ? volume / thickness : 0.5 * thickness;
    EXPECT_NEAR(area, set == "bottom" || set == "left" ? 2 * expected : expected, 1e-3) << set;
  }
  for (const Face& f : mesh.face_set("arc"))
  {
    const Eigen::Vector3d centre =
        0.25 * (mesh.nodes.row(f[0]) + mesh.nodes.row(f[1]) + mesh.nodes.row(f[2]) + mesh.nodes.row(f[3]));
    const Eigen::Vector3d n =
        (mesh.nodes.row(f[1]) - mesh.nodes.row(f[0])).cross(mesh.nodes.row(f[3]) - mesh.nodes.row(f[0]));
    EXPECT_LT(n.dot(centre - Eigen::Vector3d(1, 1, centre.z())), 0); // out of the plate: towards the centre
  }
}

// The 2D mesh is the extruded layer's section: the same points and quadrilaterals, counter-
// clockwise, its edge sets the layer's side faces seen edge-on (its z = 0 nodes, outward normals).
TEST(CrossSection, QuadrilateralsOfA2DModel)
{
  const auto size = [](double, double) { return 0.05; };
  const Mesh layer = extrude_cross_section(notched_square(), size, 0.1);
  const Mesh planar = mesh_cross_section(notched_square(), size, {PlanarKind::plane_strain, 0.1});
  EXPECT_EQ(planar.planar.kind, PlanarKind::plane_strain);
  ASSERT_EQ(planar.n_cells(), layer.n_cells());
  ASSERT_EQ(2 * planar.n_nodes(), layer.n_nodes());
  EXPECT_EQ(planar.nodes, layer.nodes.topRows(planar.n_nodes()));
  double area = 0;
  for (int32_t c = 0; c < planar.n_cells(); ++c)
  {
    EXPECT_EQ(planar.cells.kind(c), CellKind::quad4);
    const auto cell = planar.cells[c];
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(cell[k], layer.cells[c][k]);
    EXPECT_GT(centre_jacobian_determinant(planar, c), 0);
    for (int k = 0; k < 4; ++k) // shoelace
      area += 0.5 *
          (planar.nodes(cell[k], 0) * planar.nodes(cell[(k + 1) % 4], 1) -
           planar.nodes(cell[(k + 1) % 4], 0) * planar.nodes(cell[k], 1));
  }
  EXPECT_NEAR(area, (1 - M_PI / 16), 5e-4);
  EXPECT_EQ(planar.face_sets.count("zmin"), 0u);
  const std::map<std::string, Eigen::Vector3d> normals = {
      {"bottom", {0, -1, 0}}, {"right", {1, 0, 0}}, {"top", {0, 1, 0}}, {"left", {-1, 0, 0}}};
  for (const auto& [set, normal] : normals)
  {
    ASSERT_EQ(planar.face_set(set).size(), layer.face_set(set).size()) << set;
    std::vector<int32_t> first_layer = layer.node_set(set);
    std::erase_if(first_layer, [&](int32_t n) { return n >= planar.n_nodes(); });
    EXPECT_EQ(planar.node_set(set), first_layer) << set;
    for (const Face& f : planar.face_set(set))
    {
      ASSERT_EQ(f.kind, FaceKind::line2);
      const Eigen::Vector3d along = planar.nodes.row(f[1]) - planar.nodes.row(f[0]);
      EXPECT_NEAR(along.cross(Eigen::Vector3d::UnitZ()).normalized().dot(normal), 1, 1e-12) << set;
    }
  }
  // Its quality is the layer's seen in plane.
  const MeshQuality in_plane = mesh_quality(layer, true), own = mesh_quality(planar, false);
  EXPECT_DOUBLE_EQ(own.max_aspect_ratio, in_plane.max_aspect_ratio);
  EXPECT_DOUBLE_EQ(own.min_angle_deg, in_plane.min_angle_deg);
  EXPECT_DOUBLE_EQ(own.max_angle_deg, in_plane.max_angle_deg);
  EXPECT_GT(own.min_angle_deg, 30);
}

// A quad with a collapsed edge (decks use them as triangles) is measured as the triangle it is:
// the unit square with its corner 3 moved onto corner 0 is the right isosceles triangle 0-1-2,
// 45 and 90 degrees, edges 1, 1 and sqrt 2 (the zero edge gave an infinite aspect ratio, which
// summary.json wrote as null: fuzz seed 76, mutants 456, 8282, 12334).
TEST(MeshQuality, CollapsedQuadIsItsTriangle)
{
  Mesh mesh = generate_rectangle({.kind = CellKind::quad4, .body_name = "square"});
  const auto cell = mesh.cells[0];
  mesh.nodes.row(cell[3]) = mesh.nodes.row(cell[0]);
  const MeshQuality q = mesh_quality(mesh, false);
  EXPECT_NEAR(q.max_aspect_ratio, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(q.min_angle_deg, 45, 1e-9);
  EXPECT_NEAR(q.max_angle_deg, 90, 1e-9);
}

TEST(CrossSection, SizeFieldGradesTheCells)
{
  // Size 0.02 at the left side growing to 0.2 at the right: far more cells near x = 0.
  const Mesh mesh = extrude_cross_section(
      notched_square(), [](double x, double) { return 0.02 + 0.18 * x; }, 0.1);
  int left = 0, right = 0;
  for (const auto cell : mesh.cells)
    (mesh.nodes(cell[0], 0) < 0.5 ? left : right) += 1;
  EXPECT_GT(left, 5 * right);
}

TEST(CrossSection, SameMeshEveryTime)
{
  // Every MPI rank and every restart builds the mesh anew: it must not depend on what Gmsh did
  // before in the process (its random perturbations of the Delaunay points).
  auto size = [](double x, double) { return 0.02 + 0.1 * x; };
  const Mesh first = extrude_cross_section(notched_square(), size, 0.1);
  extrude_cross_section(
      notched_square(), [](double, double) { return 0.07; }, 0.1);
  const Mesh again = extrude_cross_section(notched_square(), size, 0.1);
  ASSERT_EQ(first.n_nodes(), again.n_nodes());
  EXPECT_EQ(first.nodes, again.nodes);
  EXPECT_EQ(first.cells, again.cells);
}

TEST(CrossSection, RefusesAnOpenLoop)
{
  CrossSection s = notched_square();
  s.curves.back().end = {0, 0.1};
  EXPECT_THROW(extrude_cross_section(
                   s, [](double, double) { return 0.1; }, 0.1),
               Error);
}

TEST(MeshQuality, BoxCells)
{
  BoxParameters p;
  p.lengths = {2, 0.5, 4};
  p.nx = 2; // cells 1 x 0.5 x 4
  const Mesh box = generate_box(p);
  const MeshQuality all = mesh_quality(box, false);
  EXPECT_NEAR(all.max_aspect_ratio, 8, 1e-12);
  EXPECT_NEAR(all.min_angle_deg, 90, 1e-9);
  EXPECT_NEAR(all.max_angle_deg, 90, 1e-9);
  EXPECT_NEAR(mesh_quality(box, true).max_aspect_ratio, 2, 1e-12); // the z = min face only

  // A sheared cell: x of the top nodes moved by 0.5 over the height 0.5 gives 45 and 135 degrees.
  Mesh sheared = box;
  for (int32_t n = 0; n < sheared.n_nodes(); ++n)
    sheared.nodes(n, 0) += sheared.nodes(n, 1);
  const MeshQuality q = mesh_quality(sheared, true);
  EXPECT_NEAR(q.min_angle_deg, 45, 1e-9);
  EXPECT_NEAR(q.max_angle_deg, 135, 1e-9);
}
} // namespace
} // namespace feticon::mesh
