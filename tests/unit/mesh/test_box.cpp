/// Tests of generate_box, generate_mapped_block, append_mesh and graded_positions.
/// References: the box geometry itself (volume lx*ly*lz, planes and outward normals of its six
/// sides) and the boundary found independently as the cell faces that belong to one cell only.

#include "mesh/box.hpp"

#include "common/error.hpp"

#include "hex_geometry.hpp"

#include <gtest/gtest.h>

#include <set>

namespace feticon::mesh
{
namespace
{
BoxParameters test_box()
{
  BoxParameters p;
  p.origin = Eigen::Vector3d(-0.5, 2.0, 0.25);
  p.lengths = Eigen::Vector3d(1.5, 0.7, 2.2);
  p.nx = 3;
  p.ny = 4;
  p.nz = 5;
  return p;
}

struct Side
{
  const char* name;
  int axis;
  bool at_max;
};
constexpr std::array<Side, 6> sides = {{{"xmin", 0, false},
                                        {"xmax", 0, true},
                                        {"ymin", 1, false},
                                        {"ymax", 1, true},
                                        {"zmin", 2, false},
                                        {"zmax", 2, true}}};
} // namespace

TEST(Box, CountsAndVolume)
{
  const BoxParameters p = test_box();
  const Mesh mesh = generate_box(p);
  EXPECT_EQ(mesh.n_nodes(), 4 * 5 * 6);
  EXPECT_EQ(mesh.n_cells(), 3 * 4 * 5);
  EXPECT_EQ(mesh.n_bodies(), 1);
  EXPECT_EQ(mesh.body_names[0], "box");
  ASSERT_EQ(mesh.cell_body.size(), mesh.cells.size());
  double volume = 0;
  for (const auto cell : mesh.cells)
  {
    const double cell_volume = test::cell_volume(mesh, cell);
    EXPECT_GT(cell_volume, 0);
    volume += cell_volume;
  }
  // Rounding only: the cells tile the box exactly.
  EXPECT_NEAR(volume, p.lengths.prod(), 1e-13 * p.lengths.prod());
}

TEST(Box, SidesOnTheirPlanesWithOutwardNormals)
{
  const BoxParameters p = test_box();
  const Mesh mesh = generate_box(p);
  for (const Side& side : sides)
  {
    SCOPED_TRACE(side.name);
    const double plane = p.origin[side.axis] + (side.at_max ? p.lengths[side.axis] : 0.0);
    Eigen::Vector3d outward = Eigen::Vector3d::Zero();
    outward[side.axis] = side.at_max ? 1 : -1;
    const auto& faces = mesh.face_set(side.name);
    const int n_cells[3] = {p.nx, p.ny, p.nz};
    EXPECT_EQ(static_cast<int>(faces.size()), n_cells[(side.axis + 1) % 3] * n_cells[(side.axis + 2) % 3]);
    for (const Face& face : faces)
    {
      for (const int32_t id : face)
        EXPECT_NEAR(mesh.nodes(id, side.axis), plane, 1e-14);
      EXPECT_LT((test::face_normal(mesh, face) - outward).norm(), 1e-14);
    }
    // The node set is every node on the plane.
    std::vector<int32_t> on_plane;
    for (int32_t id = 0; id < mesh.n_nodes(); ++id)
      if (std::abs(mesh.nodes(id, side.axis) - plane) < 1e-12)
        on_plane.push_back(id);
    EXPECT_EQ(mesh.node_set(side.name), on_plane);
  }
}

TEST(Box, EveryBoundaryFaceInExactlyOneSet)
{
  const Mesh mesh = generate_box(test_box());
  std::set<test::SortedFace> boundary;
  for (const auto& [face, cells] : test::faces_to_cells(mesh))
    if (cells.size() == 1)
      boundary.insert(face);
  std::multiset<test::SortedFace> in_sets;
  for (const auto& [name, faces] : mesh.face_sets)
    for (const Face& face : faces)
      in_sets.insert(test::sorted(face));
  EXPECT_EQ(boundary.size(), 2u * (3 * 4 + 4 * 5 + 3 * 5));
  EXPECT_EQ(in_sets.size(), boundary.size());
  for (const test::SortedFace& face : boundary)
    EXPECT_EQ(in_sets.count(face), 1u);
}

TEST(Box, RejectsBadParameters)
{
  BoxParameters p;
  p.ny = 0;
  EXPECT_THROW(generate_box(p), Error);
  p = BoxParameters{};
  p.lengths = Eigen::Vector3d(1, -1, 1);
  EXPECT_THROW(generate_box(p), Error);
  p.lengths = Eigen::Vector3d(1, 0, 1);
  EXPECT_THROW(generate_box(p), Error);
}

TEST(MappedBlock, RejectsAnInvertedMap)
{
  // x decreasing with i turns every cell inside out.
  const GridMap mirrored = [](int32_t i, int32_t j, int32_t k) { return Eigen::Vector3d(-i, j, k); };
  EXPECT_THROW(generate_mapped_block({2, 2, 2}, mirrored, "mirrored"), Error);
}

TEST(AppendMesh, ShiftsIdsAndRenamesSets)
{
  BoxParameters lower;
  lower.nx = 2;
  lower.body_name = "lower";
  BoxParameters upper;
  upper.origin = Eigen::Vector3d(0, 0, 1);
  upper.ny = 3;
  upper.body_name = "upper";
  Mesh mesh = generate_box(lower);
  const Mesh second = generate_box(upper);
  const int32_t n_first = mesh.n_nodes();
  append_mesh(mesh, second, "upper_");

  EXPECT_EQ(mesh.n_nodes(), n_first + second.n_nodes());
  EXPECT_EQ(mesh.n_cells(), 2 + 3);
  EXPECT_EQ(mesh.body_names, (std::vector<std::string>{"lower", "upper"}));
  EXPECT_EQ(mesh.cell_body, (std::vector<int32_t>{0, 0, 1, 1, 1}));
  EXPECT_TRUE(mesh.face_sets.contains("zmax") && mesh.face_sets.contains("upper_zmin"));
  // The renamed sets keep their geometry: upper_zmin lies on z = 1 and points down.
  for (const Face& face : mesh.face_set("upper_zmin"))
  {
    for (const int32_t id : face)
    {
      EXPECT_GE(id, n_first);
      EXPECT_DOUBLE_EQ(mesh.nodes(id, 2), 1.0);
    }
    EXPECT_LT((test::face_normal(mesh, face) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-14);
  }
  EXPECT_EQ(mesh.node_set("upper_zmin").size(), second.node_set("zmin").size());
  for (int32_t c = 2; c < mesh.n_cells(); ++c)
    for (const int32_t id : mesh.cells[c])
      EXPECT_GE(id, n_first);

  EXPECT_THROW(append_mesh(mesh, second, "again_"), Error); // body "upper" exists
  Mesh renamed = second;
  renamed.body_names = {"third"};
  EXPECT_THROW(append_mesh(mesh, renamed, "upper_"), Error); // set "upper_xmin" exists
}

TEST(GradedPositions, FineThenGeometricEndingExactly)
{
  const double h = 0.005, fine = 0.1, q = 1.2, length = 0.6;
  const std::vector<double> t = graded_positions(length, h, fine, q);
  ASSERT_GE(t.size(), 2u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), length);
  int n_fine = 0;
  for (std::size_t i = 1; i < t.size(); ++i)
  {
    const double size = t[i] - t[i - 1];
    ASSERT_GT(size, 0);
    if (t[i - 1] < fine - 1e-12)
    {
      EXPECT_NEAR(size, h, 1e-15);
      ++n_fine;
    }
    else
    {
      // The adjusted ratio stays within 5 % of q: m is rounded from the real cell count.
      const double previous = t[i - 1] - t[i - 2];
      EXPECT_NEAR(size / previous, q, 0.05 * q);
    }
  }
  EXPECT_EQ(n_fine, 20);
  // A short rest that cannot be graded: uniform cells no larger than h.
  const std::vector<double> short_rest = graded_positions(0.1003, h, fine, q);
  for (std::size_t i = 1; i < short_rest.size(); ++i)
    EXPECT_LE(short_rest[i] - short_rest[i - 1], h + 1e-15);
  EXPECT_EQ(short_rest.back(), 0.1003);
  EXPECT_THROW(graded_positions(1, h, fine, 0.9), Error);
  EXPECT_THROW(graded_positions(1, 0, fine, q), Error);
}
} // namespace feticon::mesh
