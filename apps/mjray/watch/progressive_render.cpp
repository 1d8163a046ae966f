#include "progressive_render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

#include "interrupts.h"
#include "preview_image.h"
#include "progress_estimate.h"
#include "mjray/job/prepared_job.h"

namespace mjray {

namespace {

using Clock = std::chrono::steady_clock;

/// How often a running pass's progress and image reach the page.
constexpr auto kPublishInterval = std::chrono::milliseconds(200);
/// How often the monitor asks whether to stop.
constexpr auto kPollInterval = std::chrono::milliseconds(20);

/// While alive, a thread beside one running pass: stops it when `stop_wanted()` turns true
/// and calls `publish()` every kPublishInterval.
class PassMonitor {
 public:
  // Both functions are kept by value: a caller's lambda arrives as a temporary std::function.
  PassMonitor(ImageRender& render, std::function<bool()> stop_wanted, std::function<void()> publish)
      : thread_([this, &render, stop_wanted = std::move(stop_wanted), publish = std::move(publish)] {
          auto last_publish = Clock::now();
          while (!done_) {
            std::this_thread::sleep_for(kPollInterval);
            if (stop_wanted()) render.request_stop();
            if (Clock::now() - last_publish >= kPublishInterval) {
              publish();
              last_publish = Clock::now();
            }
          }
        }) {}
  ~PassMonitor() {
    done_ = true;
    thread_.join();
  }

 private:
  std::atomic<bool> done_{false};
  std::thread thread_;
};

/// The page's progress figures for a pass started at `start`.
FrameProgress progress_of(const ImageRender& render, ProgressEstimate& estimate, Clock::time_point start,
                          FramePhase phase) {
  const RenderProgress p = render.progress();
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  estimate.update(p, elapsed);
  const ProgressView view = estimate.view();
  if (phase == FramePhase::kFirstPass && p.antialias_pass > 0) phase = FramePhase::kAntialiasing;
  return {phase, view.fraction, view.eta_seconds, elapsed > 0 ? double(p.rays) / elapsed : 0, view.antialias_pass};
}

}  // namespace

std::optional<Image> ProgressiveRender::coarse_pass(const PreparedJob& job, int factor,
                                                    const std::function<bool()>& stop_wanted) const {
  const int width = std::max(1, job.width() / factor), height = std::max(1, job.height() / factor);
  const Camera camera(job.description().camera, width, height);
  RenderSettings settings = settings_;
  settings.antialias_samples = 0;
  ImageRender coarse(camera, width, height, job.integrator(), settings);
  ProgressEstimate estimate(width, height, settings);
  const auto start = Clock::now();
  const PassMonitor monitor(coarse, stop_wanted, [&] {
    page_.show_progress(frame_, progress_of(coarse, estimate, start, FramePhase::kCoarse));
  });
  if (!coarse.run()) return std::nullopt;
  return coarse.image();
}

bool ProgressiveRender::operator()(const PreparedJob& job, ImageRender& render) const {
  const auto stop_wanted = [this] { return interrupted() || stale_(); };
  const auto stopped = [&] {
    if (interrupted()) return false;
    throw RenderSuperseded{};
  };

  // Compute the coarse passes: the same view, world and integrator at a fraction of the size.
  page_.show_progress(frame_, {FramePhase::kCoarse});
  Image underlay;
  for (const int factor : kCoarseFactors) {
    const auto coarse = coarse_pass(job, factor, stop_wanted);
    if (!coarse) return stopped();
    underlay = enlarge(*coarse, job.width(), job.height());
    page_.show_image(frame_, underlay);
  }

  // Compute the image itself, its finished tiles shown over the last coarse pass.
  page_.show_progress(frame_, {FramePhase::kFirstPass});
  bool finished = false;
  {
    ProgressEstimate estimate(job.width(), job.height(), settings_);
    const auto start = Clock::now();
    uint64_t shown = 0;  // samples done in the image last shown
    const PassMonitor monitor(render, stop_wanted, [&] {
      page_.show_progress(frame_, progress_of(render, estimate, start, FramePhase::kFirstPass));
      const uint64_t done = render.progress().done;
      if (done == shown) return;
      shown = done;
      const std::vector<uint8_t> tiles = render.finished_tiles();  // before the snapshot: see finished_tiles()
      page_.show_image(frame_, overlay_finished_tiles(underlay, render.snapshot(), tiles, render.layout()));
    });
    finished = render.run();
  }
  if (!finished) return stopped();
  page_.show_image(frame_, render.image());
  return true;
}

}  // namespace mjray
