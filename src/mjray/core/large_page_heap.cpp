#include "mjray/core/large_page_heap.h"

#include <cstdint>
#include <cstdlib>
#include <vector>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "mjray/core/large_pages.h"

namespace mjray {

void back_heap_with_large_pages(size_t bytes) {
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  constexpr size_t kMmapThreshold = size_t(32) << 20;  // glibc's own ceiling for the dynamic one
  // The heap grows by the pad whenever it grows, and is not trimmed back below it.
  if (mallopt(M_TOP_PAD, int(bytes)) == 0 || mallopt(M_TRIM_THRESHOLD, int(2 * bytes)) == 0 ||
      mallopt(M_MMAP_THRESHOLD, int(kMmapThreshold)) == 0)
    return;
  const auto heap_end = [] { return reinterpret_cast<uintptr_t>(sbrk(0)); };
  const uintptr_t before = heap_end();
  // Requests larger than the free top of the heap make it grow (by the request and the pad).
  std::vector<void*> blocks;
  while (heap_end() == before && blocks.size() < 64) blocks.push_back(std::malloc(size_t(1) << 20));
  const uintptr_t start = (before + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
  const uintptr_t end = heap_end() / kLargePageBytes * kLargePageBytes;
  if (end > start) madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);  // a hint
  for (void* b : blocks) std::free(b);
#else
  (void)bytes;
#endif
}

}  // namespace mjray
