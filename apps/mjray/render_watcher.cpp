#include "render_watcher.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace mjray {

namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void on_interrupt(int) { g_interrupted = true; }

std::string clock_text(double seconds) {
  const long s = long(seconds + 0.5);
  char buffer[32];
  if (s >= 3600) std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(buffer, sizeof buffer, "%ld:%02ld", s / 60, s % 60);
  return buffer;
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interrupted() { return g_interrupted; }

RenderWatcher::RenderWatcher(ImageRender& render, std::filesystem::path image_path, WatchOptions options)
    : render_(render), image_path_(std::move(image_path)), options_(options), terminal_(::isatty(2) != 0) {
  thread_ = std::thread([this] { loop(); });
}

RenderWatcher::~RenderWatcher() {
  done_ = true;
  thread_.join();
}

void RenderWatcher::loop() {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto last_snapshot = start, last_report = start;
  while (!done_) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (interrupted()) render_.request_stop();
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    if (std::chrono::duration<double>(now - last_report).count() >= (terminal_ ? 0.25 : 0.5)) {
      report(elapsed, false);
      last_report = now;
    }
    // Rewrite the image with what is finished so far; a failure here must not stop the render.
    if (options_.snapshot_interval_seconds > 0 &&
        std::chrono::duration<double>(now - last_snapshot).count() >= options_.snapshot_interval_seconds) {
      try {
        write_image(render_.snapshot(), image_path_, options_.encoding);
      } catch (const std::exception& e) {
        if (!options_.quiet) std::fprintf(stderr, "\nmjray: warning: %s\n", e.what());
      }
      last_snapshot = now;
    }
  }
  report(std::chrono::duration<double>(Clock::now() - start).count(), true);
}

void RenderWatcher::report(double elapsed, bool final) {
  if (options_.quiet) return;
  const RenderProgress p = render_.progress();
  double fraction = p.total ? double(p.done) / double(p.total) : 0;
  if (final && finished_) fraction = 1;
  fraction = std::max(shown_fraction_, std::min(fraction, final && finished_ ? 1.0 : 0.999));
  shown_fraction_ = fraction;
  const double rays_per_second = elapsed > 0 ? double(p.rays) / elapsed : 0;
  const std::string stage = p.antialias_pass > 0 && !(final && finished_) ? " (anti-aliasing pass " + std::to_string(p.antialias_pass) + ")" : "";
  if (terminal_) {
    // A live bar rewritten in place.
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    std::string bar(size_t(filled), '=');
    if (filled < kWidth) bar += '>' + std::string(size_t(kWidth - filled - 1), ' ');
    const double eta = fraction > 0.001 ? elapsed * (1 - fraction) / fraction : 0;
    std::fprintf(stderr, "\r[%s] %5.1f%%  %6.2f Mrays/s  elapsed %s  ETA %s%s   ", bar.c_str(), fraction * 100,
                 rays_per_second / 1e6, clock_text(elapsed).c_str(), clock_text(eta).c_str(), stage.c_str());
    if (final) std::fputc('\n', stderr);
    return;
  }
  // Not a terminal: one line each time another tenth is done.
  const int decile = int(fraction * 10 + 1e-9);
  if (decile > last_decile_ && (decile > 0 || final)) {
    last_decile_ = decile;
    std::fprintf(stderr, "mjray: %3d%% done, %.1fs elapsed, %.2f Mrays/s%s\n", decile * 10, elapsed,
                 rays_per_second / 1e6, stage.c_str());
  }
}

}  // namespace mjray
