#pragma once
/// One image rendered on this machine: the first pass over all tiles, then the adaptive
/// anti-aliasing passes, with stop and resume between units of work. Every pixel is
/// independent of thread and order, so a stopped render resumes to the same image.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <vector>

#include "mjray/camera/camera.h"
#include "mjray/core/image.h"
#include "mjray/integrator/integrator.h"
#include "mjray/render/film.h"
#include "mjray/render/image_sampler.h"
#include "mjray/render/render_checkpoint.h"
#include "mjray/render/tile_executor.h"
#include "mjray/render/tile_layout.h"

namespace mjray {

/// How to sample and how to schedule the work.
struct RenderSettings : SamplingSettings {
  int threads = 0;     ///< 0 = all cores
  int tile_size = 16;  ///< pixels per tile side
  /// --crop: the window of the image to render and return; the whole image when unset.
  std::optional<PixelRect> crop;
};

/// The pixels a render traces: without a crop the whole image; with one, the window grown by
/// the reach of anti-aliasing's decisions (2 pixels per pass: a pixel's plan looks at its
/// neighbours' neighbours), within the image, so that the window comes out exactly as in the
/// whole image's render.
PixelRect rendered_region(int width, int height, const RenderSettings& settings);

/// The passes after the first that a render may run: -a's anti-aliasing passes, or the noise
/// target's, each doubling the samples of the pixels it refines, up to --max-spp.
int pixel_pass_count(const SamplingSettings& settings);

/// What the render did.
struct RenderStats {
  RayCounters rays;
  double seconds = 0;
  int threads = 1;
  uint64_t pixels_supersampled = 0;
  int antialias_passes = 0;
  bool subdivided = false;  ///< --aa-method subdivide: every pixel anti-aliased in the first pass
  /// --noise-threshold: the passes after the first added samples to noisy pixels (then
  /// pixels_supersampled counts each pixel once per pass that refined it).
  bool refined_to_noise = false;
};

/// Work done so far, in camera samples (--spp per pixel in the first pass); `total` grows as anti-aliasing passes find work.
struct RenderProgress {
  uint64_t done = 0;
  uint64_t total = 0;
  uint64_t rays = 0;       ///< rays of every kind cast so far in this run (updated per tile)
  int antialias_pass = 0;  ///< 0 during the first pass
  /// With --noise-threshold, the pixels the pass under way refines (0 in the first pass and
  /// while a pass is planned): the others are clean or at --max-spp.
  uint64_t pixels_refining = 0;
};

/// run() may be stopped from another thread (request_stop); the checkpoint then holds what is
/// done, and a new ImageRender resumed from it finishes the same image. progress(),
/// snapshot() and checkpoint() may be called from other threads while run() works.
class ImageRender {
 public:
  /// The camera and integrator must outlive the render. The tiles and pixels run on this
  /// process's settings.threads threads unless `executor` makes another TileExecutor.
  ImageRender(const Camera& camera, int width, int height, const Integrator& integrator,
              const RenderSettings& settings, const TileExecutorFactory& executor = {});

  /// Continues from a checkpoint of the same scene and settings (call before run). Throws
  /// SceneError when its size or tiles do not match.
  void resume_from(const RenderCheckpoint& checkpoint);
  /// Renders until finished (true) or stopped (false).
  bool run();
  /// Asks run() to stop after the tiles and pixel chunks in flight; safe from any thread.
  void request_stop() { stop_.request_stop(); }
  /// For tests: stop once this many first-pass tiles have been finished in this run.
  void stop_after_tiles(int tiles) { stop_after_tiles_ = tiles; }
  /// For tests: stop once this many chunks of the passes after the first are done in this run.
  void stop_after_pixel_chunks(int chunks) { stop_after_chunks_ = chunks; }

  RenderProgress progress() const;
  /// The finished part of the image, or of its crop window (unfinished tiles are black).
  Image snapshot() const;
  /// Per tile of layout(), whether its first pass is finished (any thread). A tile finished in
  /// this answer is finished in a snapshot() taken after it.
  std::vector<uint8_t> finished_tiles() const;
  const TileLayout& layout() const { return layout_; }
  /// The state to resume from after run() returned false.
  RenderCheckpoint checkpoint() const;
  /// The image, or its crop window (after run() returned true).
  Image image() const;
  /// The film of rendered_region() (the window's margin included).
  const Film& film() const { return film_; }
  /// What the film covers, in image pixels.
  const PixelRect& region() const { return region_; }
  RenderStats stats() const;

 private:
  bool run_first_pass();
  /// The passes over chosen pixels: -a's anti-aliasing, or the noise target's refinement.
  bool run_pixel_passes();
  /// Chooses the pixels of the next anti-aliasing pass; false when there are none.
  bool plan_pass();

  /// The crop window of `image` (region coordinates), or the image itself without a crop
  /// (moved, not copied: a copy of a large image is mostly page faults).
  Image windowed(Image image) const;

  PixelRect region_;   // rendered_region()
  PixelRect window_;   // what image() returns, in region coordinates
  ImageSampler sampler_;
  RenderSettings settings_;
  TileLayout layout_;
  std::unique_ptr<TileExecutor> workers_;
  Film film_;
  std::unique_ptr<std::atomic<uint8_t>[]> tile_done_;
  std::vector<uint8_t> supersampled_;
  std::vector<int32_t> pass_pixels_;       // the current anti-aliasing pass's plan
  std::vector<uint8_t> pass_done_;
  std::atomic<int> antialias_pass_{0};     // 0: first pass not finished
  std::stop_source stop_;
  std::atomic<int> tiles_finished_{0};
  int stop_after_tiles_ = -1;
  int chunks_finished_ = 0;  // of the passes after the first, in this run
  int stop_after_chunks_ = -1;
  std::atomic<uint64_t> done_{0}, total_{0}, pixels_refining_{0};
  uint64_t pixels_supersampled_ = 0;
  int antialias_passes_run_ = 0;
  double seconds_ = 0;
  mutable std::mutex film_mutex_;          // anti-aliasing writes vs snapshot and checkpoint
};

/// Renders a whole image (or its crop window) in one go (no interruption).
Image render_image(const Camera& camera, int width, int height, const Integrator& integrator,
                   const RenderSettings& settings, RenderStats* stats = nullptr);

}  // namespace mjray
