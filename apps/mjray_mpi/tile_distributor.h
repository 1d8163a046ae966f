#pragma once
/// Rank 0's TileExecutor: the tiles (or pieces of an anti-aliasing pass) of one image go
/// into one queue, and every rank, rank 0's own threads included, is kept supplied from it as
/// its results come back, so that fast ranks take more. Results land in rank 0's film.

#include <atomic>
#include <deque>
#include <functional>
#include <vector>

#include "job_statistics.h"
#include "messages.h"
#include "mpi_world.h"
#include "unit_pool.h"
#include "mjray/render/tile_executor.h"

namespace mjray {

/// Hands the units of one job to the ranks serving it (those that said Ready).
class TileDistributor final : public TileExecutor {
 public:
  /// `local_threads` render on rank 0; `report` receives rank 0's own figures when the
  /// distributor is destroyed. Every argument must outlive the distributor.
  TileDistributor(MpiWorld& world, const ImageSampler& sampler, const TileLayout& layout, int local_threads,
                  RankStatistics& report);
  ~TileDistributor() override;

  int threads() const override;
  bool render_tiles(std::span<const int> tiles, Film& film, std::stop_token stop,
                    const std::function<void(int tile)>& on_tile) override;
  bool render_pixels(std::span<const int> pixels, const PixelPass& pass, std::stop_token stop,
                     const std::function<void(const PixelChunk&)>& on_chunk) override;
  RayCounters rays() const override;
  uint64_t rays_published() const override { return published_rays_.load(std::memory_order_relaxed); }

  /// After a stop, how long units still out on other ranks are waited for (a rank that has
  /// died never answers; mpirun ends the processes about a second after it signals them).
  static constexpr double kStopGraceSeconds = 0.2;

 private:
  struct Rank {
    bool ready = false;
    int threads = 0;
    int in_hand = 0;  // units given and not yet returned
    RayCounters rays;
  };

  /// Runs `units` on every ready rank until all came back or a stop; `deliver` stores each
  /// result. Returns whether every unit was done. Throws RankFailed.
  bool run(std::deque<WorkUnit> units, std::stop_token stop, const std::function<void(const ResultMessage&)>& deliver);
  /// Gives ready ranks units up to what keeps them busy.
  void top_up();
  /// Handles one message from another rank.
  void handle(const Message& message, const std::function<void(const ResultMessage&)>& deliver);
  void take_result(int rank, const ResultMessage& result, const std::function<void(const ResultMessage&)>& deliver);

  MpiWorld& world_;
  TileLayout layout_;
  UnitPool local_;
  RankStatistics& report_;
  std::vector<Rank> ranks_;
  std::deque<WorkUnit> queue_;
  uint32_t phase_ = 0;
  int in_hand_ = 0;  // over all ranks
  std::atomic<uint64_t> published_rays_{0};
};

}  // namespace mjray
