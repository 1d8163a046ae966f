// What available_memory_bytes reads: the system's available memory, capped by ulimit -v.

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mjray/core/available_memory.h"
#include "mjray/core/large_page_heap.h"

namespace mjray {
namespace {

/// MemTotal of /proc/meminfo, in bytes.
uint64_t memory_total() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  uint64_t kilobytes = 0;
  while (in >> key >> kilobytes) {
    if (key == "MemTotal:") return kilobytes * 1024;
    in.ignore(1 << 12, '\n');
  }
  return 0;
}

TEST(AvailableMemory, IsSomeOfTheMachinesMemory) {
  const uint64_t available = available_memory_bytes();
  EXPECT_GT(available, 0u);
  EXPECT_LE(available, memory_total());
}

TEST(AvailableMemory, TheMachinesFigureLeavesOutOnlyTheAddressSpaceLimit) {
  const uint64_t machine = machine_available_bytes();
  EXPECT_GT(machine, 0u);
  EXPECT_LE(machine, memory_total());
  // Without ulimit -v the two read the same files; each read may differ a little.
  rlimit limit{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &limit), 0);
  if (limit.rlim_cur == RLIM_INFINITY) {
    EXPECT_NEAR(double(available_memory_bytes()), double(machine), 0.05 * double(machine));
  }
}

TEST(AvailableMemory, ResidentBytesCountWhatTheProcessTouches) {
  const uint64_t before = resident_bytes();
  EXPECT_GT(before, 0u);
  std::vector<char> touched(size_t(64) << 20);
  for (size_t i = 0; i < touched.size(); i += 4096) touched[i] = char(i);
  EXPECT_GE(resident_bytes(), before + (uint64_t(60) << 20));
  EXPECT_EQ(touched[4096], char(4096));
}

TEST(AvailableMemory, IsCappedByTheRoomLeftUnderUlimitV) {
  if (kSanitizerAllocator) GTEST_SKIP() << "AddressSanitizer cannot run under an address-space limit";
  // In a child, so that the limit does not outlive the test: 64 MiB above what it maps now.
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::ifstream status("/proc/self/status");
    std::string key;
    uint64_t mapped_kb = 0;
    while (status >> key)
      if (key == "VmSize:" && status >> mapped_kb) break;
    constexpr uint64_t kRoom = uint64_t(64) << 20;
    const rlimit limit{mapped_kb * 1024 + kRoom, mapped_kb * 1024 + kRoom};
    if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(2);
    const uint64_t available = available_memory_bytes();
    _exit(available > 0 && available <= kRoom ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "available memory above the room left under the limit";
}

}  // namespace
}  // namespace mjray
