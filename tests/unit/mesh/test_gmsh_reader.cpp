/// Tests of read_gmsh. The meshes are made here with the Gmsh API (OpenCASCADE boxes, transfinite
/// and recombined into hexahedra, or single hand-placed hexahedra) and written to .msh 4.1.
/// References: Gmsh's own node and element counts of the model it wrote, the box geometry
/// (volumes, planes and outward normals of the sides), the cell faces that belong to one cell only
/// (found independently in hex_geometry.hpp), and Gmsh's reference coordinates of the hex8 nodes
/// (getElementProperties) against VTK's order (hex_mesh.hpp).

#include "mesh/gmsh_reader.hpp"

#include "common/error.hpp"

#include "hex_geometry.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace feticon::mesh
{
namespace
{
namespace fs = std::filesystem;

/// A fresh folder per test (tests may run in parallel processes), removed at the end.
class TempFolder
{
public:
  TempFolder()
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    _path =
        fs::temp_directory_path() / ("feticon_gmsh_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(_path);
    fs::create_directories(_path);
  }
  ~TempFolder() { fs::remove_all(_path); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  fs::path operator/(const std::string& name) const { return _path / name; }

private:
  fs::path _path;
};

/// A Gmsh API session building one model; closed before read_gmsh opens its own.
class GmshModel
{
public:
  GmshModel()
  {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::model::add("test");
  }
  ~GmshModel() { gmsh::finalize(); }
  GmshModel(const GmshModel&) = delete;
  GmshModel& operator=(const GmshModel&) = delete;
};

struct BoxSpec
{
  Eigen::Vector3d origin;
  Eigen::Vector3d lengths;
  std::array<int, 3> cells;
};

/// OpenCASCADE enlarges bounding boxes by its tolerance (about 1e-7 m); the boxes here are
/// 0.1 m and larger.
constexpr double geometry_tolerance = 1e-5;

/// Extent of the bounding box of an entity along `axis` (min, max).
std::pair<double, double> extent(int dim, int tag, int axis)
{
  std::array<double, 6> box{};
  gmsh::model::getBoundingBox(dim, tag, box[0], box[1], box[2], box[3], box[4], box[5]);
  return {box[axis], box[axis + 3]};
}

std::vector<int> boundary_tags(const gmsh::vectorpair& dim_tags)
{
  gmsh::vectorpair boundary;
  gmsh::model::getBoundary(dim_tags, boundary, false, false, false);
  std::set<int> tags;
  for (const auto& [dim, tag] : boundary)
    tags.insert(std::abs(tag));
  return {tags.begin(), tags.end()};
}

/// OCC box with transfinite curves (box.cells along each axis); hexahedra if `hexahedra`.
int add_box(const BoxSpec& box, bool hexahedra = true)
{
  const int volume = gmsh::model::occ::addBox(box.origin.x(), box.origin.y(), box.origin.z(), box.lengths.x(),
                                              box.lengths.y(), box.lengths.z());
  gmsh::model::occ::synchronize();
  if (!hexahedra)
    return volume;
  const std::vector<int> surfaces = boundary_tags({{3, volume}});
  gmsh::vectorpair surface_dim_tags;
  for (const int s : surfaces)
    surface_dim_tags.emplace_back(2, s);
  for (const int curve : boundary_tags(surface_dim_tags))
    for (int axis = 0; axis < 3; ++axis)
      if (const auto [low, high] = extent(1, curve, axis); high - low > geometry_tolerance)
        gmsh::model::mesh::setTransfiniteCurve(curve, box.cells[axis] + 1);
  for (const int s : surfaces)
  {
    gmsh::model::mesh::setTransfiniteSurface(s);
    gmsh::model::mesh::setRecombine(2, s);
  }
  gmsh::model::mesh::setTransfiniteVolume(volume);
  return volume;
}

/// The side of a box volume on the plane coordinate[axis] = value.
int side(int volume, int axis, double value)
{
  for (const int s : boundary_tags({{3, volume}}))
    if (const auto [low, high] = extent(2, s, axis);
        std::abs(low - value) < geometry_tolerance && std::abs(high - value) < geometry_tolerance)
      return s;
  ADD_FAILURE() << "volume " << volume << " has no side on plane " << axis << " = " << value;
  return -1;
}

void add_group(int dim, const std::vector<int>& tags, const std::string& name)
{
  const int group = gmsh::model::addPhysicalGroup(dim, tags);
  gmsh::model::setPhysicalName(dim, group, name);
}

void mesh_and_write(const fs::path& path)
{
  gmsh::model::mesh::generate(3);
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::write(path.string());
}

const BoxSpec lower_box{{0, 0, 0}, {1.0, 0.8, 0.5}, {4, 3, 2}};
const BoxSpec upper_box{{0.2, 0.2, 0.5}, {0.6, 0.4, 0.3}, {3, 2, 2}};

/// What Gmsh reported about the two-box model it wrote.
struct GmshCounts
{
  std::size_t n_nodes = 0, n_hexahedra = 0;
};

/// Two boxes as separate OCC volumes touching at z = 0.5 (not fragmented, so they share no
/// nodes), with the groups of a contact problem, written to `path`.
GmshCounts write_two_boxes(const fs::path& path)
{
  GmshModel model;
  const int lower = add_box(lower_box);
  const int upper = add_box(upper_box);
  add_group(3, {lower}, "lower");
  add_group(3, {upper}, "upper");
  add_group(2, {side(lower, 2, 0.5)}, "lower_top");
  add_group(2, {side(upper, 2, 0.5)}, "upper_bottom");
  add_group(2, {side(lower, 2, 0.0)}, "support");
  add_group(2, {side(upper, 2, 0.8)}, "load");
  // The lower box's edge on y = 0, z = 0 and its corner at the origin.
  for (const int curve : boundary_tags({{2, side(lower, 1, 0.0)}}))
    if (std::abs(extent(1, curve, 2).second) < geometry_tolerance)
      add_group(1, {curve}, "front_edge");
  gmsh::vectorpair points;
  const double t = geometry_tolerance;
  gmsh::model::getEntitiesInBoundingBox(-t, -t, -t, t, t, t, points, 0);
  add_group(0, {points.at(0).second}, "origin");
  mesh_and_write(path);

  GmshCounts counts;
  std::vector<std::size_t> node_tags, element_tags, element_nodes;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
  counts.n_nodes = node_tags.size();
  // Fresh vectors: Gmsh 4.8 fills non-empty ones in place (preallocated, size-checked).
  gmsh::model::mesh::getElementsByType(5, element_tags, element_nodes);
  counts.n_hexahedra = element_tags.size();
  return counts;
}

/// One hexahedron by hand on a discrete volume: `order` lists which of the 8 corners of a
/// sheared unit cube is each node of the element.
void write_single_hex(const fs::path& path, const std::array<int, 8>& order)
{
  GmshModel model;
  const int volume = gmsh::model::addDiscreteEntity(3);
  std::vector<double> coordinates;
  for (const auto& corner : test::reference_corners)
  {
    const Eigen::Vector3d x(0.5 * (corner[0] + 1), 0.5 * (corner[1] + 1), 0.5 * (corner[2] + 1));
    const Eigen::Vector3d sheared(x[0] + 0.3 * x[2], 2 * x[1], 0.5 * x[2] + 0.1 * x[0]);
    coordinates.insert(coordinates.end(), sheared.data(), sheared.data() + 3);
  }
  gmsh::model::mesh::addNodes(3, volume, {1, 2, 3, 4, 5, 6, 7, 8}, coordinates);
  std::vector<std::size_t> nodes;
  for (const int corner : order)
    nodes.push_back(corner + 1);
  gmsh::model::mesh::addElementsByType(volume, 5, {1}, nodes);
  add_group(3, {volume}, "block");
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::write(path.string());
}

/// The message of the feticon::Error that reading `path` throws (a test failure if none).
std::string read_error(const fs::path& path)
{
  try
  {
    read_gmsh(path);
  }
  catch (const Error& error)
  {
    return error.what();
  }
  ADD_FAILURE() << "read_gmsh(" << path << ") did not throw feticon::Error";
  return {};
}

#define EXPECT_MESSAGE(message, path, text)                                                                            \
  do                                                                                                                   \
  {                                                                                                                    \
    const std::string feticon_message_ = (message);                                                                    \
    EXPECT_NE(feticon_message_.find((path).string()), std::string::npos) << feticon_message_;                          \
    EXPECT_NE(feticon_message_.find(text), std::string::npos) << feticon_message_;                                     \
    EXPECT_EQ(feticon_message_.find('\n'), std::string::npos) << feticon_message_;                                     \
  } while (false)

struct FaceSetCase
{
  const char* name;
  int body;
  int axis;
  double plane;
  double outward;
  int n_faces;
};
} // namespace

TEST(GmshReader, HexahedronNodeOrderIsVtkOrder)
{
  GmshModel model;
  std::string name;
  int dim = 0, order = 0, n_nodes = 0, n_primary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(5, name, dim, order, n_nodes, local, n_primary);
  ASSERT_EQ(n_nodes, 8);
  ASSERT_EQ(local.size(), 24u);
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(local[3 * a + d], test::reference_corners[a][d]) << "node " << a;
}

TEST(GmshReader, SingleHexKeepsNodeOrderAndRejectsInvertedCell)
{
  TempFolder folder;
  const fs::path path = folder / "single.msh";
  write_single_hex(path, {0, 1, 2, 3, 4, 5, 6, 7});
  const Mesh mesh = read_gmsh(path);
  ASSERT_EQ(mesh.n_cells(), 1);
  ASSERT_EQ(mesh.n_nodes(), 8);
  // Gmsh tags 1..8 are renumbered 0..7 in tag order, so the cell is the identity.
  EXPECT_TRUE(std::ranges::equal(mesh.cells[0], Hex8Nodes{0, 1, 2, 3, 4, 5, 6, 7}));
  // The sheared cube's volume: det of the linear map [[1,0,0.3],[0,2,0],[0.1,0,0.5]] = 0.94.
  EXPECT_NEAR(test::cell_volume(mesh, mesh.cells[0]), 0.94, 1e-14);

  // Mirrored: corners 1 <-> 3 and 5 <-> 7 swapped turn the cell inside out.
  const fs::path inverted = folder / "inverted.msh";
  write_single_hex(inverted, {0, 3, 2, 1, 4, 7, 6, 5});
  EXPECT_MESSAGE(read_error(inverted), inverted, "inverted");
}

TEST(GmshReader, TwoBoxesCountsAndVolumes)
{
  TempFolder folder;
  const fs::path path = folder / "two_boxes.msh";
  const GmshCounts gmsh_counts = write_two_boxes(path);
  const Mesh mesh = read_gmsh(path);

  EXPECT_EQ(static_cast<std::size_t>(mesh.n_nodes()), gmsh_counts.n_nodes);
  EXPECT_EQ(static_cast<std::size_t>(mesh.n_cells()), gmsh_counts.n_hexahedra);
  // Structured boxes: (nx + 1)(ny + 1)(nz + 1) nodes and nx ny nz cells each.
  EXPECT_EQ(mesh.n_nodes(), 5 * 4 * 3 + 4 * 3 * 3);
  EXPECT_EQ(mesh.n_cells(), 4 * 3 * 2 + 3 * 2 * 2);
  EXPECT_EQ(mesh.body_names, (std::vector<std::string>{"lower", "upper"}));
  ASSERT_EQ(mesh.cell_body.size(), mesh.cells.size());

  std::array<double, 2> volume{0, 0};
  std::array<std::set<int32_t>, 2> body_nodes;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
  {
    const double cell_volume = test::cell_volume(mesh, mesh.cells[c]);
    EXPECT_GT(cell_volume, 0);
    volume.at(mesh.cell_body[c]) += cell_volume;
    body_nodes.at(mesh.cell_body[c]).insert(mesh.cells[c].begin(), mesh.cells[c].end());
  }
  // Rounding only: the cells tile the boxes exactly.
  EXPECT_NEAR(volume[0], lower_box.lengths.prod(), 1e-13);
  EXPECT_NEAR(volume[1], upper_box.lengths.prod(), 1e-13);

  // Separate volumes: the bodies share no nodes although they touch at z = 0.5, and the nodes
  // are numbered body by body.
  EXPECT_EQ(body_nodes[0].size() + body_nodes[1].size(), static_cast<std::size_t>(mesh.n_nodes()));
  EXPECT_EQ(*body_nodes[0].rbegin() + 1, *body_nodes[1].begin());
}

TEST(GmshReader, TwoBoxesFaceSetsOnTheirPlanesOutward)
{
  TempFolder folder;
  const fs::path path = folder / "two_boxes.msh";
  write_two_boxes(path);
  const Mesh mesh = read_gmsh(path);

  const auto faces_cells = test::faces_to_cells(mesh);
  const std::array<FaceSetCase, 4> cases = {{{"lower_top", 0, 2, 0.5, 1, 4 * 3},
                                             {"upper_bottom", 1, 2, 0.5, -1, 3 * 2},
                                             {"support", 0, 2, 0.0, -1, 4 * 3},
                                             {"load", 1, 2, 0.8, 1, 3 * 2}}};
  for (const FaceSetCase& expected : cases)
  {
    SCOPED_TRACE(expected.name);
    const std::vector<Face>& faces = mesh.face_set(expected.name);
    EXPECT_EQ(static_cast<int>(faces.size()), expected.n_faces);
    Eigen::Vector3d outward = Eigen::Vector3d::Zero();
    outward[expected.axis] = expected.outward;
    for (const Face& face : faces)
    {
      for (const int32_t id : face)
        EXPECT_NEAR(mesh.nodes(id, expected.axis), expected.plane, 1e-14);
      EXPECT_LT((test::face_normal(mesh, face) - outward).norm(), 1e-12);
      // A boundary face of exactly one cell, of the expected body.
      const auto it = faces_cells.find(test::sorted(face));
      ASSERT_NE(it, faces_cells.end());
      ASSERT_EQ(it->second.size(), 1u);
      EXPECT_EQ(mesh.cell_body[it->second[0]], expected.body);
    }
    EXPECT_EQ(mesh.node_set(expected.name), mesh.face_set_nodes(expected.name));
  }

  // 1D and 0D groups: the 5 nodes of the edge y = z = 0 of the lower box, and its corner.
  const std::vector<int32_t>& edge = mesh.node_set("front_edge");
  EXPECT_EQ(edge.size(), 5u);
  for (const int32_t id : edge)
    EXPECT_LT(mesh.nodes.row(id).tail<2>().norm(), 1e-14);
  ASSERT_EQ(mesh.node_set("origin").size(), 1u);
  EXPECT_LT(test::point(mesh, mesh.node_set("origin")[0]).norm(), 1e-14);
}

TEST(GmshReader, MissingFile)
{
  TempFolder folder;
  const fs::path path = folder / "missing.msh";
  EXPECT_MESSAGE(read_error(path), path, "no such file");
}

TEST(GmshReader, TruncatedFile)
{
  TempFolder folder;
  const fs::path full = folder / "full.msh";
  write_two_boxes(full);
  std::ifstream in(full, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const fs::path half = folder / "half.msh";
  std::ofstream(half, std::ios::binary) << text.substr(0, text.size() / 2);
  // The pre-check reads the sections' bodies and names where the file ends.
  EXPECT_MESSAGE(read_error(half), half, "ends inside $Nodes");
}

/// How a box is meshed for one cell type: unstructured tetrahedra, transfinite hexahedra, or
/// prisms extruded from a triangulated rectangle; then raised to second order if asked.
struct CellTypeCase
{
  CellKind kind;
  FaceKind side_faces; ///< the faces on the box's side z = 0
  int order;
  bool hexahedra;
  bool prisms;
};

/// A 1 x 0.8 x 0.5 box of the case's cells with the physical surface "bottom" (z = 0), written
/// to `path`; returns Gmsh's element count of the volume.
std::size_t write_box_of(const CellTypeCase& c, const fs::path& path)
{
  GmshModel model;
  int volume = 0;
  if (c.prisms)
  {
    const int rectangle = gmsh::model::occ::addRectangle(0, 0, 0, lower_box.lengths.x(), lower_box.lengths.y());
    gmsh::vectorpair out;
    gmsh::model::occ::extrude({{2, rectangle}}, 0, 0, lower_box.lengths.z(), out, {2}, {}, true);
    gmsh::model::occ::synchronize();
    for (const auto& [dim, tag] : out)
      if (dim == 3)
        volume = tag;
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
  }
  else
  {
    volume = add_box(lower_box, c.hexahedra);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
  }
  add_group(3, {volume}, "block");
  add_group(2, {side(volume, 2, 0.0)}, "bottom");
  gmsh::option::setNumber("Mesh.ElementOrder", c.order);
  gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1);
  mesh_and_write(path);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 3, volume);
  return types.size() == 1 ? tags[0].size() : 0;
}

class GmshCellTypes : public ::testing::TestWithParam<CellTypeCase>
{
};

// Reference: Gmsh's element count, the box geometry (the bottom's area 0.8 m^2 and normal -z),
// and the orientation of every cell (centre Jacobian > 0).
TEST_P(GmshCellTypes, ReadsTheCellsAndOrientsTheirFacesOutward)
{
  const CellTypeCase c = GetParam();
  TempFolder folder;
  const fs::path path = folder / (std::string(cell_type(c.kind).name) + ".msh");
  const std::size_t n_elements = write_box_of(c, path);
  ASSERT_GT(n_elements, 0u) << "Gmsh made more than one element type";
  const Mesh mesh = read_gmsh(path);
  ASSERT_EQ(static_cast<std::size_t>(mesh.n_cells()), n_elements);
  EXPECT_TRUE(mesh.cells.all_of_kind(c.kind));
  for (int32_t cell = 0; cell < mesh.n_cells(); ++cell)
    EXPECT_GT(centre_jacobian_determinant(mesh, cell), 0) << "cell " << cell;
  double area = 0;
  for (const Face& face : mesh.face_set("bottom"))
  {
    ASSERT_EQ(face.kind, c.side_faces);
    const Eigen::Vector3d x0 = mesh.nodes.row(face[0]).transpose();
    const Eigen::Vector3d to_second = mesh.nodes.row(face[1]).transpose() - x0;
    const Eigen::Vector3d to_last = mesh.nodes.row(face[face.n_corners() - 1]).transpose() - x0;
    const Eigen::Vector3d normal = to_second.cross(to_last);
    EXPECT_LT(normal.z(), 0) << "a bottom face points into the box";
    for (int a = 0; a < face.size(); ++a)
      EXPECT_NEAR(mesh.nodes(face[a], 2), 0.0, 1e-12);
    // The corners' polygon: a triangle, or a quad split along its diagonal.
    area += 0.5 * std::abs(normal.z());
    if (face.n_corners() == 4)
    {
      const Eigen::Vector3d to_third = mesh.nodes.row(face[2]).transpose() - x0;
      area += 0.5 * std::abs(to_third.cross(to_last).z()) - 0.5 * std::abs(normal.z()) +
          0.5 * std::abs(to_second.cross(to_third).z());
    }
  }
  EXPECT_NEAR(area, lower_box.lengths.x() * lower_box.lengths.y(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(EveryType, GmshCellTypes,
                         ::testing::Values(CellTypeCase{CellKind::tet4, FaceKind::tri3, 1, false, false},
                                           CellTypeCase{CellKind::tet10, FaceKind::tri6, 2, false, false},
                                           CellTypeCase{CellKind::hex8, FaceKind::quad4, 1, true, false},
                                           CellTypeCase{CellKind::hex20, FaceKind::quad8, 2, true, false},
                                           CellTypeCase{CellKind::wedge6, FaceKind::tri3, 1, false, true}),
                         [](const ::testing::TestParamInfo<CellTypeCase>& info) {
  return std::string(cell_type(info.param.kind).name);
});

TEST(GmshReader, RejectsTwentySevenNodeHexahedra)
{
  TempFolder folder;
  const fs::path path = folder / "hex27.msh";
  {
    GmshModel model;
    add_group(3, {add_box(lower_box)}, "block");
    gmsh::option::setNumber("Mesh.ElementOrder", 2);
    mesh_and_write(path);
  }
  EXPECT_MESSAGE(read_error(path), path, "Hexahedron 27");
}

TEST(GmshReader, RejectsFileWithoutPhysicalVolume)
{
  TempFolder folder;
  const fs::path path = folder / "no_volume_group.msh";
  {
    GmshModel model;
    const int volume = add_box(lower_box);
    add_group(2, {side(volume, 2, 0.5)}, "top");
    mesh_and_write(path);
  }
  EXPECT_MESSAGE(read_error(path), path, "no 3D physical group");
}

TEST(GmshReader, RejectsDuplicateAndMissingNames)
{
  TempFolder folder;
  const fs::path duplicate = folder / "duplicate.msh";
  {
    GmshModel model;
    const int volume = add_box(lower_box);
    add_group(3, {volume}, "block");
    add_group(2, {side(volume, 2, 0.5)}, "block");
    mesh_and_write(duplicate);
  }
  EXPECT_MESSAGE(read_error(duplicate), duplicate, "used twice");

  const fs::path unnamed = folder / "unnamed.msh";
  {
    GmshModel model;
    const int volume = add_box(lower_box);
    add_group(3, {volume}, "block");
    gmsh::model::addPhysicalGroup(2, {side(volume, 2, 0.5)});
    mesh_and_write(unnamed);
  }
  EXPECT_MESSAGE(read_error(unnamed), unnamed, "has no name");
}

TEST(GmshReader, KeepsTheNodesBodiesShareOnce)
{
  // Fragmenting makes the touching boxes conformal: one shared surface mesh, whose nodes both
  // bodies' cells use (the sections of one connected mesh; the problem file decides whether
  // that is allowed, io/problem_file.cpp).
  TempFolder folder;
  const fs::path path = folder / "fragmented.msh";
  {
    GmshModel model;
    const int lower = gmsh::model::occ::addBox(0, 0, 0, 1, 1, 0.5);
    const int upper = gmsh::model::occ::addBox(0, 0, 0.5, 1, 1, 0.5);
    gmsh::vectorpair result;
    std::vector<gmsh::vectorpair> result_map;
    gmsh::model::occ::fragment({{3, lower}}, {{3, upper}}, result, result_map);
    gmsh::model::occ::synchronize();
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, 1);
    for (const auto& [dim, curve] : entities)
      gmsh::model::mesh::setTransfiniteCurve(curve, 3);
    gmsh::model::getEntities(entities, 2);
    for (const auto& [dim, surface] : entities)
    {
      gmsh::model::mesh::setTransfiniteSurface(surface);
      gmsh::model::mesh::setRecombine(2, surface);
    }
    gmsh::model::getEntities(entities, 3);
    for (const auto& [dim, volume] : entities)
      gmsh::model::mesh::setTransfiniteVolume(volume);
    add_group(3, {result_map.at(0).at(0).second}, "lower");
    add_group(3, {result_map.at(1).at(0).second}, "upper");
    mesh_and_write(path);
  }
  const Mesh mesh = read_gmsh(path);
  // Two boxes of 3 x 3 x 3 nodes (3 nodes on every curve) sharing the 3 x 3 of z = 0.5.
  EXPECT_EQ(mesh.n_nodes(), 45);
  const std::vector<SharedBodies> shared = bodies_sharing_nodes(mesh);
  ASSERT_EQ(shared.size(), 1u);
  EXPECT_EQ(shared[0].first_body, 0);
  EXPECT_EQ(shared[0].second_body, 1);
  EXPECT_NEAR(mesh.nodes(shared[0].node, 2), 0.5, 1e-12);
  std::set<int32_t> lower, upper;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    (mesh.cell_body[c] == 0 ? lower : upper).insert(mesh.cells[c].begin(), mesh.cells[c].end());
  std::vector<int32_t> both;
  std::set_intersection(lower.begin(), lower.end(), upper.begin(), upper.end(), std::back_inserter(both));
  EXPECT_EQ(both.size(), 9u);
  for (const int32_t n : both)
    EXPECT_NEAR(mesh.nodes(n, 2), 0.5, 1e-12);
}

TEST(GmshReader, RejectsQuadranglesOffTheHexahedra)
{
  // A quadrangle-meshed rectangle beside the box: its faces bound no hexahedron.
  TempFolder folder;
  const fs::path path = folder / "loose_surface.msh";
  {
    GmshModel model;
    add_group(3, {add_box(lower_box)}, "block");
    const int loose = gmsh::model::occ::addRectangle(2, 0, 0, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::model::mesh::setRecombine(2, loose);
    add_group(2, {loose}, "loose");
    mesh_and_write(path);
  }
  EXPECT_MESSAGE(read_error(path), path, "'loose' is not a face of any cell");
}

TEST(GmshReader, RejectsVolumeOutsidePhysicalGroups)
{
  TempFolder folder;
  const fs::path path = folder / "save_all.msh";
  {
    GmshModel model;
    add_group(3, {add_box(lower_box)}, "block");
    add_box(upper_box);
    gmsh::option::setNumber("Mesh.SaveAll", 1);
    mesh_and_write(path);
  }
  EXPECT_MESSAGE(read_error(path), path, "in no physical volume");
}
} // namespace feticon::mesh
