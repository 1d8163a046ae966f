#include "mjray/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#include "mjray/render/adaptive_antialiasing.h"
#include "mjray/render/parallel_for.h"

namespace mjray {

int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

namespace {

/// The mean of N×N jittered samples over pixel (x, y); sample k uses random stream k + 1
/// (stream 0 is the pixel-centre sample of the first pass).
Color supersample(const PinholeCamera& camera, const WhittedIntegrator& integrator, uint64_t seed,
                  int width, int x, int y, int n, RayCounters& counters) {
  Color sum;
  const uint64_t pixel = uint64_t(y) * uint64_t(width) + uint64_t(x);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      RandomStream random(seed, pixel, uint64_t(j * n + i) + 1);
      const float sx = float(x) + (float(i) + random.uniform()) / float(n);
      const float sy = float(y) + (float(j) + random.uniform()) / float(n);
      sum += integrator.radiance(camera.generate_ray(sx, sy), random, counters);
    }
  return sum / float(n * n);
}

}  // namespace

Image render_image(const PinholeCamera& camera, int width, int height,
                   const WhittedIntegrator& integrator, const RenderSettings& settings,
                   RenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  Image image(width, height);
  const int tile = std::max(1, settings.tile_size);
  const int tiles_x = (width + tile - 1) / tile, tiles_y = (height + tile - 1) / tile;
  const int tile_count = tiles_x * tiles_y;
  const int thread_count = std::clamp(resolve_thread_count(settings.threads), 1, std::max(1, tile_count));
  std::vector<RayCounters> counters(static_cast<size_t>(thread_count));

  // Compute one sample through each pixel centre, tile by tile.
  parallel_for(tile_count, thread_count, [&](int t, int thread) {
    const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
    const int x1 = std::min(width, x0 + tile), y1 = std::min(height, y0 + tile);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        RandomStream random(settings.seed, uint64_t(y) * uint64_t(width) + uint64_t(x), 0);
        image.at(x, y) = integrator.radiance(camera.generate_ray(x + 0.5f, y + 0.5f), random, counters[size_t(thread)]);
      }
  });

  // Compute adaptive anti-aliasing passes: each reads the image as the last pass left it.
  uint64_t supersampled_count = 0;
  int passes = 0;
  if (settings.antialias_samples > 0) {
    std::vector<uint8_t> supersampled(size_t(width) * size_t(height), 0);
    for (; passes < settings.antialias_max_passes; ++passes) {
      const std::vector<int> pixels = next_supersample_set(image, settings.antialias_threshold, supersampled);
      if (pixels.empty()) break;
      supersampled_count += pixels.size();
      std::vector<Color> results(pixels.size());
      constexpr int kChunk = 64;
      const int chunks = int((pixels.size() + kChunk - 1) / kChunk);
      parallel_for(chunks, thread_count, [&](int c, int thread) {
        const size_t end = std::min(pixels.size(), size_t(c + 1) * kChunk);
        for (size_t k = size_t(c) * kChunk; k < end; ++k)
          results[k] = supersample(camera, integrator, settings.seed, width, pixels[k] % width, pixels[k] / width,
                                   settings.antialias_samples, counters[size_t(thread)]);
      });
      for (size_t k = 0; k < pixels.size(); ++k) image.at(pixels[k] % width, pixels[k] / width) = results[k];
    }
  }

  if (stats) {
    stats->rays = {};
    for (const auto& c : counters) stats->rays += c;
    stats->threads = thread_count;
    stats->pixels_supersampled = supersampled_count;
    stats->antialias_passes = passes;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

}  // namespace mjray
