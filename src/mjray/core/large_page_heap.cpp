#include "mjray/core/large_page_heap.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>
#endif

#include "mjray/core/large_pages.h"

namespace mjray {

void back_heap_with_large_pages(size_t bytes) {
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  if (kSanitizerAllocator) return;
  constexpr size_t kMmapThreshold = size_t(32) << 20;  // glibc's own ceiling for the dynamic one
  constexpr int kDefaultTopPad = 128 << 10;             // glibc's default
  // Under a limit on address space (ulimit -v) take only a small part of it.
  if (rlimit limit{}; getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    bytes = std::min(bytes, size_t(limit.rlim_cur / 8));
  // The next growth of the heap adds the pad, and the heap is not trimmed back below it.
  if (bytes < kLargePageBytes || mallopt(M_TOP_PAD, int(bytes)) == 0 ||
      mallopt(M_TRIM_THRESHOLD, int(2 * bytes)) == 0 || mallopt(M_MMAP_THRESHOLD, int(kMmapThreshold)) == 0)
    return;
  const auto heap_end = [] { return reinterpret_cast<uintptr_t>(sbrk(0)); };
  const uintptr_t before = heap_end();
  // Requests larger than the free top of the heap make it grow (by the request and the pad).
  std::vector<void*> blocks;
  while (heap_end() == before && blocks.size() < 64) {
    void* block = std::malloc(size_t(1) << 20);
    if (!block) break;
    blocks.push_back(block);
  }
  const uintptr_t start = (before + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
  const uintptr_t end = heap_end() / kLargePageBytes * kLargePageBytes;
  if (end > start) madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);  // a hint
  for (void* b : blocks) std::free(b);
  // Later growth, beyond the advised part, is ordinary again.
  mallopt(M_TOP_PAD, kDefaultTopPad);
#else
  (void)bytes;
#endif
}

}  // namespace mjray
