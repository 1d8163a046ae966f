#pragma once
/// Renders an image over tiles on all cores; every pixel is independent of thread and order,
/// so a render can stop between tiles and resume to the same image.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "mjray/camera/pinhole_camera.h"
#include "mjray/core/image.h"
#include "mjray/integrator/integrator.h"
#include "mjray/render/render_checkpoint.h"

namespace mjray {

/// How to schedule the work.
struct RenderSettings {
  int threads = 0;     ///< 0 = all cores
  int tile_size = 16;  ///< pixels per tile side
  uint64_t seed = 0;   ///< --seed: keys every random number
  int antialias_samples = 0;        ///< -a: N×N jittered samples in bad pixels; 0 = off
  float antialias_threshold = 0.1f; ///< --aa-threshold: neighbour difference that makes a pixel bad
  int antialias_max_passes = 4;     ///< passes of adaptive supersampling at most
};

/// What the render did.
struct RenderStats {
  RayCounters rays;
  double seconds = 0;
  int threads = 1;
  uint64_t pixels_supersampled = 0;
  int antialias_passes = 0;
};

/// Work done so far, in camera samples; `total` grows as anti-aliasing passes find work.
struct RenderProgress {
  uint64_t done = 0;
  uint64_t total = 0;
  uint64_t rays = 0;       ///< rays of every kind cast so far in this run (updated per tile)
  int antialias_pass = 0;  ///< 0 during the first pass
};

/// One image being rendered. run() may be stopped from another thread (request_stop); the
/// checkpoint then holds what is done, and a new TileRender resumed from it finishes the same
/// image. progress() and snapshot() may be called from other threads while run() works.
class TileRender {
 public:
  TileRender(const PinholeCamera& camera, int width, int height, const Integrator& integrator,
             const RenderSettings& settings);

  /// Continues from a checkpoint of the same scene and settings (call before run).
  void resume_from(const RenderCheckpoint& checkpoint);
  /// Renders until finished (true) or stopped (false).
  bool run();
  /// Asks run() to stop after the tiles in flight; safe from any thread or a signal watcher.
  void request_stop() { stop_requested_ = true; }
  /// For tests: stop once this many first-pass tiles have been finished in this run.
  void stop_after_tiles(int tiles) { stop_after_tiles_ = tiles; }

  RenderProgress progress() const;
  /// The finished part of the image (unfinished tiles are black).
  Image snapshot() const;
  /// The state to resume from after run() returned false.
  RenderCheckpoint checkpoint() const;
  const Image& image() const { return image_; }
  RenderStats stats() const;

 private:
  bool run_first_pass();
  bool run_antialiasing();
  Color supersample(int x, int y, RayCounters& counters) const;

  const PinholeCamera& camera_;
  const Integrator& integrator_;
  RenderSettings settings_;
  int width_, height_, tiles_x_, tile_count_, thread_count_;
  Image image_;
  std::unique_ptr<std::atomic<uint8_t>[]> tile_done_;
  std::vector<uint8_t> supersampled_;
  Image pass_start_image_;                 // the image as the current AA pass found it
  std::vector<uint8_t> pass_start_supersampled_;
  std::atomic<int> antialias_pass_{0};     // 0: first pass not finished
  std::vector<RayCounters> counters_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<int> tiles_finished_{0};
  int stop_after_tiles_ = -1;
  std::atomic<uint64_t> done_{0}, total_{0};
  std::unique_ptr<std::atomic<uint64_t>[]> published_rays_;  // per thread, for live rays/s
  uint64_t pixels_supersampled_ = 0;
  int antialias_passes_run_ = 0;
  double seconds_ = 0;
  mutable std::mutex image_mutex_;         // guards whole-image writes in AA passes vs snapshot
};

/// Renders a whole image in one go (no interruption).
Image render_image(const PinholeCamera& camera, int width, int height,
                   const Integrator& integrator, const RenderSettings& settings,
                   RenderStats* stats = nullptr);

/// The number of worker threads `requested` means on this machine (0 = all cores).
int resolve_thread_count(int requested);

}  // namespace mjray
