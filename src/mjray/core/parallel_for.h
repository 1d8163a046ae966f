#pragma once
/// Runs a loop body over [0, count) on a fixed number of threads, handing out indices from a
/// shared counter so that uneven items balance themselves. Results must not depend on which
/// thread runs an index (each index writes only its own outputs).

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace mjray {

/// Calls body(index, thread) for every index in [0, count), on `threads` threads (the caller's
/// thread is thread 0).
template <class Body>
void parallel_for(int count, int threads, Body&& body) {
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
