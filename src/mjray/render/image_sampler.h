#pragma once
/// Where camera samples go in a pixel and which random stream each one draws from: the pure,
/// single-threaded core of every render (drivers decide which pixels, on which thread or rank).

#include <algorithm>
#include <cstdint>
#include <stop_token>

#include "mjray/camera/camera.h"
#include "mjray/integrator/integrator.h"
#include "mjray/render/film.h"
#include "mjray/render/lens_points.h"
#include "mjray/render/tile_layout.h"

namespace mjray {

/// How -a anti-aliases (--aa-method).
enum class AntialiasMethod {
  kGrid,       ///< bad pixels and their neighbours get N×N jittered cells each (the original's)
  kSubdivide,  ///< every pixel is subdivided from its corners (subdivided_pixel.h), in one pass
};

/// How camera samples are placed.
struct SamplingSettings {
  uint64_t seed = 0;                ///< --seed: keys every random number
  int antialias_samples = 0;        ///< -a: N×N jittered samples in bad pixels; 0 = off
  AntialiasMethod antialias_method = AntialiasMethod::kGrid;  ///< --aa-method
  float antialias_threshold = 0.1f; ///< --aa-threshold: neighbour difference that makes a pixel bad
  int antialias_max_passes = 4;     ///< passes of adaptive supersampling at most
  /// --spp: stratified first-pass samples in every pixel (1 = the pixel centre). A bad pixel's
  /// anti-aliasing estimate then has -a² times as many: N×N cells of this many each.
  int samples_per_pixel = 1;
  /// --noise-threshold: after the first pass, passes of more samples go to every pixel whose
  /// estimated error relative to its brightness is still above this (noise_estimate.h); 0 = off.
  float noise_threshold = 0;
  /// --max-spp: the most samples a pixel gets from the noise target's passes.
  int max_samples_per_pixel = 4096;

  /// Whether the first pass subdivides every pixel, leaving no anti-aliasing passes.
  bool subdivides() const { return antialias_samples > 0 && antialias_method == AntialiasMethod::kSubdivide; }
  /// Whether passes refine the image to a noise target.
  bool targets_noise() const { return noise_threshold > 0; }
  /// The samples the first pass takes in every pixel: --spp, and at least kNoiseFirstSamples
  /// under a noise target (its error estimate needs a spread to measure).
  int first_pass_samples() const { return targets_noise() ? std::max(samples_per_pixel, kNoiseFirstSamples) : samples_per_pixel; }
  static constexpr int kNoiseFirstSamples = 16;
};

/// What a pass over chosen pixels computes for each of them.
struct PixelPass {
  enum class Kind : uint8_t {
    kSupersample,  ///< -a's estimate, which replaces the pixel's
    kMoreSamples,  ///< samples first..first+count-1 of the pixel, added to its estimate
  };
  Kind kind = Kind::kSupersample;
  uint32_t first = 0;
  uint32_t count = 0;
  bool operator==(const PixelPass&) const = default;
};

/// The random stream of a camera sample is keyed by (seed, pixel, sample index); draws within
/// it are numbered in the order they are made: the position in the pixel (two, except for the
/// single first-pass sample at the centre), the lens point (two, with --aa-method subdivide
/// only: the other passes take theirs from LensPoints), then the integrator's (light samples,
/// lobes, bounces), so no two draws of one sample collide.
/// Sample indices of the passes are disjoint:
///   first pass sample s (s < --spp; the pixel centre when --spp is 1): s · 2³²
///   adaptive anti-aliasing sample k of a pixel (k < N²·spp):           k + 1
///   --aa-method subdivide, sample s (s < spp) of a lattice point:        2³¹ + s + 1
/// A subdivided pixel's lattice points are keyed by their place in the image's lattice rather
/// than by pixel, so a corner that pixels (or tiles, or processes) share is the same sample.
constexpr uint64_t first_pass_sample_index(uint32_t s) { return uint64_t(s) << 32; }
constexpr uint64_t antialias_sample_index(uint32_t k) { return uint64_t(k) + 1; }
constexpr uint64_t subdivision_sample_index(uint32_t s) { return antialias_sample_index((uint32_t(1) << 31) + s); }

/// A stratified grid of n cells over a pixel: columns × rows = n, as square as n's divisors
/// allow (16: 4×4, 8: 4×2, 7: 7×1).
struct StratifiedGrid {
  int columns = 1, rows = 1;
};
StratifiedGrid stratified_grid(int n);

/// Turns pixels into film samples through a camera and an integrator. Pixels are numbered in
/// `region`, a window of the width × height image (the whole image unless a crop asks for
/// less); random streams and camera rays use image coordinates.
class ImageSampler {
 public:
  /// The camera, integrator and settings must outlive the sampler.
  ImageSampler(const Camera& camera, const Integrator& integrator, int width, int height,
               const SamplingSettings& settings)
      : ImageSampler(camera, integrator, width, height, settings, {0, 0, width, height}) {}
  /// Samples only `region` (which must lie inside the image).
  ImageSampler(const Camera& camera, const Integrator& integrator, int width, int height,
               const SamplingSettings& settings, const PixelRect& region);

