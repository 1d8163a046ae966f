#include "worker.h"

#include <future>
#include <memory>
#include <optional>

#include "frame_render.h"
#include "messages.h"
#include "unit_pool.h"
#include "mjray/core/error.h"
#include "mjray/job/prepared_job.h"
#include "mjray/render/tile_render.h"

namespace mjray {

namespace {

/// Seconds a worker waits for its threads' results before looking for messages again.
constexpr double kLookInterval = 0.0002;

/// How a job leaves the worker: set, the exit code the process ends with; unset, it carries on
/// with the next message.
using ExitCode = std::optional<int>;

/// After a failure has been reported: wait for rank 0 to end the run.
int wait_for_finish(MpiWorld& world) {
  while (true)
    if (auto message = world.wait(1.0); message && type_of(message->bytes) == MessageType::kFinish) return 0;
}

/// A tile job: prepare it, say Ready, render the units as they come, report at its end.
ExitCode serve_tile_job(MpiWorld& world, const SceneDescription& scene, const JobOptions& options,
                    const TileJobMessage& request, const RankStatistics& rank) {
  const uint64_t bytes_before = world.bytes_sent();
  std::unique_ptr<PreparedJob> job;
  try {
    job = std::make_unique<PreparedJob>(scene, request.job, options);
  } catch (const std::exception& e) {
    world.send(0, encode(FailedMessage{error_message(e)}));
    return wait_for_finish(world);
  }
  const ImageSampler sampler(job->camera(), job->integrator(), job->width(), job->height(), options.render);
  const TileLayout layout{job->width(), job->height(), std::max(1, request.tile_size)};
  UnitPool pool(sampler, layout, resolve_thread_count(options.render.threads));
  world.send(0, encode(ReadyMessage{request.job, pool.threads(), job->build_seconds()}));
  while (true) {
    for (const ResultMessage& result : pool.take_results(kLookInterval)) world.send(0, encode(result));
    while (auto message = world.poll()) {
      switch (type_of(message->bytes)) {
        case MessageType::kUnits: {
          UnitsMessage units = decode_units(message->bytes);
          pool.add(units.phase, std::move(units.units));
          break;
        }
        case MessageType::kEndJob: {
          RankStatistics report = pool.done();
          report.rank = rank.rank;
          report.host = rank.host;
          report.seconds_load = rank.seconds_load;
          report.seconds_build = job->build_seconds();
          report.bytes_sent = world.bytes_sent() - bytes_before;
          report.bytes_sent += encode(report).size();
          world.send(0, encode(report));
          return std::nullopt;
        }
        case MessageType::kFinish:
          return 0;
        default:
          break;
      }
    }
  }
}

/// A frame job: render the whole job on this rank's threads, stopping when asked.
ExitCode render_frame_job(MpiWorld& world, const SceneDescription& scene, const JobOptions& options,
                      const FrameJobMessage& request, const RankStatistics& rank) {
  std::optional<RenderCheckpoint> state;
  if (!request.state.empty()) state = decode_checkpoint(request.state, "the resume state sent by rank 0");
  FrameRender frame;
  auto outcome = std::async(std::launch::async, [&] { return frame.run(scene, request.job, options, state, rank); });
  std::optional<int> finish;
  while (outcome.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    if (auto message = world.wait(kLookInterval)) {
      const MessageType type = type_of(message->bytes);
      if (type == MessageType::kStopFrame || type == MessageType::kFinish) frame.request_stop();
      if (type == MessageType::kFinish) finish = 0;
    }
  }
  FrameOutcome result = outcome.get();
  if (finish) return finish;
  if (!result.error.empty()) {
    world.send(0, encode(FailedMessage{result.error}));
    return wait_for_finish(world);
  }
  result.done.stats.ranks.front().bytes_sent = encode(result.done).size();
  world.send(0, encode(result.done));
  return std::nullopt;
}

}  // namespace

int run_worker(MpiWorld& world, const SceneDescription& scene, const JobOptions& options, const RankStatistics& rank) {
  while (true) {
    const auto message = world.wait(1.0);
    if (!message) continue;
    ExitCode exit_code;
    switch (type_of(message->bytes)) {
      case MessageType::kTileJob:
        exit_code = serve_tile_job(world, scene, options, decode_tile_job(message->bytes), rank);
        break;
      case MessageType::kFrameJob:
        exit_code = render_frame_job(world, scene, options, decode_frame_job(message->bytes), rank);
        break;
      case MessageType::kFinish:
        return 0;
      default:
        break;  // left over from a job that ended early
    }
    if (exit_code) return *exit_code;
  }
}

}  // namespace mjray
