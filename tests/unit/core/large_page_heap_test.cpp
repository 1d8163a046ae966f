#include "mjray/core/large_page_heap.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

namespace mjray {
namespace {

/// The name and advice flags of the mapping that holds `address`, from /proc/self/smaps.
struct Mapping {
  std::string name;
  std::string flags;
};

Mapping mapping_of(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<uintptr_t>(address);
  std::string line;
  bool inside = false;
  Mapping found;
  while (std::getline(smaps, line)) {
    uintptr_t start = 0, end = 0;
    char dash = 0;
    std::istringstream fields(line);
    if (fields >> std::hex >> start >> dash >> end && dash == '-') {
      if (inside) break;
      inside = at >= start && at < end;
      if (inside) {
        std::string perms, offset, device, inode;
        fields >> perms >> offset >> device >> inode;
        std::getline(fields >> std::ws, found.name);
      }
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      found.flags = line;
    }
  }
  return found;
}

bool transparent_huge_pages_available() {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(setting, text);
  return setting && text.find("[never]") == std::string::npos;
}

TEST(LargePageHeap, BlocksUnder32MiBComeFromTheHeapAdvisedForLargePages) {
  if (kSanitizerAllocator) GTEST_SKIP() << "AddressSanitizer's allocator replaces the heap";
  if (!transparent_huge_pages_available()) GTEST_SKIP() << "this system has no transparent huge pages";
  back_heap_with_large_pages(size_t(64) << 20);
  // An 8 MiB block would be mapped on its own, on small pages, by default (above 128 KiB).
  const size_t bytes = size_t(8) << 20;
  void* block = std::malloc(bytes);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, bytes);
  // Its start may lie in the heap's old top, below the advised part: ask about its middle.
  const Mapping m = mapping_of(static_cast<char*>(block) + bytes / 2);
  EXPECT_EQ(m.name, "[heap]");
  EXPECT_NE(m.flags.find(" hg"), std::string::npos) << m.flags;
  std::free(block);
}

}  // namespace
}  // namespace mjray
