#include "mjray/render/noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mjray {

namespace {

/// Brightness below which the error is weighed as at this brightness: black and nearly black
/// pixels are not refined without end for noise no one sees.
constexpr double kDarkFloor = 1e-3;

}  // namespace

float relative_error(const FilmPixel& pixel) {
  const double n = pixel.weight;
  if (!(n > 1)) return 0;
  const double mean = double(pixel.sum.average()) / n;
  const double spread = std::max(0.0, double(pixel.brightness_squares) / n - mean * mean) * n / (n - 1);
  const double standard_error = std::sqrt(spread / n);
  return float(standard_error / std::sqrt(std::max(mean, kDarkFloor)));
}

std::vector<int> next_noise_set(const Film& film, float threshold, float max_samples) {
  const int w = film.width(), h = film.height();
  std::vector<uint8_t> chosen(size_t(w) * size_t(h), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!(relative_error(film.at(x, y)) > threshold)) continue;
      for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny)
        for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx) chosen[size_t(ny) * size_t(w) + size_t(nx)] = 1;
    }
  std::vector<int> pixels;
  for (size_t p = 0; p < chosen.size(); ++p)
    if (chosen[p] && film.pixels()[p].weight < max_samples) pixels.push_back(int(p));
  return pixels;
}

}  // namespace mjray
