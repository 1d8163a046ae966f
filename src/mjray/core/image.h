#pragma once
/// A rectangular grid of linear colours, row 0 at the top.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mjray/core/color.h"

namespace mjray {

/// The widest and tallest image mjray renders (gr.render, --size, --crop, resume states).
inline constexpr int kMaxImageSide = 65536;
/// The most pixels an image may have: 2^27 (e.g. 16384 x 8192), about 5 GiB of render buffers
/// at some 40 bytes per pixel (colours, the anti-aliasing pass copy, the snapshot being written).
inline constexpr uint64_t kMaxImagePixels = uint64_t(1) << 27;

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
