// mjray: read the command line → run the scene script → plan the run (the jobs --frames
// selects, every check of outputs and views) → for each job: prepare (flatten, build, camera,
// integrator) → render → write → with --video, encode the frames.

#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli.h"
#include "mjray/core/seconds_since.h"
#include "interrupts.h"
#include "job_statistics.h"
#include "statistics_json.h"
#include "local_render.h"
#include "watch/watch_session.h"
#include "mjray/core/error.h"
#include "mjray/core/large_page_heap.h"
#include "mjray/io/video_encoder.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/run_plan.h"
#include "mjray/lua/scene_loader.h"

namespace {

using namespace mjray;

/// Loads the scene and renders every job its plan selects in this process.
void render_locally(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SceneDescription scene = [&] {
    const ExitOnInterrupt exit_on_interrupt;  // nothing to keep yet: Ctrl-C ends at once
    return load_scene(options.scene, options.load);
  }();
  const double parse_seconds = seconds_since(start);
  const RunPlan plan = plan_run(scene, options);
  print_plan_messages(plan, options.report.quiet);

  // Compute each image, then what the frames add up to and the video.
  const ReportOptions& report = options.report;
  const bool animation = scene.jobs.size() > 1;
  std::optional<std::chrono::steady_clock::time_point> deadline;
  if (report.time_limit_seconds > 0)
    deadline = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(report.time_limit_seconds));
  std::vector<JobStatistics> statistics;
  size_t jobs_begun = 0;
  try {
    for (const size_t i : plan.jobs) {
      LocalRunOptions run = local_run_options(report);
      run.deadline = deadline;
      if (animation) run.frame = "frame " + std::to_string(i + 1) + "/" + std::to_string(scene.jobs.size());
      if (deadline && std::chrono::steady_clock::now() >= *deadline) throw TimeLimitReached{};
      ++jobs_begun;
      if (auto stats = render_job_locally(scene, i, options.job, plan.fingerprints, run, parse_seconds))
        statistics.push_back(*stats);
      if (report.stats_json) write_statistics_json(statistics, *report.stats_json);
    }
  } catch (const TimeLimitReached&) {
    // What is done stays; the rest waits for --resume.
    if (!report.quiet && jobs_begun < plan.jobs.size())
      std::fprintf(stderr, "mjray: time limit: %zu of %zu images not begun%s\n", plan.jobs.size() - jobs_begun,
                   plan.jobs.size(), report.video ? "; no video" : "");
    return;
  }
  if (animation && (report.print_stats || !report.quiet))
    std::fputs(animation_summary(statistics, plan.jobs.size() - statistics.size(), report.print_stats).c_str(), stderr);
  if (report.video) {
    std::vector<std::filesystem::path> files;
    for (const size_t i : plan.jobs) files.push_back(output_path(scene, i, options.job.outputs));
    encode_video(files, *report.video, report.fps);
    if (!report.quiet)
      std::fprintf(stderr, "mjray: wrote %s (%zu frames at %d fps)\n", report.video->c_str(), files.size(), report.fps);
  }
}

}  // namespace

int main(int argc, char** argv) {
  // Page faults would be a quarter of a small render's time (core/large_page_heap.h).
  back_heap_with_large_pages(size_t(256) << 20);
  // A file-size limit (ulimit -f) then fails writes with EFBIG, reported like a full disk,
  // instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  CommandLine cl;
  try {
    cl = parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& e) {
    std::fprintf(stderr, "mjray: %s\n(run 'mjray --help' for the options)\n", e.what());
    return 2;
  }
  if (cl.show_help) {
    std::fputs(usage_text().c_str(), stdout);
    return 0;
  }
  if (cl.show_version) {
    std::printf("mjray %s\n", MJRAY_VERSION);
    return 0;
  }
  print_warnings(cl.warnings);
  try {
    // --watch: the live preview's loop renders, again after every change (apps/mjray/watch/).
    if (cl.run.report.watch) return run_watch_session(cl.run);
    // Ctrl-C ends the run at once until a render has something to keep (interrupts.h).
    install_interrupt_handlers();
    render_locally(cl.run);
  } catch (const Interrupted&) {
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mjray: error: %s\n", error_message(e).c_str());
    return 1;
  }
  return 0;
}
