#pragma once
/// How much memory this process may still take, for refusing work that cannot fit before it
/// fills the machine.

#include <cstdint>

namespace mjray {

/// The memory the system could give now (MemAvailable of /proc/meminfo), capped by the room
/// left under this process's address-space limit (ulimit -v) and its cgroup's memory limit;
/// 0 when unknown.
uint64_t available_memory_bytes();

/// The same without the address-space limit, which is each process's own: what processes
/// started together on this machine share. 0 when unknown.
uint64_t machine_available_bytes();

/// The memory this process holds now (VmRSS); 0 when unknown.
uint64_t resident_bytes();

}  // namespace mjray
