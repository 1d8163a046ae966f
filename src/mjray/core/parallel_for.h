#pragma once
/// Runs a loop body over [0, count) on a fixed number of threads, handing out indices from a
/// shared counter so that uneven items balance themselves. Results must not depend on which
/// thread runs an index (each index writes only its own outputs).

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace mjray {

/// The number of worker threads `requested` means on this machine (0 = all cores).
inline int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  return int(std::max(1u, std::thread::hardware_concurrency()));
}

/// The part [begin, end) of [0, count) that chunk `chunk` of `chunks` equal chunks covers.
struct ChunkRange {
  size_t begin, end;
};
inline ChunkRange chunk_range(size_t count, int chunk, int chunks) {
  return {count * size_t(chunk) / size_t(chunks), count * size_t(chunk + 1) / size_t(chunks)};
}

/// Calls body(index, thread) for every index in [0, count), on `threads` threads (the caller's
/// thread is thread 0), or on fewer when there are fewer indices.
template <class Body>
void parallel_for(int count, int threads, Body&& body) {
  threads = std::clamp(threads, 1, std::max(1, count));
  std::atomic<int> next{0};
  auto worker = [&](int thread) {
    for (int i = next++; i < count; i = next++) body(i, thread);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& thread : pool) thread.join();
}

}  // namespace mjray
