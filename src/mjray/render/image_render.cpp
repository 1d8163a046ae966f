#include "mjray/render/image_render.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "mjray/core/error.h"
#include "mjray/core/seconds_since.h"
#include "mjray/render/adaptive_antialiasing.h"
#include "mjray/render/noise_estimate.h"
#include "mjray/render/tile_render.h"

namespace mjray {

namespace {

TileLayout layout_of(const PixelRect& region, int tile_size) {
  return {region.x1 - region.x0, region.y1 - region.y0, std::max(1, tile_size)};
}

/// Camera samples per pixel of the first pass and of an anti-aliasing estimate.
uint64_t first_pass_samples(const SamplingSettings& s) { return uint64_t(std::max(1, s.first_pass_samples())); }
uint64_t antialias_samples(const SamplingSettings& s) {
  return uint64_t(s.antialias_samples) * uint64_t(s.antialias_samples) * uint64_t(std::max(1, s.samples_per_pixel));
}

/// What pass `k` (1-based) after the first computes for each pixel it takes.
PixelPass pixel_pass(const SamplingSettings& s, int k) {
  if (!s.targets_noise()) return {};
  const uint64_t first = first_pass_samples(s) << (k - 1);
  return {PixelPass::Kind::kMoreSamples, uint32_t(first),
          uint32_t(std::min(first, uint64_t(s.max_samples_per_pixel) - first))};
}

}  // namespace

int pixel_pass_count(const SamplingSettings& s) {
  if (s.targets_noise()) {
    int passes = 0;
    for (uint64_t total = first_pass_samples(s); total < uint64_t(s.max_samples_per_pixel); total *= 2) ++passes;
    return passes;
  }
  return s.antialias_samples > 0 && !s.subdivides() ? s.antialias_max_passes : 0;
}

PixelRect rendered_region(int width, int height, const RenderSettings& settings) {
  if (!settings.crop) return {0, 0, width, height};
  // A pixel's plan for the next pass looks at its neighbours' neighbours (anti-aliasing) or its
  // neighbours (the noise target); subdivided pixels depend on nothing outside themselves.
  const int reach = settings.targets_noise() ? 1 : 2;
  const int margin = reach * pixel_pass_count(settings);
  const PixelRect& c = *settings.crop;
  return {std::max(0, c.x0 - margin), std::max(0, c.y0 - margin), std::min(width, c.x1 + margin),
          std::min(height, c.y1 + margin)};
}

ImageRender::ImageRender(const Camera& camera, int width, int height, const Integrator& integrator,
                         const RenderSettings& settings, const TileExecutorFactory& executor)
    : region_(rendered_region(width, height, settings)),
      sampler_(camera, integrator, width, height, settings, region_),
      settings_(settings),
      layout_(layout_of(region_, settings.tile_size)),
      workers_(executor ? executor(sampler_, layout_) : std::make_unique<TileRender>(sampler_, layout_, settings.threads)),
      film_(layout_.width, layout_.height),
      supersampled_(size_t(layout_.width) * size_t(layout_.height), 0) {
  const PixelRect crop = settings.crop.value_or(region_);
  window_ = {crop.x0 - region_.x0, crop.y0 - region_.y0, crop.x1 - region_.x0, crop.y1 - region_.y0};
  settings_.tile_size = layout_.tile_size;
  tile_done_ = std::make_unique<std::atomic<uint8_t>[]>(size_t(layout_.count()));
  for (int t = 0; t < layout_.count(); ++t) tile_done_[size_t(t)] = 0;
  total_ = uint64_t(layout_.width) * uint64_t(layout_.height) * first_pass_samples(settings);
}

Image ImageRender::windowed(Image image) const {
  if (!settings_.crop) return image;
  Image window(window_.x1 - window_.x0, window_.y1 - window_.y0);
  for (int y = 0; y < window.height(); ++y)
    for (int x = 0; x < window.width(); ++x) window.at(x, y) = image.at(x + window_.x0, y + window_.y0);
  return window;
}

Image ImageRender::image() const { return windowed(film_.resolve()); }

void ImageRender::resume_from(const RenderCheckpoint& c) {
  if (c.film.width() != film_.width() || c.film.height() != film_.height() || c.tile_size != layout_.tile_size ||
      c.tile_done.size() != size_t(layout_.count()) || c.supersampled.size() != supersampled_.size())
    throw SceneError("the resume state does not match this render (size or tiles differ)");
  film_ = c.film;
  supersampled_ = c.supersampled;
  pass_pixels_ = c.pass_pixels;
  pass_done_ = c.pass_done;
  antialias_pass_ = c.antialias_pass;
  if (settings_.targets_noise()) pixels_refining_ = pass_pixels_.size();
  uint64_t done = 0;
  for (int t = 0; t < layout_.count(); ++t) {
    tile_done_[size_t(t)] = c.tile_done[size_t(t)];
    if (c.tile_done[size_t(t)]) done += uint64_t(layout_.rect(t).pixel_count()) * first_pass_samples(settings_);
  }
  done_ = done;
}

bool ImageRender::run() {
  const auto start = std::chrono::steady_clock::now();
  const bool finished = run_first_pass() && run_pixel_passes();
  seconds_ += seconds_since(start);
  return finished;
}

bool ImageRender::run_first_pass() {
  if (antialias_pass_ > 0) return true;
  std::vector<int> pending;
  for (int t = 0; t < layout_.count(); ++t)
    if (!tile_done_[size_t(t)]) pending.push_back(t);
  const bool finished = workers_->render_tiles(pending, film_, stop_.get_token(), [&](int tile) {
    tile_done_[size_t(tile)].store(1, std::memory_order_release);
    done_ += uint64_t(layout_.rect(tile).pixel_count()) * first_pass_samples(settings_);
    if (++tiles_finished_ == stop_after_tiles_) stop_.request_stop();
  });
  if (!finished) return false;
  antialias_pass_ = 1;
  return true;
}

bool ImageRender::plan_pass() {
  std::lock_guard lock(film_mutex_);  // checkpoint() may read the plan from another thread
  const std::vector<int> pixels =
      settings_.targets_noise()
          ? next_noise_set(film_, settings_.noise_threshold, float(settings_.max_samples_per_pixel))
          : next_supersample_set(film_.resolve(), settings_.antialias_threshold, supersampled_);
  if (pixels.empty()) return false;
  pass_pixels_.assign(pixels.begin(), pixels.end());
  pass_done_.assign(pixels.size(), 0);
  if (settings_.targets_noise()) pixels_refining_ = pixels.size();
  return true;
}

bool ImageRender::run_pixel_passes() {
  const int passes = pixel_pass_count(settings_);
  while (antialias_pass_ <= passes) {
    if (stop_.stop_requested()) return false;
    // Plan the pass from the image the last pass left (a resumed pass keeps its plan).
    if (pass_pixels_.empty() && !plan_pass()) break;
    const PixelPass pass = pixel_pass(settings_, antialias_pass_);
    const uint64_t samples_per_pixel = pass.kind == PixelPass::Kind::kSupersample ? antialias_samples(settings_) : pass.count;
    std::vector<int> pending;
    std::vector<size_t> plan_index;  // of each pending pixel in pass_pixels_
    for (size_t k = 0; k < pass_pixels_.size(); ++k) {
      if (pass_done_[k]) {
        done_ += samples_per_pixel;
        continue;
      }
      pending.push_back(pass_pixels_[k]);
      plan_index.push_back(k);
    }
    total_ += pass_pixels_.size() * samples_per_pixel;
    const bool finished = workers_->render_pixels(pending, pass, stop_.get_token(), [&](const PixelChunk& chunk) {
      const size_t first = size_t(chunk.pixels.data() - pending.data());
      std::lock_guard lock(film_mutex_);
      for (size_t k = 0; k < chunk.pixels.size(); ++k) {
        const int p = chunk.pixels[k];
        FilmPixel& pixel = film_.at(p % film_.width(), p / film_.width());
        if (pass.kind == PixelPass::Kind::kSupersample) pixel = chunk.values[k];
        else pixel.merge(chunk.values[k]);
        pass_done_[plan_index[first + k]] = 1;
      }
      pixels_supersampled_ += chunk.pixels.size();
      done_ += chunk.pixels.size() * samples_per_pixel;
      if (++chunks_finished_ == stop_after_chunks_) stop_.request_stop();
    });
    if (!finished) return false;
    // The plan and the pass number change together, so a checkpoint never sees one without the other.
    std::lock_guard lock(film_mutex_);
    pass_pixels_.clear();
    pass_done_.clear();
    pixels_refining_ = 0;
    ++antialias_passes_run_;
    ++antialias_pass_;
  }
  antialias_pass_ = passes + 1;
  return true;
}

RenderProgress ImageRender::progress() const {
  return {done_.load(), total_.load(), workers_->rays_published(), antialias_pass_, pixels_refining_.load()};
}

Image ImageRender::snapshot() const {
  std::lock_guard lock(film_mutex_);
  if (antialias_pass_ > 0) return windowed(film_.resolve());
  // First pass: copy only tiles whose writes are complete.
  Image copy(film_.width(), film_.height());
  for (int t = 0; t < layout_.count(); ++t) {
    if (!tile_done_[size_t(t)].load(std::memory_order_acquire)) continue;
    const PixelRect r = layout_.rect(t);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) copy.at(x, y) = film_.at(x, y).value();
  }
  return windowed(std::move(copy));
}

