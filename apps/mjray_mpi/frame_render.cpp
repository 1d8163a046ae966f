#include "frame_render.h"

#include <algorithm>

#include "local_render.h"
#include "mjray/core/error.h"
#include "mjray/job/prepared_job.h"
#include "mjray/render/tile_layout.h"

namespace mjray {

namespace {

size_t count_done(const std::vector<uint8_t>& flags) { return size_t(std::count(flags.begin(), flags.end(), uint8_t(1))); }

}  // namespace

FrameOutcome FrameRender::run(const SceneDescription& scene, size_t index, const JobOptions& options,
                              const std::optional<RenderCheckpoint>& state, const RankStatistics& rank) {
  FrameOutcome outcome;
  try {
    const PreparedJob job(scene, index, options);
    JobStatistics stats = prepared_job_statistics(job, rank.seconds_load);
    // Compute the image unless a stop came first.
    RenderOutcome rendered = render_job(job, state, options.render, [&](ImageRender& render) {
      std::unique_lock lock(mutex_);
      if (stop_) return false;
      current_ = &render;
      lock.unlock();
      const bool finished = render.run();
      lock.lock();
      current_ = nullptr;
      return finished;
    });
    stats.render = rendered.stats;
    stats.seconds_render = stats.render.seconds;
    stats.peak_rss_bytes = peak_rss_bytes();

    // Compute what this rank did, and the image or the state to resume from.
    FrameDoneMessage& done = outcome.done;
    done.job = uint32_t(index);
    done.finished = rendered.finished;
    RankStatistics r = rank;
    r.threads = stats.render.threads;
    r.seconds_build = job.build_seconds();
    r.seconds_rendering = stats.render.seconds * stats.render.threads;
    r.pixels_supersampled = stats.render.pixels_supersampled;
    r.rays = stats.render.rays.total();
    const size_t done_before = state ? count_done(state->tile_done) : 0;
    if (rendered.finished) {
      done.image = std::move(rendered.image);
      r.tiles = size_t(TileLayout{job.width(), job.height(), std::max(1, options.render.tile_size)}.count()) - done_before;
    } else {
      r.tiles = count_done(rendered.checkpoint.tile_done) - done_before;
      done.checkpoint = encode_checkpoint(rendered.checkpoint);
    }
    stats.ranks = {r};
    done.stats = std::move(stats);
  } catch (const std::exception& e) {
    outcome.error = error_message(e);
  }
  return outcome;
}

void FrameRender::request_stop() {
  std::lock_guard lock(mutex_);
  stop_ = true;
  if (current_) current_->request_stop();
}

}  // namespace mjray
