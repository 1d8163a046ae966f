#pragma once
/// The unit of work handed to a rank within one image: a first-pass tile, or a piece of an
/// anti-aliasing pass (whose pixels need the whole film to choose, so rank 0 chooses them).

#include <cstdint>
#include <optional>
#include <stop_token>
#include <vector>

#include "mjray/render/image_sampler.h"
#include "mjray/render/tile_layout.h"

namespace mjray {

/// One tile or one piece of a pass.
struct WorkUnit {
  enum class Kind : uint8_t { kTile, kPixels };
  Kind kind = Kind::kTile;
  int32_t id = 0;               ///< the tile, or the piece's offset in its pass's pixel list
  std::vector<int32_t> pixels;  ///< kPixels: row-major pixel indices
  PixelPass pass;               ///< kPixels: what to compute for each
};

/// The film pixels of a rendered unit: a tile's rectangle row by row (rendered through
/// `scratch`, a film of the image's size whose rectangle must be empty), or what the unit's
/// pass computes for each of its pixels in order. Nothing once `stop` is requested (it is
/// looked at between pixels, and between a tile's rows), so that a stopped rank ends at once.
std::optional<std::vector<FilmPixel>> render_unit(const ImageSampler& sampler, const TileLayout& layout,
                                                  const WorkUnit& unit, Film& scratch, TraceState& state,
                                                  std::stop_token stop);

/// Copies a rendered tile's pixels (as render_unit returns them) into its rectangle of `film`.
void store_tile(const TileLayout& layout, int tile, const std::vector<FilmPixel>& values, Film& film);

}  // namespace mjray
