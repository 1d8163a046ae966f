#pragma once
/// The film: per pixel, the sum of the linear radiance samples that landed in it and their
/// total weight. Tiles, anti-aliasing passes and processes accumulate into it; the checkpoint
/// stores it; the image is its resolve.

#include <cstddef>
#include <vector>

#include "mjray/core/color.h"
#include "mjray/core/image.h"

namespace mjray {

/// What one pixel of the film has gathered.
struct FilmPixel {
  Color sum;         ///< Σ weight·radiance (linear)
  float weight = 0;  ///< Σ weight; 0 = nothing rendered yet
  /// Σ weight·brightness² (Color::average), for the spread of the samples: the noise target's
  /// error estimate.
  float brightness_squares = 0;

  /// The pixel's colour: the weighted mean, black when empty.
  Color value() const { return weight > 0 ? sum / weight : Color{}; }
  /// Adds one sample of `radiance` with `weight`.
  void add(const Color& radiance, float sample_weight = 1) {
    sum += radiance * sample_weight;
    weight += sample_weight;
    const float brightness = radiance.average();
    brightness_squares += sample_weight * brightness * brightness;
  }
  /// Adds what another estimate of the same pixel gathered.
  void merge(const FilmPixel& other) {
    sum += other.sum;
    weight += other.weight;
    brightness_squares += other.brightness_squares;
  }
  bool operator==(const FilmPixel&) const = default;
};

/// Pixels in row-major order, (0,0) the top-left corner.
class Film {
 public:
  Film() = default;
  Film(int width, int height) : width_(width), height_(height), pixels_(size_t(width) * size_t(height)) {}

  int width() const { return width_; }
  int height() const { return height_; }
  FilmPixel& at(int x, int y) { return pixels_[index(x, y)]; }
  const FilmPixel& at(int x, int y) const { return pixels_[index(x, y)]; }
  /// Adds one sample of `radiance` with `weight` to pixel (x, y).
  void add(int x, int y, const Color& radiance, float weight = 1) { at(x, y).add(radiance, weight); }
  const std::vector<FilmPixel>& pixels() const { return pixels_; }
  std::vector<FilmPixel>& pixels() { return pixels_; }

  /// The image of every pixel's value.
  Image resolve() const {
    Image image(width_, height_);
    for (size_t i = 0; i < pixels_.size(); ++i) image.data()[i] = pixels_[i].value();
    return image;
  }

 private:
  size_t index(int x, int y) const { return size_t(y) * size_t(width_) + size_t(x); }

  int width_ = 0;
  int height_ = 0;
  std::vector<FilmPixel> pixels_;
};

}  // namespace mjray
