#pragma once
/// @file The memory a process may still take: the smaller of the node's MemAvailable and the
/// room under the memory limit of its control group (a container, a batch job, a systemd
/// scope), which the kernel enforces by killing the process, however much the node has free.

#include <cstdint>
#include <string>

namespace feticon
{
/// The files the available memory is read from; other paths let a test read prepared files.
struct MemorySources
{
  std::string meminfo = "/proc/meminfo";         ///< its MemAvailable line
  std::string own_cgroups = "/proc/self/cgroup"; ///< "id:controllers:path" per hierarchy
  /// Where the cgroup file systems are mounted: v2 (unified) at the root, v1's memory
  /// controller at root/memory.
  std::string cgroup_root = "/sys/fs/cgroup";
};

/// The room under a memory limit and the file that sets the limit.
struct CgroupRoom
{
  int64_t bytes = -1; ///< -1: no limit (none set, or no cgroup file readable)
  std::string limit_file;
};

/// The room under the tightest memory limit on the process's cgroup and its ancestors (a limit
/// on an ancestor holds for its descendants): limit - (usage - inactive file pages), the page
/// cache the kernel reclaims before it kills counted as room, as MemAvailable counts it.
/// cgroup v2: memory.max ("max": no limit), memory.current, inactive_file of memory.stat;
/// v1: memory.limit_in_bytes (2^63 rounded down to a page: no limit), memory.usage_in_bytes,
/// total_inactive_file. An ancestor whose folder is not mounted (a container that sees its
/// own cgroup as the root) is skipped.
CgroupRoom cgroup_memory_room(const MemorySources& sources = {});

/// The memory available to this process and which figure it is.
struct AvailableMemory
{
  int64_t bytes = -1; ///< -1: unknown (no MemAvailable and no cgroup limit); 0: nothing left
  std::string source; ///< "MemAvailable" or "the cgroup limit <file>"
};

/// min(MemAvailable of the meminfo file, cgroup_memory_room).
AvailableMemory available_memory(const MemorySources& sources = {});

/// available_memory().bytes.
int64_t available_memory_bytes();

/// Resident memory of this process now, in bytes (VmRSS of /proc/self/status; 0 if unknown).
int64_t resident_memory_bytes();
} // namespace feticon
