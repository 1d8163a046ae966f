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

}  // namespace

uint64_t available_memory_bytes() {
  uint64_t available = proc_kilobytes("/proc/meminfo", "MemAvailable:");
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const uint64_t mapped = proc_kilobytes("/proc/self/status", "VmSize:");
    const uint64_t room = limit.rlim_cur > mapped ? limit.rlim_cur - mapped : 1;
    available = available == 0 ? room : std::min(available, room);
  }
  return available;
}

}  // namespace mjray