std::vector<uint8_t> ImageRender::finished_tiles() const {
  std::vector<uint8_t> finished(size_t(layout_.count()));
  for (int t = 0; t < layout_.count(); ++t) finished[size_t(t)] = tile_done_[size_t(t)].load(std::memory_order_acquire);
  return finished;
}

RenderCheckpoint ImageRender::checkpoint() const {
  std::lock_guard lock(film_mutex_);
  RenderCheckpoint c;
  c.tile_size = layout_.tile_size;
  c.antialias_pass = antialias_pass_;
  c.tile_done = finished_tiles();
  c.supersampled = supersampled_;
  c.pass_pixels = pass_pixels_;
  c.pass_done = pass_done_;
  c.film = Film(film_.width(), film_.height());
  if (antialias_pass_ > 0) {
    c.film = film_;
  } else {
    for (int t = 0; t < layout_.count(); ++t) {
      if (!c.tile_done[size_t(t)]) continue;
      const PixelRect r = layout_.rect(t);
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) c.film.at(x, y) = film_.at(x, y);
    }
  }
  return c;
}

RenderStats ImageRender::stats() const {
  RenderStats s;
  s.rays = workers_->rays();
  s.threads = workers_->threads();
  s.pixels_supersampled = pixels_supersampled_;
  s.antialias_passes = antialias_passes_run_;
  s.subdivided = settings_.subdivides();
  s.refined_to_noise = settings_.targets_noise();
  s.seconds = seconds_;
  return s;
}

Image render_image(const Camera& camera, int width, int height, const Integrator& integrator,
                   const RenderSettings& settings, RenderStats* stats) {
  ImageRender render(camera, width, height, integrator, settings);
  MJRAY_CHECK(render.run());
  if (stats) *stats = render.stats();
  return render.image();
}

}  // namespace mjray
