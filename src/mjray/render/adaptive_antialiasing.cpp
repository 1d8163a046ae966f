#include "mjray/render/adaptive_antialiasing.h"

#include <algorithm>
#include <cmath>

namespace mjray {

bool is_bad_pixel(const Image& image, int x, int y, float threshold) {
  const Color& c = image.at(x, y);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= image.width() || ny >= image.height()) continue;
      const Color& n = image.at(nx, ny);
      if (std::abs(c.r - n.r) > threshold || std::abs(c.g - n.g) > threshold || std::abs(c.b - n.b) > threshold)
        return true;
    }
  return false;
}

std::vector<int> next_supersample_set(const Image& image, float threshold, std::vector<uint8_t>& supersampled) {
  const int w = image.width(), h = image.height();
  std::vector<uint8_t> chosen(supersampled.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Pixels already supersampled are settled: they neither need work nor spread it.
      if (supersampled[size_t(y * w + x)] || !is_bad_pixel(image, x, y, threshold)) continue;
      for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx) chosen[size_t(ny * w + nx)] = 1;
    }
  std::vector<int> pixels;
  for (size_t i = 0; i < chosen.size(); ++i)
    if (chosen[i] && !supersampled[i]) {
      pixels.push_back(int(i));
      supersampled[i] = 1;
    }
  return pixels;
}

}  // namespace mjray
