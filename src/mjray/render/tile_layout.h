#pragma once
/// How an image is cut into square tiles, numbered row-major from the top-left.

#include <algorithm>

namespace mjray {

/// A rectangle of pixels [x0, x1) × [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  int pixel_count() const { return (x1 - x0) * (y1 - y0); }
};

/// Tiles of `tile_size`² pixels (smaller at the right and bottom edges).
struct TileLayout {
  int width = 0;
  int height = 0;
  int tile_size = 16;

  int tiles_x() const { return (width + tile_size - 1) / tile_size; }
  int tiles_y() const { return (height + tile_size - 1) / tile_size; }
  int count() const { return tiles_x() * tiles_y(); }
  PixelRect rect(int tile) const {
    const int x0 = (tile % tiles_x()) * tile_size, y0 = (tile / tiles_x()) * tile_size;
    return {x0, y0, std::min(width, x0 + tile_size), std::min(height, y0 + tile_size)};
  }
};

}  // namespace mjray
