#include "common/available_memory.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

namespace feticon
{
namespace
{
/// The first word of a file as bytes; nullopt if the file is missing, unreadable, or says
/// "max" (cgroup v2: no limit).
std::optional<int64_t> read_bytes(const std::filesystem::path& path)
{
  std::ifstream file(path);
  long long value = 0;
  if (!(file >> value))
    return std::nullopt;
  return static_cast<int64_t>(value);
}

/// The number after `key` (a whole word at the start of a line) in a file of "key value"
/// lines, times `unit`; nullopt if absent.
std::optional<int64_t> read_keyed(const std::filesystem::path& path, const std::string& key, int64_t unit)
{
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
  {
    std::istringstream words(line);
    std::string word;
    long long value = 0;
    if (words >> word && (word == key || word == key + ":") && words >> value)
      return static_cast<int64_t>(value) * unit;
  }
  return std::nullopt;
}

/// One cgroup hierarchy's memory files (v1 and v2 name them differently).
struct CgroupFiles
{
  std::filesystem::path mount;
  const char* limit;
  const char* usage;
  const char* inactive_file; ///< key in memory.stat
};

/// v1 writes "no limit" as the largest page-aligned int64; anything near it is no limit.
constexpr int64_t unlimited = int64_t{1} << 62;

/// The room under the limits of `cgroup` (a path like /a/b) and its ancestors in one hierarchy.
void tightest_room(const CgroupFiles& files, std::string cgroup, CgroupRoom& out)
{
  while (true)
  {
    const std::filesystem::path dir = cgroup == "/" ? files.mount : files.mount / cgroup.substr(1);
    const std::optional<int64_t> limit = read_bytes(dir / files.limit);
    if (limit && *limit < unlimited)
    {
      const int64_t usage = read_bytes(dir / files.usage).value_or(0);
      const int64_t reclaimable = read_keyed(dir / "memory.stat", files.inactive_file, 1).value_or(0);
      const int64_t room = std::max<int64_t>(0, *limit - std::max<int64_t>(0, usage - reclaimable));
      if (out.bytes < 0 || room < out.bytes)
        out = {room, (dir / files.limit).string()};
    }
    if (cgroup == "/" || cgroup.empty())
      return;
    const size_t slash = cgroup.find_last_of('/');
    cgroup = slash == 0 ? "/" : cgroup.substr(0, slash);
  }
}
} // namespace

CgroupRoom cgroup_memory_room(const MemorySources& sources)
{
  CgroupRoom out;
  std::ifstream list(sources.own_cgroups);
  std::string line;
  const std::filesystem::path root(sources.cgroup_root);
  // Lines "id:controllers:path": v2's is "0::path"; v1's memory hierarchy lists "memory"
  // among its controllers.
  while (std::getline(list, line))
  {
    const size_t first = line.find(':'), second = first == std::string::npos ? first : line.find(':', first + 1);
    if (second == std::string::npos)
      continue;
    const std::string id = line.substr(0, first), controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    if (path.empty() || path[0] != '/')
      continue;
    if (id == "0" && controllers.empty())
      tightest_room({root, "memory.max", "memory.current", "inactive_file"}, path, out);
    std::istringstream names(controllers);
    std::string name;
    while (std::getline(names, name, ','))
      if (name == "memory")
        tightest_room({root / "memory", "memory.limit_in_bytes", "memory.usage_in_bytes", "total_inactive_file"}, path,
                      out);
  }
  return out;
}

AvailableMemory available_memory(const MemorySources& sources)
{
  AvailableMemory out{read_keyed(sources.meminfo, "MemAvailable", 1024).value_or(-1), "MemAvailable"};
  const CgroupRoom cgroup = cgroup_memory_room(sources);
  if (cgroup.bytes >= 0 && (out.bytes < 0 || cgroup.bytes < out.bytes))
    out = {cgroup.bytes, "the cgroup limit " + cgroup.limit_file};
  return out;
}

int64_t available_memory_bytes() { return available_memory().bytes; }

int64_t resident_memory_bytes() { return read_keyed("/proc/self/status", "VmRSS", 1024).value_or(0); }
} // namespace feticon
