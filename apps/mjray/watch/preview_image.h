#pragma once
/// The images the live page shows while a frame refines.

#include <cstdint>
#include <vector>

#include "mjray/core/image.h"
#include "mjray/render/tile_layout.h"

namespace mjray {

/// `coarse` enlarged to width × height, each pixel taking the coarse pixel it falls in.
Image enlarge(const Image& coarse, int width, int height);

/// `underlay` with the tiles of `layout` that `finished` marks replaced by those of
/// `snapshot` (all three of the layout's size).
Image overlay_finished_tiles(const Image& underlay, const Image& snapshot, const std::vector<uint8_t>& finished,
                             const TileLayout& layout);

}  // namespace mjray
