#include "mjray/render/image_sampler.h"

#include <algorithm>
#include <vector>

#include "mjray/core/error.h"
#include "mjray/render/subdivided_pixel.h"

namespace mjray {

namespace {

/// The pass numbers of LensPoints for the first pass and -a's estimate; a noise pass uses its
/// first sample's number, 16 or more.
constexpr uint64_t kFirstPassLens = 0;
constexpr uint64_t kSupersampleLens = 1;

}  // namespace

ImageSampler::ImageSampler(const Camera& camera, const Integrator& integrator, int width, int height,
                           const SamplingSettings& settings, const PixelRect& region)
    : camera_(camera), integrator_(integrator), image_width_(width), region_(region), settings_(settings) {
  MJRAY_CHECK(region.x0 >= 0 && region.y0 >= 0 && region.x0 < region.x1 && region.y0 < region.y1 &&
              region.x1 <= width && region.y1 <= height);
}

StratifiedGrid stratified_grid(int n) {
  int rows = 1;
  for (int r = 1; r * r <= n; ++r)
    if (n % r == 0) rows = r;
  return {n / rows, rows};
}

Color ImageSampler::trace(float sx, float sy, LensPoint lens, uint32_t sample, RandomStream& random,
                          TraceState& state) const {
  state.camera_sample = sample;
  if (!camera_.has_lens()) return integrator_.radiance(camera_.generate_ray(sx, sy), random, state);
  return integrator_.radiance(camera_.generate_ray(sx, sy, lens.u, lens.v), random, state);
}

Color ImageSampler::stratified_sample(int ix, int iy, StratifiedGrid grid, uint32_t k, uint64_t stream, LensPoint lens,
                                      uint32_t sample, TraceState& state) const {
  RandomStream random(settings_.seed, pixel_key(ix, iy), stream);
  const float sx = float(ix) + (float(k % uint32_t(grid.columns)) + random.uniform()) / float(grid.columns);
  const float sy = float(iy) + (float(k / uint32_t(grid.columns)) + random.uniform()) / float(grid.rows);
  return trace(sx, sy, lens, sample, random, state);
}

bool ImageSampler::first_pass(const PixelRect& rect, Film& film, TraceState& state, std::stop_token stop) const {
  if (settings_.subdivides()) return first_pass_subdivided(rect, film, state, stop);
  const int n = settings_.first_pass_samples();
  const StratifiedGrid grid = stratified_grid(n);
  for (int y = rect.y0; y < rect.y1; ++y) {
    if (stop.stop_requested()) return false;
    for (int x = rect.x0; x < rect.x1; ++x) {
      const int ix = x + region_.x0, iy = y + region_.y0;
      const LensPoints lens(settings_.seed, pixel_key(ix, iy), kFirstPassLens, uint32_t(std::max(1, n)));
      if (n <= 1) {
        RandomStream random(settings_.seed, pixel_key(ix, iy), first_pass_sample_index(0));
        film.add(x, y, trace(float(ix) + 0.5f, float(iy) + 0.5f, lens.at(0), 0, random, state));
        continue;
      }
      for (uint32_t s = 0; s < uint32_t(n); ++s)
        film.add(x, y, stratified_sample(ix, iy, grid, s, first_pass_sample_index(s), lens.at(s), s, state));
    }
  }
  return true;
}

FilmPixel ImageSampler::supersample(int x, int y, TraceState& state) const {
  // Compute the sum over a jittered grid of the pixel: N×N cells, each a stratified --spp grid.
  const int n = settings_.antialias_samples;
  const StratifiedGrid cell = stratified_grid(std::max(1, settings_.samples_per_pixel));
  const int columns = n * cell.columns, rows = n * cell.rows;
  const int ix = x + region_.x0, iy = y + region_.y0;
  const LensPoints lens(settings_.seed, pixel_key(ix, iy), kSupersampleLens, uint32_t(columns * rows));
  Color sum;
  for (uint32_t k = 0; k < uint32_t(columns * rows); ++k)
    sum += stratified_sample(ix, iy, {columns, rows}, k, antialias_sample_index(k), lens.at(k), k, state);
  return {sum, float(columns * rows)};
}

FilmPixel ImageSampler::more_samples(int x, int y, const PixelPass& pass, TraceState& state) const {
  const StratifiedGrid grid = stratified_grid(int(pass.count));
  const int ix = x + region_.x0, iy = y + region_.y0;
  const LensPoints lens(settings_.seed, pixel_key(ix, iy), pass.first, pass.count);
  FilmPixel estimate;
  for (uint32_t k = 0; k < pass.count; ++k) {
    // Numbered on from the first pass's samples, so that each has a stream of its own.
    const uint32_t sample = pass.first + k;
    estimate.add(stratified_sample(ix, iy, grid, k, first_pass_sample_index(sample), lens.at(k), sample, state));
  }
  return estimate;
}

bool ImageSampler::first_pass_subdivided(const PixelRect& rect, Film& film, TraceState& state,
                                         std::stop_token stop) const {
  const int cells = SubdivisionLattice::finest_for(settings_.antialias_samples).cells();
  const int spp = std::max(1, settings_.samples_per_pixel);
  const uint64_t image_columns = uint64_t(image_width_) * uint64_t(cells) + 1;
  // The lattice points of one row of pixels, cells + 1 rows of them; its last row is the next
  // pixel row's first.
  const size_t columns = size_t(rect.x1 - rect.x0) * size_t(cells) + 1;
  std::vector<Color> colours(columns * size_t(cells + 1));
  std::vector<uint8_t> known(colours.size(), 0);
  for (int y = rect.y0; y < rect.y1; ++y) {
    if (stop.stop_requested()) return false;
    if (y > rect.y0) {
      const size_t last = columns * size_t(cells);
      std::copy(colours.begin() + std::ptrdiff_t(last), colours.end(), colours.begin());
      std::copy(known.begin() + std::ptrdiff_t(last), known.end(), known.begin());
      std::fill(known.begin() + std::ptrdiff_t(columns), known.end(), 0);
    }
    const uint64_t gy0 = uint64_t(y + region_.y0) * uint64_t(cells);
    for (int x = rect.x0; x < rect.x1; ++x) {
      const size_t lx0 = size_t(x - rect.x0) * size_t(cells);
      const uint64_t gx0 = uint64_t(x + region_.x0) * uint64_t(cells);
      const auto corner = [&](int i, int j) -> const Color& {
        const size_t k = size_t(j) * columns + lx0 + size_t(i);
        if (known[k]) return colours[k];
        const uint64_t gx = gx0 + uint64_t(i), gy = gy0 + uint64_t(j);
        Color sum;
        for (int s = 0; s < spp; ++s) {
          RandomStream random(settings_.seed, gy * image_columns + gx, subdivision_sample_index(uint32_t(s)));
          // Jittered by up to half a cell either way, as POV-Ray's +J1.
          const float sx = (float(gx) + random.uniform() - 0.5f) / float(cells);
          const float sy = (float(gy) + random.uniform() - 0.5f) / float(cells);
          // A lattice point's samples are too few to stratify: its lens point is drawn.
          const LensPoint lens{random.uniform(), random.uniform()};
          sum += trace(sx, sy, lens, uint32_t(s), random, state);
        }
        known[k] = 1;
        return colours[k] = sum / float(spp);
      };
      film.add(x, y, subdivided_estimate(0, 0, cells, settings_.antialias_threshold, corner));
    }
  }
  return true;
}

}  // namespace mjray
