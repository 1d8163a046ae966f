#pragma once
/// The render threads of one rank: they take the units handed to the rank, in order, and
/// leave each result for the rank's MPI thread to deliver.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <stop_token>
#include <thread>
#include <vector>

#include "messages.h"
#include "work_unit.h"
#include "mjray/render/image_sampler.h"

namespace mjray {

/// A fixed set of threads rendering WorkUnits of one image; thread-safe.
class UnitPool {
 public:
  /// The sampler must outlive the pool.
  UnitPool(const ImageSampler& sampler, const TileLayout& layout, int threads);
  /// Abandons the units in progress (at their next pixel) and drops the queued ones.
  ~UnitPool();
  UnitPool(const UnitPool&) = delete;
  UnitPool& operator=(const UnitPool&) = delete;

  int threads() const { return int(threads_.size()); }
  /// Queues units of render call `phase`.
  void add(uint32_t phase, std::vector<WorkUnit> units);
  /// Drops the units not started yet; returns how many.
  size_t drop_queued();
  /// Waits at most `seconds` for a result, then returns every result finished so far.
  std::vector<ResultMessage> take_results(double seconds);

  /// What the threads have done so far (tiles, pixels, rays, thread-seconds rendering).
  RankStatistics done() const;

 private:
  void work(int thread);

  const ImageSampler& sampler_;
  TileLayout layout_;
  Film scratch_;                  // tiles are rendered through it (disjoint rectangles)
  std::vector<TraceState> states_;
  mutable std::mutex mutex_;
  std::condition_variable work_ready_, result_ready_;
  std::deque<std::pair<uint32_t, WorkUnit>> queue_;
  std::vector<ResultMessage> results_;
  RankStatistics done_;
  bool stopping_ = false;
  std::stop_source abandon_;
  std::vector<std::thread> threads_;
};

}  // namespace mjray
