#pragma once
/// Checks of whole images: isolated outlier pixels ("speckles") and their 8-bit luma.

#include <algorithm>
#include <array>
#include <cstdlib>

#include "mjray/core/image.h"
#include "mjray/io/quantise.h"

namespace mjray::test {

/// The 8-bit luma (Rec. 601 weights) of pixel (x, y), as an image viewer shows it.
inline int luma8(const Image& image, int x, int y) {
  const Color& c = image.at(x, y);
  return (to_8bit(c.r, OutputGamma::kLinear) * 299 + to_8bit(c.g, OutputGamma::kLinear) * 587 +
          to_8bit(c.b, OutputGamma::kLinear) * 114) / 1000;
}

/// Pixels whose luma differs from the median of their 8 neighbours by more than `threshold`
/// levels (border pixels are not judged): salt-and-pepper noise.
inline int isolated_outliers(const Image& image, int threshold = 60) {
  int count = 0;
  for (int y = 1; y + 1 < image.height(); ++y)
    for (int x = 1; x + 1 < image.width(); ++x) {
      std::array<int, 8> around;
      int k = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (dx || dy) around[size_t(k++)] = luma8(image, x + dx, y + dy);
      std::sort(around.begin(), around.end());
      const double median = 0.5 * (around[3] + around[4]);
      if (std::abs(luma8(image, x, y) - median) > threshold) ++count;
    }
  return count;
}

}  // namespace mjray::test
