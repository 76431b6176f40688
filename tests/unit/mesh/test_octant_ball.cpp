/// Tests of octant_ball, the graded all-hex mesh of a ball octant (hertz3d's bodies).
/// References: the geometry itself (the octant's volume pi R^3 / 6, its planes and sphere,
/// their outward normals), the boundary found independently as the cell faces that belong to
/// one cell only (hex_geometry.hpp), and the shape bounds issue 20 asks of the mesh.

#include "mesh/octant_ball.hpp"

#include "common/error.hpp"
#include "mesh/mesh_quality.hpp"

#include "hex_geometry.hpp"

#include <gtest/gtest.h>

#include <set>

namespace feticon::mesh
{
namespace
{
Mesh as_mesh(const OctantBall& ball)
{
  Mesh m;
  m.nodes = ball.nodes;
  for (const Hex8Nodes& cell : ball.cells)
    m.cells.add(CellKind::hex8, cell);
  m.cell_body.assign(ball.cells.size(), 0);
  m.body_names = {"ball"};
  return m;
}

OctantBallParameters small_ball()
{
  return {0.5, 6, 20.0, 2.0}; // core [0, 3]^3, R = 20
}
} // namespace

TEST(OctantBall, CellsArePositiveAndFillTheOctant)
{
  const OctantBallParameters p = small_ball();
  const OctantBall ball = octant_ball(p);
  const Mesh mesh = as_mesh(ball);
  EXPECT_EQ(mesh.n_cells(), 6 * 6 * 6 + ball.layers * 3 * 6 * 6);
  double volume = 0;
  for (const auto cell : mesh.cells)
  {
    for (const Eigen::Vector3d& xi : test::gauss_points())
      ASSERT_GT(test::jacobian(mesh, cell, xi).determinant(), 0);
    volume += test::cell_volume(mesh, cell);
  }
  // The outer nodes lie on the sphere and the faces between them are bilinear, so the mesh is
  // slightly inside it: the deficit is of the order of the squared angle of a cell (pi/24)^2.
  const double exact = M_PI * std::pow(p.radius, 3) / 6;
  EXPECT_LT(volume, exact);
  EXPECT_GT(volume, (1 - 0.03) * exact);
}

TEST(OctantBall, BoundaryFacesLieOnTheirSurfacesAndPointOutward)
{
  const OctantBallParameters p = small_ball();
  const OctantBall ball = octant_ball(p);
  const Mesh mesh = as_mesh(ball);
  std::set<test::SortedFace> boundary;
  for (const auto& [face, cells] : test::faces_to_cells(mesh))
    if (cells.size() == 1)
      boundary.insert(face);
  std::set<test::SortedFace> listed;
  struct Surface
  {
    const std::vector<Face>* faces;
    int axis; // 0, 1, 2: the plane x, y or d = 0; -1: the sphere
  };
  for (const Surface& s :
       {Surface{&ball.symmetry_x, 0}, Surface{&ball.symmetry_y, 1}, Surface{&ball.flat, 2}, Surface{&ball.outer, -1}})
  {
    ASSERT_FALSE(s.faces->empty());
    for (const Face& f : *s.faces)
    {
      EXPECT_TRUE(listed.insert(test::sorted(f)).second) << "face listed twice";
      const Eigen::Vector3d normal = test::face_normal(mesh, f);
      const Eigen::Vector3d centre = test::face_centroid(mesh, f);
      for (int32_t id : f)
        if (s.axis >= 0)
          EXPECT_EQ(mesh.nodes(id, s.axis), 0.0);
        else
          EXPECT_NEAR(test::point(mesh, id).norm(), p.radius, 1e-12 * p.radius);
      if (s.axis >= 0)
        EXPECT_LT(normal(s.axis), -0.999);
      else
        EXPECT_GT(normal.dot(centre.normalized()), 0.9);
    }
  }
  EXPECT_EQ(listed, boundary);
}

TEST(OctantBall, ShapeRegularAndGradedWithTheDistance)
{
  // Issue 20: aspect ratio <= 3; the face angles stay within [45, 135] degrees as well. (At
  // radial_aspect 2 the corner cells of the cubed-sphere panels reach 3.01 for n = 16.)
  for (double aspect : {1.0, 1.5})
    for (int n : {4, 8, 16})
    {
      const OctantBall ball = octant_ball({1.0, n, 40.0 * n, aspect});
      const MeshQuality q = mesh_quality(as_mesh(ball), false);
      EXPECT_LE(q.max_aspect_ratio, 3.0) << "n " << n << " aspect " << aspect;
      EXPECT_GE(q.min_angle_deg, 45.0);
      EXPECT_LE(q.max_angle_deg, 135.0 + 1e-9);
    }
  // The layers grow geometrically: the outermost cells are R / c times the core's, so the cell
  // count grows with log(R / c), not with (R / c)^3.
  const OctantBall near = octant_ball({1.0, 8, 80.0, 1.5});
  const OctantBall far = octant_ball({1.0, 8, 800.0, 1.5});
  EXPECT_LT(far.cells.size(), 2.5 * near.cells.size());
}

TEST(OctantBall, SizeCountedWithoutBuildingIsTheBuiltMesh)
{
  // octant_ball_size sizes a run for the memory guard; the reference is the mesh itself.
  for (double aspect : {1.0, 2.0})
    for (int n : {2, 5, 8})
      for (double radius : {2.5 * n, 40.0 * n})
      {
        const OctantBallParameters p{1.0, n, radius, aspect};
        const OctantBall ball = octant_ball(p);
        const OctantBallSize size = octant_ball_size(p);
        EXPECT_EQ(size.nodes, ball.nodes.rows()) << n << " " << radius << " " << aspect;
        EXPECT_EQ(size.cells, static_cast<int64_t>(ball.cells.size()));
        EXPECT_EQ(size.layers, ball.layers);
        int64_t on_plane = 0;
        for (Eigen::Index i = 0; i < ball.nodes.rows(); ++i)
          on_plane += ball.nodes(i, 0) == 0.0;
        EXPECT_EQ(size.plane_nodes, on_plane);
      }
}

TEST(OctantBall, MirroredAcrossXIsTheHalfBall)
{
  // References: the half ball's volume is twice the octant's (to round-off), its boundary is
  // the faces of one cell only (found independently), every listed face points outward, and
  // the x = 0 plane is inside.
  const OctantBallParameters p = small_ball();
  const OctantBall ball = octant_ball(p);
  const OctantBall half = mirrored_across_x(ball);
  EXPECT_EQ(half.nodes.rows(), 2 * ball.nodes.rows() - octant_ball_size(p).plane_nodes);
  EXPECT_EQ(half.cells.size(), 2 * ball.cells.size());
  EXPECT_TRUE(half.symmetry_x.empty());
  const Mesh octant = as_mesh(ball), mesh = as_mesh(half);
  double volume = 0, octant_volume = 0;
  for (const auto cell : mesh.cells)
  {
    for (const Eigen::Vector3d& xi : test::gauss_points())
      ASSERT_GT(test::jacobian(mesh, cell, xi).determinant(), 0);
    volume += test::cell_volume(mesh, cell);
  }
  for (const auto cell : octant.cells)
    octant_volume += test::cell_volume(octant, cell);
  EXPECT_NEAR(volume, 2 * octant_volume, 1e-12 * volume);

  std::set<test::SortedFace> boundary, listed;
  for (const auto& [face, cells] : test::faces_to_cells(mesh))
    if (cells.size() == 1)
      boundary.insert(face);
  for (const auto* faces : {&half.symmetry_y, &half.flat, &half.outer})
    for (const Face& f : *faces)
    {
      EXPECT_TRUE(listed.insert(test::sorted(f)).second) << "face listed twice";
      const Eigen::Vector3d centre = test::face_centroid(mesh, f);
      const Eigen::Vector3d outward = faces == &half.symmetry_y ? Eigen::Vector3d(0, -1, 0)
          : faces == &half.flat                                 ? Eigen::Vector3d(0, 0, -1)
                                                                : centre.normalized();
      EXPECT_GT(test::face_normal(mesh, f).dot(outward), 0.9);
    }
  EXPECT_EQ(listed, boundary);
}

TEST(OctantBall, RejectsBadParameters)
{
  EXPECT_THROW(octant_ball_size({1.0, 4, 9.0, 2.0}), Error);
  EXPECT_THROW(octant_ball({0.0, 4, 10.0, 2.0}), Error);
  EXPECT_THROW(octant_ball({1.0, 0, 10.0, 2.0}), Error);
  EXPECT_THROW(octant_ball({1.0, 4, 9.0, 2.0}), Error); // R < 2.5 c
  EXPECT_THROW(octant_ball({1.0, 4, 100.0, 5.0}), Error);
}
} // namespace feticon::mesh
