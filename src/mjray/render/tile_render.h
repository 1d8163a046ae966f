#pragma once
/// Renders given sets of tiles (the first pass) and of pixels (adaptive anti-aliasing) on a
/// fixed number of threads, stopping early when asked. Which tiles and pixels, and what
/// happens to them afterwards, is the caller's business (a local render, an MPI rank).

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stop_token>
#include <vector>

#include "mjray/core/parallel_for.h"
#include "mjray/render/image_sampler.h"
#include "mjray/render/tile_executor.h"

namespace mjray {

/// Runs an ImageSampler over tiles and pixel lists on `threads` threads of this process.
class TileRender final : public TileExecutor {
 public:
  TileRender(const ImageSampler& sampler, const TileLayout& layout, int threads);

  const TileLayout& layout() const { return layout_; }
  int threads() const override { return thread_count_; }

  /// The first pass of every tile in `tiles`, written into `film` (which must match the
  /// layout). `on_tile(tile)` runs on the worker after each finished tile; tiles not started
  /// once `stop` is requested are skipped. Returns whether every tile was done.
  bool render_tiles(std::span<const int> tiles, Film& film, std::stop_token stop,
                    const std::function<void(int tile)>& on_tile = {}) override;

  /// Computes `pass` for `pixels` (row-major indices) in chunks of kChunk; `on_chunk` receives
  /// each finished chunk on the worker (the caller stores it). Returns whether all were done.
  bool render_pixels(std::span<const int> pixels, const PixelPass& pass, std::stop_token stop,
                     const std::function<void(const PixelChunk&)>& on_chunk) override;
  static constexpr int kChunk = 64;

  /// Rays cast so far, by kind, summed over threads (call when no render_* is running).
  RayCounters rays() const override;
  /// Rays of every kind cast so far, as published after each tile or chunk (any thread).
  uint64_t rays_published() const override;

 private:
  void publish(int thread);

  const ImageSampler& sampler_;
  TileLayout layout_;
  int thread_count_;
  std::vector<TraceState> states_;                           // one per thread
  std::unique_ptr<std::atomic<uint64_t>[]> published_rays_;  // per thread, for live rays/s
};

}  // namespace mjray
