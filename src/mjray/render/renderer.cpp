#include "mjray/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "mjray/core/error.h"
#include "mjray/render/adaptive_antialiasing.h"
#include "mjray/render/parallel_for.h"

namespace mjray {

int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

TileRender::TileRender(const PinholeCamera& camera, int width, int height,
                       const Integrator& integrator, const RenderSettings& settings)
    : camera_(camera), integrator_(integrator), settings_(settings), width_(width), height_(height),
      image_(width, height), supersampled_(size_t(width) * size_t(height), 0) {
  settings_.tile_size = std::max(1, settings_.tile_size);
  tiles_x_ = (width + settings_.tile_size - 1) / settings_.tile_size;
  tile_count_ = tiles_x_ * ((height + settings_.tile_size - 1) / settings_.tile_size);
  tile_done_ = std::make_unique<std::atomic<uint8_t>[]>(size_t(tile_count_));
  for (int t = 0; t < tile_count_; ++t) tile_done_[size_t(t)] = 0;
  thread_count_ = std::clamp(resolve_thread_count(settings.threads), 1, std::max(1, tile_count_));
  counters_.resize(size_t(thread_count_));
  published_rays_ = std::make_unique<std::atomic<uint64_t>[]>(size_t(thread_count_));
  for (int t = 0; t < thread_count_; ++t) published_rays_[size_t(t)] = 0;
  total_ = uint64_t(width) * uint64_t(height);
}

void TileRender::resume_from(const RenderCheckpoint& c) {
  if (c.image.width() != width_ || c.image.height() != height_ || c.tile_size != settings_.tile_size ||
      c.tile_done.size() != size_t(tile_count_) || c.supersampled.size() != supersampled_.size())
    throw SceneError("the resume state does not match this render (size or tiles differ)");
  image_ = c.image;
  supersampled_ = c.supersampled;
  antialias_pass_ = c.antialias_pass;
  uint64_t done = 0;
  for (int t = 0; t < tile_count_; ++t) {
    tile_done_[size_t(t)] = c.tile_done[size_t(t)];
    if (c.tile_done[size_t(t)]) done += uint64_t(settings_.tile_size) * uint64_t(settings_.tile_size);
  }
  done_ = std::min(done, total_.load());
}

bool TileRender::run() {
  const auto start = std::chrono::steady_clock::now();
  const bool finished = run_first_pass() && run_antialiasing();
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return finished;
}

bool TileRender::run_first_pass() {
  if (antialias_pass_ > 0) return true;
  std::vector<int> pending;
  for (int t = 0; t < tile_count_; ++t)
    if (!tile_done_[size_t(t)]) pending.push_back(t);
  const int tile = settings_.tile_size;
  // Compute one sample through each pixel centre, tile by tile; a tile once started finishes.
  parallel_for(int(pending.size()), thread_count_, [&](int k, int thread) {
    if (stop_requested_) return;
    const int t = pending[size_t(k)];
    const int x0 = (t % tiles_x_) * tile, y0 = (t / tiles_x_) * tile;
    const int x1 = std::min(width_, x0 + tile), y1 = std::min(height_, y0 + tile);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        RandomStream random(settings_.seed, uint64_t(y) * uint64_t(width_) + uint64_t(x), 0);
        image_.at(x, y) = integrator_.radiance(camera_.generate_ray(x + 0.5f, y + 0.5f), random, counters_[size_t(thread)]);
      }
    tile_done_[size_t(t)].store(1, std::memory_order_release);
    published_rays_[size_t(thread)].store(counters_[size_t(thread)].total(), std::memory_order_relaxed);
    done_ += uint64_t(x1 - x0) * uint64_t(y1 - y0);
    if (++tiles_finished_ == stop_after_tiles_) stop_requested_ = true;
  });
  for (int t = 0; t < tile_count_; ++t)
    if (!tile_done_[size_t(t)]) return false;
  antialias_pass_ = 1;
  return true;
}

Color TileRender::supersample(int x, int y, RayCounters& counters) const {
  // The mean of N×N jittered samples; sample k uses random stream k + 1 (stream 0 is the
  // pixel-centre sample of the first pass).
  const int n = settings_.antialias_samples;
  Color sum;
  const uint64_t pixel = uint64_t(y) * uint64_t(width_) + uint64_t(x);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      RandomStream random(settings_.seed, pixel, uint64_t(j * n + i) + 1);
      const float sx = float(x) + (float(i) + random.uniform()) / float(n);
      const float sy = float(y) + (float(j) + random.uniform()) / float(n);
      sum += integrator_.radiance(camera_.generate_ray(sx, sy), random, counters);
    }
  return sum / float(n * n);
}