  /// The size of the region sampled (what films, tiles and pixel indices cover).
  int width() const { return region_.x1 - region_.x0; }
  int height() const { return region_.y1 - region_.y0; }
  const PixelRect& region() const { return region_; }
  const SamplingSettings& settings() const { return settings_; }

  /// The first pass over `rect` (region coordinates): --spp stratified samples per pixel
  /// (one through the centre when --spp is 1), added to `film`; with settings().subdivides(),
  /// each pixel's subdivided estimate instead. Stops between rows once `stop` is requested
  /// (the rows done are in `film`); returns whether every row was done.
  bool first_pass(const PixelRect& rect, Film& film, TraceState& state, std::stop_token stop = {}) const;
  /// What `pass` computes for region pixel (x, y) (see PixelPass).
  FilmPixel sample_pixel(int x, int y, const PixelPass& pass, TraceState& state) const {
    return pass.kind == PixelPass::Kind::kSupersample ? supersample(x, y, state) : more_samples(x, y, pass, state);
  }
  /// The adaptive anti-aliasing estimate of region pixel (x, y): N×N jittered cells of --spp
  /// stratified samples each, which replace the pixel's first-pass estimate (the original's
  /// rule).
  FilmPixel supersample(int x, int y, TraceState& state) const;
  /// Samples pass.first to pass.first + pass.count − 1 of region pixel (x, y), stratified over
  /// the pixel among themselves, each from its own stream: what a noise target's pass adds.
  FilmPixel more_samples(int x, int y, const PixelPass& pass, TraceState& state) const;

 private:
  uint64_t pixel_key(int x, int y) const { return uint64_t(y) * uint64_t(image_width_) + uint64_t(x); }
  bool first_pass_subdivided(const PixelRect& rect, Film& film, TraceState& state, std::stop_token stop) const;
  /// Sample k of a pass of grid.columns × grid.rows samples over image pixel (ix, iy): jittered
  /// in cell k of the grid, from random stream `stream`, through `lens`; `sample` is its number
  /// among the pixel's camera samples.
  Color stratified_sample(int ix, int iy, StratifiedGrid grid, uint32_t k, uint64_t stream, LensPoint lens,
                          uint32_t sample, TraceState& state) const;
  /// The radiance of camera sample `sample` of its pixel, at image position (sx, sy), through
  /// `lens` (with a thin lens).
  Color trace(float sx, float sy, LensPoint lens, uint32_t sample, RandomStream& random, TraceState& state) const;

  const Camera& camera_;
  const Integrator& integrator_;
  int image_width_;
  PixelRect region_;
  SamplingSettings settings_;
};

}  // namespace mjray
