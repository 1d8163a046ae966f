#pragma once
/// Storage for the large arrays of an acceleration structure (nodes, leaves, and the build's
/// own arrays): mapped straight from the system, on 2 MiB pages where it allows them. One large
/// page stands for 512 small ones, so filling an array faults 512 times less often and rays
/// that read it at random miss the TLB far less; and since the memory is unmapped when freed,
/// the build's temporary arrays do not linger in the heap after it. Small arrays, and systems
/// without this, get ordinary memory.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace mjray {

/// Arrays of at least this many bytes are mapped, in whole multiples of it, aligned to it.
constexpr size_t kLargePageBytes = size_t(2) << 20;

/// Whether an array of `bytes` is mapped on large pages.
constexpr bool is_large(size_t bytes) {
#if defined(__linux__)
  return bytes >= kLargePageBytes;
#else
  return false;
#endif
}

#if defined(__linux__)
/// `bytes` (is_large) of storage aligned to a large page, or throws std::bad_alloc.
inline void* map_large(size_t bytes) {
  const size_t size = (bytes + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
  // Map one page more than needed, then unmap the ends so that what is left is aligned.
  void* mapped = mmap(nullptr, size + kLargePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t start = uintptr_t(mapped);
  const uintptr_t aligned = (start + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
  if (aligned > start) munmap(mapped, aligned - start);
  if (const size_t tail = start + kLargePageBytes - aligned; tail > 0) munmap(reinterpret_cast<void*>(aligned + size), tail);
#if defined(MADV_HUGEPAGE)
  madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);  // a hint: if refused, small pages serve
#endif
  return reinterpret_cast<void*>(aligned);
}

/// Frees what map_large(bytes) returned.
inline void unmap_large(void* p, size_t bytes) {
  munmap(p, (bytes + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes);
}
#endif

/// A std::allocator that maps large arrays on large pages and leaves the rest (with their
/// alignment) to std::allocator.
template <class T>
struct LargePageAllocator {
  using value_type = T;
  LargePageAllocator() = default;
  template <class U>
  LargePageAllocator(const LargePageAllocator<U>&) {}
  T* allocate(size_t n) {
#if defined(__linux__)
    static_assert(alignof(T) <= kLargePageBytes);
    if (is_large(n * sizeof(T))) return static_cast<T*>(map_large(n * sizeof(T)));
#endif
    return std::allocator<T>{}.allocate(n);
  }
  void deallocate(T* p, size_t n) {
#if defined(__linux__)
    if (is_large(n * sizeof(T))) return unmap_large(p, n * sizeof(T));
#endif
    std::allocator<T>{}.deallocate(p, n);
  }
  template <class U>
  bool operator==(const LargePageAllocator<U>&) const { return true; }
};

}  // namespace mjray