bool TileRender::run_antialiasing() {
  if (settings_.antialias_samples <= 0) return true;
  const uint64_t samples_per_pixel = uint64_t(settings_.antialias_samples) * uint64_t(settings_.antialias_samples);
  for (; antialias_pass_ <= settings_.antialias_max_passes; ++antialias_pass_) {
    // Compute the pass's pixels from the image as the last pass left it; keep that state so
    // an interrupted pass can be redone from the start.
    pass_start_image_ = image_;
    pass_start_supersampled_ = supersampled_;
    if (stop_requested_) return false;
    const std::vector<int> pixels = next_supersample_set(image_, settings_.antialias_threshold, supersampled_);
    if (pixels.empty()) break;
    total_ += pixels.size() * samples_per_pixel;
    std::vector<Color> results(pixels.size());
    constexpr int kChunk = 64;
    const int chunks = int((pixels.size() + kChunk - 1) / kChunk);
    parallel_for(chunks, thread_count_, [&](int c, int thread) {
      if (stop_requested_) return;
      const size_t end = std::min(pixels.size(), size_t(c + 1) * kChunk);
      for (size_t k = size_t(c) * kChunk; k < end; ++k)
        results[k] = supersample(pixels[k] % width_, pixels[k] / width_, counters_[size_t(thread)]);
      done_ += (end - size_t(c) * kChunk) * samples_per_pixel;
      published_rays_[size_t(thread)].store(counters_[size_t(thread)].total(), std::memory_order_relaxed);
    });
    if (stop_requested_) {
      supersampled_ = pass_start_supersampled_;
      return false;
    }
    std::lock_guard lock(image_mutex_);
    for (size_t k = 0; k < pixels.size(); ++k) image_.at(pixels[k] % width_, pixels[k] / width_) = results[k];
    pixels_supersampled_ += pixels.size();
    ++antialias_passes_run_;
  }
  antialias_pass_ = settings_.antialias_max_passes + 1;
  return true;
}

RenderProgress TileRender::progress() const {
  uint64_t rays = 0;
  for (int t = 0; t < thread_count_; ++t) rays += published_rays_[size_t(t)].load(std::memory_order_relaxed);
  return {done_.load(), total_.load(), rays, antialias_pass_};
}

Image TileRender::snapshot() const {
  std::lock_guard lock(image_mutex_);
  if (antialias_pass_ > 0) return image_;
  // First pass: copy only tiles whose writes are complete.
  Image copy(width_, height_);
  const int tile = settings_.tile_size;
  for (int t = 0; t < tile_count_; ++t) {
    if (!tile_done_[size_t(t)].load(std::memory_order_acquire)) continue;
    const int x0 = (t % tiles_x_) * tile, y0 = (t / tiles_x_) * tile;
    for (int y = y0; y < std::min(height_, y0 + tile); ++y)
      for (int x = x0; x < std::min(width_, x0 + tile); ++x) copy.at(x, y) = image_.at(x, y);
  }
  return copy;
}

RenderCheckpoint TileRender::checkpoint() const {
  RenderCheckpoint c;
  c.tile_size = settings_.tile_size;
  c.antialias_pass = antialias_pass_;
  c.tile_done.resize(size_t(tile_count_));
  for (int t = 0; t < tile_count_; ++t) c.tile_done[size_t(t)] = tile_done_[size_t(t)];
  if (antialias_pass_ == 0) {
    c.image = snapshot();
    c.supersampled = supersampled_;
  } else {
    c.image = pass_start_image_.width() ? pass_start_image_ : image_;
    c.supersampled = pass_start_image_.width() ? pass_start_supersampled_ : supersampled_;
  }
  return c;
}

RenderStats TileRender::stats() const {
  RenderStats s;
  for (const auto& c : counters_) s.rays += c;
  s.threads = thread_count_;
  s.pixels_supersampled = pixels_supersampled_;
  s.antialias_passes = antialias_passes_run_;
  s.seconds = seconds_;
  return s;
}

Image render_image(const PinholeCamera& camera, int width, int height,
                   const Integrator& integrator, const RenderSettings& settings,
                   RenderStats* stats) {
  TileRender render(camera, width, height, integrator, settings);
  MJRAY_CHECK(render.run());
  if (stats) *stats = render.stats();
  return render.image();
}

}  // namespace mjray
