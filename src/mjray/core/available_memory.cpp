#include "mjray/core/available_memory.h"

#include <algorithm>
#include <fstream>
#include <string>

#include <sys/resource.h>

namespace mjray {

namespace {

/// A "Name:   123 kB" line of a /proc file, in bytes; 0 when absent.
uint64_t proc_kilobytes(const char* file, const std::string& name) {
  std::ifstream in(file);
  std::string key;
  uint64_t kilobytes = 0;
  while (in >> key) {
    if (key == name && in >> kilobytes) return kilobytes * 1024;
    in.ignore(1 << 12, '\n');
  }
  return 0;
}

/// The room left under ulimit -v; 0 when there is no limit.
uint64_t address_space_room() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 0;
  const uint64_t mapped = proc_kilobytes("/proc/self/status", "VmSize:");
  return limit.rlim_cur > mapped ? limit.rlim_cur - mapped : 1;
}

/// The room left under a cgroup's limit, read from its two files; 0 when it has none ("max",
/// or cgroup v1's largest page-aligned number).
uint64_t room_under(const std::string& limit_file, const std::string& usage_file) {
  std::ifstream limit_in(limit_file), usage_in(usage_file);
  uint64_t limit = 0, usage = 0;
  if (!(limit_in >> limit) || !(usage_in >> usage) || limit >= (uint64_t(1) << 62)) return 0;
  return limit > usage ? limit - usage : 1;
}

/// The room left under the memory limit of this process's own cgroup, which containers and
/// batch systems set (cgroup v2, else v1's memory controller); 0 when there is none.
uint64_t cgroup_room() {
  std::ifstream membership("/proc/self/cgroup");
  std::string line;
  while (std::getline(membership, line)) {
    if (line.rfind("0::", 0) == 0) {
      const std::string folder = "/sys/fs/cgroup" + line.substr(3);
      if (const uint64_t room = room_under(folder + "/memory.max", folder + "/memory.current")) return room;
    } else if (const size_t at = line.find(":memory:"); at != std::string::npos) {
      const std::string folder = "/sys/fs/cgroup/memory" + line.substr(at + 8);
      if (const uint64_t room = room_under(folder + "/memory.limit_in_bytes", folder + "/memory.usage_in_bytes"))
        return room;
    }
  }
  return 0;
}

}  // namespace

uint64_t machine_available_bytes() {
  uint64_t available = 0;
  for (const uint64_t room : {proc_kilobytes("/proc/meminfo", "MemAvailable:"), cgroup_room()})
    if (room > 0) available = available == 0 ? room : std::min(available, room);
  return available;
}

uint64_t available_memory_bytes() {
  const uint64_t machine = machine_available_bytes(), own = address_space_room();
  return machine == 0 || own == 0 ? std::max(machine, own) : std::min(machine, own);
}

uint64_t resident_bytes() { return proc_kilobytes("/proc/self/status", "VmRSS:"); }

}  // namespace mjray
