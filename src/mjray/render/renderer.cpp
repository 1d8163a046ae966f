#include "mjray/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace mjray {

int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

Image render_image(const PinholeCamera& camera, int width, int height,
                   const WhittedIntegrator& integrator, const RenderSettings& settings,
                   RenderStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  Image image(width, height);
  const int tile = std::max(1, settings.tile_size);
  const int tiles_x = (width + tile - 1) / tile, tiles_y = (height + tile - 1) / tile;
  const int tile_count = tiles_x * tiles_y;
  const int thread_count = std::clamp(resolve_thread_count(settings.threads), 1, std::max(1, tile_count));

  // Each worker takes the next tile from a shared counter and keeps its own ray counts.
  std::atomic<int> next_tile{0};
  std::vector<RayCounters> counters(static_cast<size_t>(thread_count));
  auto worker = [&](int index) {
    RayCounters& mine = counters[size_t(index)];
    for (int t = next_tile++; t < tile_count; t = next_tile++) {
      const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
      const int x1 = std::min(width, x0 + tile), y1 = std::min(height, y0 + tile);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          RandomStream random(settings.seed, uint64_t(y) * uint64_t(width) + uint64_t(x), 0);
          image.at(x, y) = integrator.radiance(camera.generate_ray(x + 0.5f, y + 0.5f), random, mine);
        }
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < thread_count; ++i) pool.emplace_back(worker, i);
  worker(0);
  for (auto& thread : pool) thread.join();

  if (stats) {
    stats->rays = {};
    for (const auto& c : counters) stats->rays += c;
    stats->threads = thread_count;
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

}  // namespace mjray
