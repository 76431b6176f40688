/// The available memory (common/available_memory.hpp) read from prepared /proc and cgroup
/// files: cgroup v2 and v1 limits, "no limit" in both spellings, a tighter ancestor, a
/// container that sees its own cgroup as the root, and MemAvailable when it is the smaller.
/// The expected values are worked by hand from the files' contents with the kernel's meaning
/// of them (Documentation/admin-guide/cgroup-v2.rst: memory.max "max" is no limit;
/// cgroup-v1/memory.rst: memory.limit_in_bytes, usage_in_bytes, total_inactive_file).

#include "common/available_memory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace feticon;
namespace fs = std::filesystem;

namespace
{
/// A fresh folder with a fake /proc and cgroup tree; removed at the end of the test.
class FakeSystem
{
public:
  explicit FakeSystem(const std::string& name = "system")
  {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    _root = fs::temp_directory_path() / ("feticon_available_memory_" + std::string(test->name()) + "_" + name);
    fs::remove_all(_root);
    fs::create_directories(_root / "cgroup");
  }
  ~FakeSystem() { fs::remove_all(_root); }

  /// Writes `text` to `relative` (folders made as needed).
  void write(const std::string& relative, const std::string& text) const
  {
    const fs::path path = _root / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }
  MemorySources sources() const
  {
    return {(_root / "meminfo").string(), (_root / "self_cgroup").string(), (_root / "cgroup").string()};
  }
  std::string path(const std::string& relative) const { return (_root / relative).string(); }

private:
  fs::path _root;
};

constexpr int64_t MB = 1000 * 1000;
const std::string meminfo_2GB = "MemTotal:       4000000 kB\nMemFree:        1000000 kB\n"
                                "MemAvailable:   2000000 kB\nBuffers:          10000 kB\n";
} // namespace

TEST(AvailableMemory, CgroupV2LimitLessUsageWithoutReclaimablePageCache)
{
  FakeSystem sys;
  sys.write("meminfo", meminfo_2GB);
  sys.write("self_cgroup", "0::/user.slice/job\n");
  sys.write("cgroup/user.slice/job/memory.max", "1000000000\n");
  sys.write("cgroup/user.slice/job/memory.current", "300000000\n");
  sys.write("cgroup/user.slice/job/memory.stat", "anon 150000000\nfile 150000000\ninactive_file 100000000\n");
  sys.write("cgroup/user.slice/memory.max", "max\n");
  sys.write("cgroup/user.slice/memory.current", "900000000\n");
  // 1e9 - (3e8 - 1e8) = 8e8 < MemAvailable 2 048 000 000.
  const CgroupRoom room = cgroup_memory_room(sys.sources());
  EXPECT_EQ(room.bytes, 800 * MB);
  EXPECT_EQ(room.limit_file, sys.path("cgroup/user.slice/job/memory.max"));
  const AvailableMemory available = available_memory(sys.sources());
  EXPECT_EQ(available.bytes, 800 * MB);
  EXPECT_EQ(available.source, "the cgroup limit " + sys.path("cgroup/user.slice/job/memory.max"));
}

TEST(AvailableMemory, TighterAncestorWins)
{
  FakeSystem sys;
  sys.write("meminfo", meminfo_2GB);
  sys.write("self_cgroup", "0::/a/b\n");
  sys.write("cgroup/a/b/memory.max", "1000000000\n");
  sys.write("cgroup/a/b/memory.current", "100000000\n");
  sys.write("cgroup/a/memory.max", "500000000\n");
  sys.write("cgroup/a/memory.current", "450000000\n"); // a sibling uses most of it
  // min(1e9 - 1e8, 5e8 - 4.5e8) = 5e7 (no memory.stat: no reclaimable pages counted).
  const AvailableMemory available = available_memory(sys.sources());
  EXPECT_EQ(available.bytes, 50 * MB);
  EXPECT_EQ(available.source, "the cgroup limit " + sys.path("cgroup/a/memory.max"));
}

TEST(AvailableMemory, NoLimitInEitherVersionLeavesMemAvailable)
{
  FakeSystem sys;
  sys.write("meminfo", meminfo_2GB);
  sys.write("self_cgroup", "4:memory:/job\n0::/job\n");
  sys.write("cgroup/job/memory.max", "max\n");
  sys.write("cgroup/job/memory.current", "300000000\n");
  sys.write("cgroup/memory/job/memory.limit_in_bytes", "9223372036854771712\n"); // v1's "unlimited"
  sys.write("cgroup/memory/job/memory.usage_in_bytes", "300000000\n");
  EXPECT_EQ(cgroup_memory_room(sys.sources()).bytes, -1);
  const AvailableMemory available = available_memory(sys.sources());
  EXPECT_EQ(available.bytes, 2000000 * int64_t{1024});
  EXPECT_EQ(available.source, "MemAvailable");
}

TEST(AvailableMemory, CgroupV1InAContainerThatSeesItsCgroupAsTheRoot)
{
  FakeSystem sys;
  sys.write("meminfo", meminfo_2GB);
  // /proc/self/cgroup names the host's path; the container mounts its own cgroup at the root.
  sys.write("self_cgroup", "12:cpu,cpuacct:/docker/abc\n4:blkio,memory:/docker/abc\n1:name=systemd:/docker/abc\n");
  sys.write("cgroup/memory/memory.limit_in_bytes", "268435456\n");
  sys.write("cgroup/memory/memory.usage_in_bytes", "120000000\n");
  sys.write("cgroup/memory/memory.stat", "cache 30000000\ninactive_file 25000000\ntotal_inactive_file 20000000\n");
  // 268 435 456 - (1.2e8 - 2e7) = 168 435 456 (the hierarchical total_inactive_file, not inactive_file).
  const AvailableMemory available = available_memory(sys.sources());
  EXPECT_EQ(available.bytes, 168435456);
  EXPECT_EQ(available.source, "the cgroup limit " + sys.path("cgroup/memory/memory.limit_in_bytes"));
}

TEST(AvailableMemory, MemAvailableWhenSmallerThanTheCgroupsRoom)
{
  FakeSystem sys;
  sys.write("meminfo", "MemAvailable:     100000 kB\n");
  sys.write("self_cgroup", "0::/job\n");
  sys.write("cgroup/job/memory.max", "8000000000\n");
  sys.write("cgroup/job/memory.current", "0\n");
  const AvailableMemory available = available_memory(sys.sources());
  EXPECT_EQ(available.bytes, 100000 * int64_t{1024});
  EXPECT_EQ(available.source, "MemAvailable");
}

TEST(AvailableMemory, UsageAboveTheLimitLeavesNothingAndNoFilesLeaveUnknown)
{
  FakeSystem sys;
  sys.write("meminfo", meminfo_2GB);
  sys.write("self_cgroup", "0::/job\n");
  sys.write("cgroup/job/memory.max", "100000000\n");
  sys.write("cgroup/job/memory.current", "150000000\n");
  EXPECT_EQ(available_memory(sys.sources()).bytes, 0); // refused, not "unknown"

  FakeSystem none("empty");
  const AvailableMemory unknown = available_memory(none.sources());
  EXPECT_EQ(unknown.bytes, -1);
}
