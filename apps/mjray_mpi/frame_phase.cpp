#include "frame_phase.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <future>

#include "frame_render.h"
#include "interrupts.h"
#include "messages.h"
#include "rank_failed.h"
#include "mjray/job/job_outputs.h"

namespace mjray {

namespace {

/// After an interrupt, how long frames still out on other ranks are waited for.
constexpr double kStopGraceSeconds = 0.4;
/// Seconds between looks for messages and for rank 0's own frame.
constexpr double kLookInterval = 0.0002;

/// Rank 0's own frames, rendered on a thread of their own while rank 0 coordinates.
class LocalFrames {
 public:
  explicit LocalFrames(const RunSetup& setup) : setup_(setup) {}
  ~LocalFrames() { render_.request_stop(); }  // the future then waits for the frame to stop

  bool busy() const { return outcome_.valid(); }
  void start(size_t job, const std::optional<RenderCheckpoint>& state) {
    outcome_ = std::async(std::launch::async, [this, job, &state] {
      return render_.run(setup_.scene, job, setup_.options, state, setup_.ranks[0]);
    });
  }
  /// The frame's outcome once it is done.
  std::optional<FrameOutcome> take() {
    if (!busy() || outcome_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    return outcome_.get();
  }
  void stop() { render_.request_stop(); }

 private:
  const RunSetup& setup_;
  FrameRender render_;
  std::future<FrameOutcome> outcome_;
};

/// Writes a frame that came back: the finished image, or the partial one and its state.
void write_frame(const RunSetup& setup, FrameDoneMessage done, StatisticsLog& log) {
  const auto path = output_path(setup.scene, done.job, setup.options.outputs);
  const std::string fingerprint = setup.plan.fingerprints.of(done.job);
  if (!done.finished) {
    RenderCheckpoint checkpoint = decode_checkpoint(done.checkpoint, path);
    checkpoint.fingerprint = fingerprint;
    const RenderSettings& render = setup.options.render;
    write_stopped_image(checkpoint, path, setup.options.outputs.encoding, StopReason::kInterrupted,
                        progress_reached(checkpoint, render.targets_noise(), pixel_pass_count(render)));
    return;
  }
  write_finished_image(done.image, path, setup.options.outputs.encoding, fingerprint);
  done.stats.image = path.string();
  report_written(done.stats, setup.run);
  log.add(done.job, done.stats);
}

}  // namespace

void render_frames(MpiWorld& world, const RunSetup& setup, const std::vector<ResumePlan>& plans,
                   const std::vector<size_t>& jobs, StatisticsLog& log) {
  using Clock = std::chrono::steady_clock;
  std::deque<size_t> queue(jobs.begin(), jobs.end());
  std::vector<bool> busy(size_t(world.size()), false);  // remote ranks with a frame
  LocalFrames local(setup);
  std::optional<Clock::time_point> stopped_at;
  while (true) {
    // On an interrupt, nothing more goes out and every frame under way is stopped.
    if (interrupted() && !stopped_at) {
      stopped_at = Clock::now();
      queue.clear();
      for (int k = 1; k < world.size(); ++k)
        if (busy[size_t(k)]) world.send(k, encode(MessageType::kStopFrame));
      local.stop();
    }
    // Hand the next frames to the ranks that are free, rank 0 last.
    for (int k = 1; k < world.size() && !queue.empty(); ++k) {
      if (busy[size_t(k)]) continue;
      const size_t job = queue.front();
      queue.pop_front();
      world.send(k, encode(FrameJobMessage{uint32_t(job), plans[job].state ? encode_checkpoint(*plans[job].state) : ""}));
      busy[size_t(k)] = true;
    }
    if (!local.busy() && !queue.empty()) {
      local.start(queue.front(), plans[queue.front()].state);
      queue.pop_front();
    }
    if (!local.busy() && std::find(busy.begin(), busy.end(), true) == busy.end()) break;
    if (stopped_at && std::chrono::duration<double>(Clock::now() - *stopped_at).count() > kStopGraceSeconds) break;

    // Write what came back.
    if (auto outcome = local.take()) {
      if (!outcome->error.empty()) throw std::runtime_error(outcome->error);
      write_frame(setup, std::move(outcome->done), log);
    }
    if (auto message = world.wait(kLookInterval)) {
      const MessageType type = type_of(message->bytes);
      if (type == MessageType::kFailed) throw RankFailed(message->from, decode_failed(message->bytes).text);
      if (type != MessageType::kFrameDone) continue;
      busy[size_t(message->from)] = false;
      write_frame(setup, decode_frame_done(message->bytes), log);
    }
  }
  if (stopped_at) throw Interrupted{};
}

}  // namespace mjray
