/// Tests of the mesh cache. References: the mesh that was stored (a hit must return it bit for
/// bit), the published FNV-1a 64-bit test vectors (Fowler, Noll, Vo: "" -> cbf29ce484222325,
/// "a" -> af63dc4c8601ec8c), and the number of times the builder runs.

#include "mesh/mesh_cache.hpp"

#include "mesh/box.hpp"
#include "mesh/rectangle.hpp"

#include "common/error.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include <unistd.h>

namespace feticon::mesh
{
namespace
{
namespace fs = std::filesystem;

Mesh test_mesh()
{
  BoxParameters p;
  p.origin = Eigen::Vector3d(-0.5, 2.0, 0.25);
  p.lengths = Eigen::Vector3d(1.5, 0.7, 2.2);
  p.nx = 3;
  p.ny = 4;
  p.nz = 2;
  Mesh mesh = generate_box(p);
  mesh.nodes(5, 1) += 1e-13; // a value text would round
  return mesh;
}

void expect_identical(const Mesh& a, const Mesh& b)
{
  ASSERT_EQ(a.nodes.rows(), b.nodes.rows());
  EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), sizeof(double) * a.nodes.size()));
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.cell_body, b.cell_body);
  EXPECT_EQ(a.body_names, b.body_names);
  EXPECT_EQ(a.node_sets, b.node_sets);
  EXPECT_EQ(a.face_sets, b.face_sets);
  EXPECT_EQ(a.planar.kind, b.planar.kind);
  EXPECT_EQ(a.planar.thickness, b.planar.thickness);
}

class MeshCache : public ::testing::Test
{
protected:
  void SetUp() override
  {
    folder = fs::temp_directory_path() / ("feticon_mesh_cache_test_" + std::to_string(getpid()));
    fs::remove_all(folder);
    location.enabled = true;
    location.folder = folder;
  }
  void TearDown() override { fs::remove_all(folder); }

  /// The one entry file of the folder.
  fs::path entry() const
  {
    std::vector<fs::path> files;
    for (const auto& item : fs::directory_iterator(folder))
      files.push_back(item.path());
    EXPECT_EQ(files.size(), 1u);
    return files.empty() ? fs::path() : files.front();
  }

  Mesh get(const std::string& key, bool& hit)
  {
    return cached_mesh(
        location, key,
        [this] {
      ++builds;
      return test_mesh();
        },
        &hit);
  }

  fs::path folder;
  MeshCacheLocation location;
  int builds = 0;
};

TEST_F(MeshCache, SecondCallReadsTheStoredMeshBitForBit)
{
  bool hit = true;
  expect_identical(get("box", hit), test_mesh());
  EXPECT_FALSE(hit);
  const Mesh again = get("box", hit);
  EXPECT_TRUE(hit);
  EXPECT_EQ(builds, 1);
  expect_identical(again, test_mesh());
}

// A 2D mesh (quad8 cells, line3 edges) keeps its formulation and thickness through the cache.
TEST_F(MeshCache, PlanarMeshKeepsItsFormulation)
{
  const Mesh planar = generate_rectangle(
      {.nx = 3, .ny = 2, .kind = CellKind::quad8, .planar = {PlanarKind::plane_stress, 0.25}, .body_name = "plate"});
  bool hit = true;
  const auto build = [&] { return planar; };
  cached_mesh(location, "plate", build, &hit);
  EXPECT_FALSE(hit);
  const Mesh again = cached_mesh(location, "plate", build, &hit);
  EXPECT_TRUE(hit);
  expect_identical(again, planar);
}

TEST_F(MeshCache, OtherKeyIsAMiss)
{
  bool hit = true;
  get("box", hit);
  get("box, refinement 2", hit);
  EXPECT_FALSE(hit);
  EXPECT_EQ(builds, 2);
}

TEST_F(MeshCache, DamagedEntriesAreRebuiltAndReplaced)
{
  bool hit = false;
  get("box", hit);
  const fs::path path = entry();
  const auto size = fs::file_size(path);
  // One flipped byte in the coordinates, then a truncated file: both misses, then a hit again.
  {
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(size / 2));
    file.put('\x5a');
  }
  expect_identical(get("box", hit), test_mesh());
  EXPECT_FALSE(hit);
  fs::resize_file(path, size - 9);
  expect_identical(get("box", hit), test_mesh());
  EXPECT_FALSE(hit);
  EXPECT_EQ(builds, 3);
  get("box", hit);
  EXPECT_TRUE(hit);
}

TEST_F(MeshCache, FailedBuildStoresNothing)
{
  bool hit = true;
  EXPECT_THROW(cached_mesh(
                   location, "bad", []() -> Mesh { throw Error("no mesh"); }, &hit),
               Error);
  EXPECT_FALSE(fs::exists(folder) && !fs::is_empty(folder));
}

TEST_F(MeshCache, OffOrUnwritableCostsOnlyTheRebuild)
{
  bool hit = true;
  location.enabled = false;
  get("box", hit);
  get("box", hit);
  EXPECT_FALSE(hit);
  EXPECT_EQ(builds, 2);
  EXPECT_FALSE(fs::exists(folder));
  // A regular file where the folder should be: nothing stored, the mesh still returned.
  location.enabled = true;
  std::ofstream(folder) << "not a folder";
  expect_identical(get("box", hit), test_mesh());
  expect_identical(get("box", hit), test_mesh());
  EXPECT_FALSE(hit);
}

TEST_F(MeshCache, PrunesTheLeastRecentlyUsedBeyondTheLimit)
{
  bool hit = false;
  get("first", hit);
  const auto one_entry = fs::file_size(entry());
  location.limit_bytes = 2 * one_entry + one_entry / 2; // room for two
  get("second", hit);
  get("first", hit); // used again: "second" is now the oldest
  EXPECT_TRUE(hit);
  get("third", hit);
  int entries = 0;
  for ([[maybe_unused]] const auto& item : fs::directory_iterator(folder))
    ++entries;
  EXPECT_EQ(entries, 2);
  get("first", hit);
  EXPECT_TRUE(hit);
  get("second", hit);
  EXPECT_FALSE(hit);
}

TEST(FileDigest, PublishedFnv1aVectors)
{
  const fs::path path = fs::temp_directory_path() / ("feticon_digest_" + std::to_string(getpid()));
  std::ofstream(path) << "";
  EXPECT_EQ(file_digest(path), "cbf29ce484222325");
  std::ofstream(path) << "a";
  EXPECT_EQ(file_digest(path), "af63dc4c8601ec8c");
  fs::remove(path);
  EXPECT_THROW(file_digest(path), Error);
}
} // namespace
} // namespace feticon::mesh
