#include "render_watcher.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include <unistd.h>

#include "interrupts.h"
#include "mjray/core/error.h"
#include "mjray/core/seconds_since.h"

namespace mjray {

namespace {

std::string clock_text(double seconds) {
  const long s = long(seconds + 0.5);
  char buffer[32];
  if (s >= 3600) std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(buffer, sizeof buffer, "%ld:%02ld", s / 60, s % 60);
  return buffer;
}

/// Seconds between estimates of the anti-aliasing work from the finished tiles: often, since
/// the first tiles (the top of the image, often sky) say little about the rest and a first
/// pass often ends within a second, but never more than a tenth of the time on estimates.
constexpr double kShareInterval = 0.2;
constexpr double kShareCostFactor = 10;
/// Without a terminal, a line at least this often even when no tenth more is done.
constexpr double kQuietLineInterval = 5.0;

}  // namespace

RenderWatcher::RenderWatcher(ImageRender& render, std::filesystem::path image_path, WatchOptions options)
    : render_(render),
      image_path_(std::move(image_path)),
      options_(options),
      terminal_(::isatty(2) != 0),
      estimate_(options.width, options.height, options.render) {
  thread_ = std::thread([this] { loop(); });
}

RenderWatcher::~RenderWatcher() {
  {
    std::lock_guard lock(wake_mutex_);
    done_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void RenderWatcher::loop() {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto last_snapshot = start, last_report = start, last_share = start;
  double share_interval = kShareInterval;
  for (;;) {
    {
      std::unique_lock lock(wake_mutex_);
      if (wake_.wait_for(lock, std::chrono::milliseconds(50), [&] { return done_; })) break;
    }
    if (interrupted()) render_.request_stop();
    if (options_.deadline && Clock::now() >= *options_.deadline && !timed_out_) {
      timed_out_ = true;
      render_.request_stop();
    }
    const double elapsed = seconds_since(start);
    estimate_.update(render_.progress(), elapsed);
    // During the first pass, how much anti-aliasing the finished tiles will need.
    if (!options_.quiet && options_.render.antialias_samples > 0 && !options_.render.subdivides() &&
        render_.progress().antialias_pass == 0 && seconds_since(last_share) >= share_interval) {
      const auto began = Clock::now();
      const auto share =
          supersample_share(render_.snapshot(), options_.render.tile_size, options_.render.antialias_threshold);
      if (share) estimate_.set_first_pass_share(*share);
      last_share = Clock::now();
      share_interval = std::max(kShareInterval, kShareCostFactor * seconds_since(began));
    }
    if (seconds_since(last_report) >= (terminal_ ? 0.25 : 0.5)) {
      report(elapsed, false);
      last_report = Clock::now();
    }
    // Rewrite the image with what is finished so far; a failure here must not stop the render.
    if (options_.snapshot_interval_seconds > 0 && seconds_since(last_snapshot) >= options_.snapshot_interval_seconds) {
      try {
        write_image(render_.snapshot(), image_path_, options_.encoding);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "%smjray: warning: %s\n", terminal_ && !options_.quiet ? "\n" : "", error_message(e).c_str());
      }
      last_snapshot = Clock::now();
    }
  }
  const double elapsed = seconds_since(start);
  estimate_.update(render_.progress(), elapsed);
  report(elapsed, true);
}

void RenderWatcher::report(double elapsed, bool final) {
  if (options_.quiet) return;
  const bool complete = final && finished_;
  const ProgressView v = estimate_.view();
  // The bar never goes back, though a pass may find more work than was estimated.
  shown_fraction_ = std::max(shown_fraction_, v.fraction);
  const double fraction = complete ? 1.0 : shown_fraction_;
  const double eta = complete ? 0 : v.eta_seconds;
  const double rays_per_second = elapsed > 0 ? double(render_.progress().rays) / elapsed : 0;
  const std::string frame = options_.frame.empty() ? "" : options_.frame + ": ";
  std::string stage;
  if (!complete && v.clean_fraction) {
    char clean[64];
    std::snprintf(clean, sizeof clean, "%.0f%% of pixels clean", 100 * std::floor(*v.clean_fraction * 100) / 100);
    stage = v.choosing_pixels ? " (noise target: choosing pixels, " + std::string(clean) + ")"
                              : " (noise pass " + std::to_string(v.antialias_pass) + ", " + clean + ")";
  } else if (!complete && v.choosing_pixels) stage = " (anti-aliasing: choosing pixels)";
  else if (!complete && v.antialias_pass > 0) stage = " (anti-aliasing pass " + std::to_string(v.antialias_pass) + ")";
  if (terminal_) {
    // A live bar rewritten in place; \033[K clears what a longer line left behind.
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    std::string bar(size_t(filled), '=');
    if (filled < kWidth) bar += '>' + std::string(size_t(kWidth - filled - 1), ' ');
    std::fprintf(stderr, "\r%s[%s] %5.1f%%  %6.2f Mrays/s  elapsed %s  ETA %s%s\033[K", frame.c_str(), bar.c_str(),
                 fraction * 100, rays_per_second / 1e6, clock_text(elapsed).c_str(), clock_text(eta).c_str(), stage.c_str());
    if (final) std::fputc('\n', stderr);
    return;
  }
  // Not a terminal: a line each time another tenth is done or a stage begins, and at least
  // every few seconds.
  const int percent = std::max(last_percent_, int(fraction * 100 + 1e-9));
  const bool new_tenth = percent / 10 > last_percent_ / 10 || last_percent_ < 0;
  const bool new_stage = stage != last_stage_;
  last_stage_ = stage;
  if (!(final || new_stage || (new_tenth && percent >= 10) || elapsed - last_line_at_ >= kQuietLineInterval)) return;
  if (!final && !new_stage && percent == last_percent_ && elapsed - last_line_at_ < kQuietLineInterval) return;
  last_percent_ = percent;
  last_line_at_ = elapsed;
  std::fprintf(stderr, "mjray: %s%3d%% done, %.1fs elapsed, ETA %s, %.2f Mrays/s%s\n", frame.c_str(), percent, elapsed,
               clock_text(eta).c_str(), rays_per_second / 1e6, stage.c_str());
}

}  // namespace mjray
