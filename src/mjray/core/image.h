#pragma once
/// A rectangular grid of linear colours, row 0 at the top.

#include <cstddef>
#include <vector>

#include "mjray/core/color.h"

namespace mjray {

/// Pixels in row-major order, (0,0) the top-left corner.
class Image {
 public:
  Image() = default;
  Image(int width, int height) : width_(width), height_(height), pixels_(size_t(width) * size_t(height)) {}

  int width() const { return width_; }
  int height() const { return height_; }
  Color& at(int x, int y) { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
  const Color& at(int x, int y) const { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
  const std::vector<Color>& pixels() const { return pixels_; }
  /// Raw row-major storage, for bulk reads and writes.
  Color* data() { return pixels_.data(); }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Color> pixels_;
};

}  // namespace mjray
