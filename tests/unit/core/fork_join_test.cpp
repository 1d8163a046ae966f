#include "mjray/core/fork_join.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace mjray {
namespace {

// Sums values[begin, end) by splitting it unevenly (as SAH splits are), forking the first
// part of every range longer than 64, and records how many ranges were being summed at once.
struct Summer {
  ForkJoinPool& pool;
  const std::vector<uint64_t>& values;
  std::atomic<int> running{0};
  std::atomic<int> most_running{0};

  uint64_t sum(size_t begin, size_t end) {
    if (end - begin <= 64) {
      const int now = ++running;
      for (int seen = most_running; now > seen && !most_running.compare_exchange_weak(seen, now);) {
      }
      const uint64_t total = std::accumulate(values.begin() + long(begin), values.begin() + long(end), uint64_t(0));
      --running;
      return total;
    }
    const size_t mid = begin + (end - begin) / 3;
    uint64_t first = 0;
    ForkJoinPool::Task task(pool, [&] { first = sum(begin, mid); });
    const uint64_t second = sum(mid, end);
    task.join();
    return first + second;
  }
};

std::vector<uint64_t> values(size_t n) {
  std::vector<uint64_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = i * i % 1000003;
  return v;
}

TEST(ForkJoinPool, ForkedSumsEqualTheSerialSumOnAnyThreadCount) {
  const std::vector<uint64_t> v = values(200000);
  const uint64_t expected = std::accumulate(v.begin(), v.end(), uint64_t(0));
  for (int threads : {1, 2, 3, 8}) {
    ForkJoinPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    Summer summer{pool, v};
    EXPECT_EQ(summer.sum(0, v.size()), expected) << threads << " threads";
  }
}

TEST(ForkJoinPool, NoMoreTasksRunAtOnceThanThePoolHasThreads) {
  const std::vector<uint64_t> v = values(100000);
  for (int threads : {1, 2, 4}) {
    ForkJoinPool pool(threads);
    Summer summer{pool, v};
    summer.sum(0, v.size());
    EXPECT_GE(summer.most_running.load(), 1);
    EXPECT_LE(summer.most_running.load(), threads) << threads << " threads";
  }
}

TEST(ForkJoinPool, JoinRethrowsWhatATaskThrewAndThePoolGoesOn) {
  ForkJoinPool pool(2);
  ForkJoinPool::Task failing(pool, [] { throw std::runtime_error("out of memory, say"); });
  EXPECT_THROW(failing.join(), std::runtime_error);
  int ran = 0;
  ForkJoinPool::Task next(pool, [&] { ran = 1; });
  next.join();
  EXPECT_EQ(ran, 1);
}

TEST(ForkJoinPool, ATaskLeftUnjoinedHasRunWhenItIsDestroyed) {
  ForkJoinPool pool(1);  // no worker thread: only the wait in the destructor can run it
  int ran = 0;
  { ForkJoinPool::Task task(pool, [&] { ran = 1; }); }
  EXPECT_EQ(ran, 1);
}

}  // namespace
}  // namespace mjray
