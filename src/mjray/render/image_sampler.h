#pragma once
/// Where camera samples go in a pixel and which random stream each one draws from: the pure,
/// single-threaded core of every render (drivers decide which pixels, on which thread or rank).

#include <cstdint>

#include "mjray/camera/pinhole_camera.h"
#include "mjray/integrator/integrator.h"
#include "mjray/render/film.h"
#include "mjray/render/tile_layout.h"

namespace mjray {

/// How camera samples are placed.
struct SamplingSettings {
  uint64_t seed = 0;                ///< --seed: keys every random number
  int antialias_samples = 0;        ///< -a: N×N jittered samples in bad pixels; 0 = off
  float antialias_threshold = 0.1f; ///< --aa-threshold: neighbour difference that makes a pixel bad
  int antialias_max_passes = 4;     ///< passes of adaptive supersampling at most
};

/// The random stream of a camera sample is keyed by (seed, pixel, sample index); draws within
/// it are numbered in the order the integrator makes them (light samples, lobes, bounces), so
/// no two draws of one sample collide. Sample indices of the passes are disjoint:
///   first pass sample s (the pixel centre when s = 0): s · 2³²
///   adaptive anti-aliasing sample k of a pixel (k < N²):  k + 1
constexpr uint64_t first_pass_sample_index(uint32_t s) { return uint64_t(s) << 32; }
constexpr uint64_t antialias_sample_index(uint32_t k) { return uint64_t(k) + 1; }

/// Turns pixels into film samples through a camera and an integrator.
class ImageSampler {
 public:
  /// The camera, integrator and settings must outlive the sampler.
  ImageSampler(const PinholeCamera& camera, const Integrator& integrator, int width, int height,
               const SamplingSettings& settings)
      : camera_(camera), integrator_(integrator), width_(width), height_(height), settings_(settings) {}

  int width() const { return width_; }
  int height() const { return height_; }
  const SamplingSettings& settings() const { return settings_; }

  /// The first pass over `rect`: one sample through each pixel centre, added to `film`.
  void first_pass(const PixelRect& rect, Film& film, TraceState& state) const;
  /// The adaptive anti-aliasing estimate of pixel (x, y): N×N jittered samples, which replace
  /// the pixel's first-pass estimate (the original's rule).
  FilmPixel supersample(int x, int y, TraceState& state) const;

 private:
  uint64_t pixel_key(int x, int y) const { return uint64_t(y) * uint64_t(width_) + uint64_t(x); }

  const PinholeCamera& camera_;
  const Integrator& integrator_;
  int width_, height_;
  SamplingSettings settings_;
};

}  // namespace mjray
