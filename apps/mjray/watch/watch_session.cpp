#include "watch_session.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <vector>

#include "file_watcher.h"
#include "interrupts.h"
#include "job_statistics.h"
#include "statistics_json.h"
#include "live_state.h"
#include "local_render.h"
#include "mjray/core/seconds_since.h"
#include "preview_server.h"
#include "progressive_render.h"
#include "mjray/core/error.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/run_plan.h"
#include "mjray/lua/scene_loader.h"

namespace mjray {

namespace {

using std::chrono::milliseconds;

/// How often the files are looked at while nothing renders.
constexpr milliseconds kPollInterval{100};
/// How long the files must stay unchanged after a save before the render starts again.
constexpr milliseconds kQuietPeriod{200};

/// How one round of the loop ended.
enum class RoundEnd { kFinished, kFailed, kStale, kInterrupted };

/// Runs the script with Ctrl-C ending the process: a script stuck in a loop can then still be
/// ended, and nothing is lost (nothing renders while it runs).
SceneDescription load_interruptibly(const RunOptions& options, std::vector<std::filesystem::path>& inputs_read) {
  const ExitOnInterrupt exit_on_interrupt;
  SceneLoadOptions load = options.load;
  load.inputs_read = &inputs_read;
  return load_scene(options.scene, load);
}

/// One round: run the script, then render and write each frame as `mjray scene.lua` would,
/// each progressively on the page. The files to watch are updated once the script ran.
RoundEnd render_round(const RunOptions& options, LiveState& page, FileWatcher& files) {
  page.begin_render();
  std::vector<std::filesystem::path> read;  // what the script read, also when it failed
  try {
    const auto start = std::chrono::steady_clock::now();
    const SceneDescription scene = load_interruptibly(options, read);
    const double parse_seconds = seconds_since(start);
    std::vector<std::filesystem::path> watched = {options.scene};
    watched.insert(watched.end(), scene.inputs.begin(), scene.inputs.end());
    files.watch(watched);
    const RunPlan plan = plan_run(scene, options);
    print_plan_messages(plan, options.report.quiet);

    std::vector<FrameDescription> frames;
    for (const size_t i : plan.jobs)
      frames.push_back({output_path(scene, i, options.job.outputs).filename().string(), scene.jobs[i].width,
                        scene.jobs[i].height});
    page.set_frames(frames);

    // Compute each frame as the local driver does, with the coarse pass and the page added.
    std::vector<JobStatistics> statistics;
    LocalRunOptions run = local_run_options(options.report);
    run.snapshot_interval_seconds = 0;  // the page shows the progress; the file gets the result
    for (size_t frame = 0; frame < plan.jobs.size(); ++frame) {
      run.run_render = ProgressiveRender(page, frame, options.job.render, [&files] { return files.changed(); });
      const auto stats = render_job_locally(scene, plan.jobs[frame], options.job, plan.fingerprints, run, parse_seconds);
      page.finish_frame(frame, *stats);
      statistics.push_back(*stats);
      if (options.report.stats_json) write_statistics_json(statistics, *options.report.stats_json);
    }
    page.finish_render();
    return RoundEnd::kFinished;
  } catch (const RenderSuperseded&) {
    return RoundEnd::kStale;
  } catch (const Interrupted&) {
    return RoundEnd::kInterrupted;
  } catch (const std::exception& e) {
    // A script or output error: the page shows it and keeps the last good images. A module
    // or file the script read before it failed is watched too, so that fixing it is seen.
    std::vector<std::filesystem::path> watched = {options.scene};
    watched.insert(watched.end(), read.begin(), read.end());
    files.watch(watched);
    std::fprintf(stderr, "mjray: error: %s\n", error_message(e).c_str());
    page.fail(error_message(e));
    return RoundEnd::kFailed;
  }
}

}  // namespace

int run_watch_session(const RunOptions& options) {
  const ReportOptions& report = options.report;
  LiveState page(options.scene.filename().string(), options.job.outputs.encoding);
  const std::string address = report.listen.value_or("127.0.0.1");
  const PreviewServer server(page, address, report.port.value_or(kDefaultWatchPort));
  if (!is_loopback_address(address))
    print_warnings({"--listen " + address + ": anyone who can reach this machine on port " + std::to_string(server.port()) +
                    " can see the renders"});
  std::fprintf(stderr, "mjray: live preview of %s at %s (Ctrl-C to stop)\n", options.scene.string().c_str(),
               server.url().c_str());

  install_interrupt_handlers();
  FileWatcher files;
  files.watch({options.scene});
  for (;;) {
    files.accept();
    const RoundEnd end = render_round(options, page, files);
    if (end == RoundEnd::kInterrupted) return 130;
    if (end != RoundEnd::kStale && !files.wait_for_change(kPollInterval, interrupted)) return 0;
    if (!report.quiet) std::fprintf(stderr, "mjray: the scene changed; rendering again\n");
    if (!files.settle(kQuietPeriod, interrupted)) return 0;
  }
}

}  // namespace mjray
