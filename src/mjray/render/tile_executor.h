#pragma once
/// The seam between what an image needs rendered next (ImageRender's passes) and who renders
/// it: the threads of this process (TileRender) or the ranks of a distributed job.

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stop_token>

#include "mjray/render/image_sampler.h"

namespace mjray {

/// Pixels of one finished piece of a pass over chosen pixels: row-major pixel indices and what
/// the pass computed for each (PixelPass says whether it replaces their estimates or adds to
/// them).
struct PixelChunk {
  std::span<const int> pixels;
  std::span<const FilmPixel> values;
};

/// Renders given tiles and pixels of one image, anywhere, with results that depend only on
/// the tiles and pixels (never on where or in which order they were rendered).
class TileExecutor {
 public:
  virtual ~TileExecutor() = default;

  /// Worker threads rendering, over every process taking part.
  virtual int threads() const = 0;
  /// The first pass of every tile in `tiles`, written into `film`; `on_tile(tile)` runs once
  /// a tile's pixels are in the film (on any thread). Tiles not started once `stop` is
  /// requested are skipped. Returns whether every tile was done.
  virtual bool render_tiles(std::span<const int> tiles, Film& film, std::stop_token stop,
                            const std::function<void(int tile)>& on_tile) = 0;
  /// Computes `pass` for `pixels` (row-major indices); `on_chunk` receives each finished piece
  /// (on any thread), whose `pixels` is a subspan of `pixels`. Returns whether all were done.
  virtual bool render_pixels(std::span<const int> pixels, const PixelPass& pass, std::stop_token stop,
                             const std::function<void(const PixelChunk&)>& on_chunk) = 0;
  /// Rays cast so far, by kind (call when no render_* is running).
  virtual RayCounters rays() const = 0;
  /// Rays of every kind cast so far, as published after each tile or chunk (any thread).
  virtual uint64_t rays_published() const = 0;
};

/// Makes the executor of one image from its sampler and tiles (both outlive the executor).
using TileExecutorFactory = std::function<std::unique_ptr<TileExecutor>(const ImageSampler&, const TileLayout&)>;

}  // namespace mjray
