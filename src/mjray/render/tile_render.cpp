#include "mjray/render/tile_render.h"

#include <algorithm>

#include "mjray/core/parallel_for.h"

namespace mjray {

TileRender::TileRender(const ImageSampler& sampler, const TileLayout& layout, int threads)
    : sampler_(sampler), layout_(layout), thread_count_(std::clamp(resolve_thread_count(threads), 1, std::max(1, layout.count()))) {
  states_.resize(size_t(thread_count_));
  published_rays_ = std::make_unique<std::atomic<uint64_t>[]>(size_t(thread_count_));
  for (int t = 0; t < thread_count_; ++t) published_rays_[size_t(t)] = 0;
}

void TileRender::publish(int thread) {
  published_rays_[size_t(thread)].store(states_[size_t(thread)].rays.total(), std::memory_order_relaxed);
}

bool TileRender::render_tiles(std::span<const int> tiles, Film& film, std::stop_token stop,
                              const std::function<void(int)>& on_tile) {
  std::atomic<bool> skipped{false};
  // A tile once started finishes, so that its pixels are complete or untouched.
  parallel_for(int(tiles.size()), thread_count_, [&](int k, int thread) {
    if (stop.stop_requested()) {
      skipped = true;
      return;
    }
    const int tile = tiles[size_t(k)];
    sampler_.first_pass(layout_.rect(tile), film, states_[size_t(thread)]);
    publish(thread);
    if (on_tile) on_tile(tile);
  });
  return !skipped;
}

bool TileRender::render_pixels(std::span<const int> pixels, const PixelPass& pass, std::stop_token stop,
                               const std::function<void(const PixelChunk&)>& on_chunk) {
  std::atomic<bool> skipped{false};
  const int width = sampler_.width();
  const int chunks = int((pixels.size() + kChunk - 1) / kChunk);
  parallel_for(chunks, thread_count_, [&](int c, int thread) {
    if (stop.stop_requested()) {
      skipped = true;
      return;
    }
    const size_t begin = size_t(c) * kChunk, end = std::min(pixels.size(), begin + kChunk);
    FilmPixel values[kChunk];
    for (size_t k = begin; k < end; ++k)
      values[k - begin] = sampler_.sample_pixel(pixels[k] % width, pixels[k] / width, pass, states_[size_t(thread)]);
    publish(thread);
    on_chunk({pixels.subspan(begin, end - begin), std::span<const FilmPixel>(values, end - begin)});
  });
  return !skipped;
}

RayCounters TileRender::rays() const {
  RayCounters total;
  for (const TraceState& s : states_) total += s.rays;
  return total;
}

uint64_t TileRender::rays_published() const {
  uint64_t rays = 0;
  for (int t = 0; t < thread_count_; ++t) rays += published_rays_[size_t(t)].load(std::memory_order_relaxed);
  return rays;
}

}  // namespace mjray
