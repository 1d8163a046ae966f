#include "local_render.h"

#include <cstdio>

#include "interrupts.h"
#include "job_images.h"
#include "render_watcher.h"
#include "mjray/job/job_outputs.h"
#include "mjray/render/image_render.h"

namespace mjray {

LocalRunOptions local_run_options(const ReportOptions& report) {
  LocalRunOptions run;
  run.quiet = report.quiet;
  run.print_stats = report.print_stats;
  run.resume = report.resume;
  return run;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
}

void print_plan_messages(const RunPlan& plan, bool quiet) {
  print_warnings(plan.warnings);
  if (!quiet)
    for (const std::string& n : plan.notes) std::fprintf(stderr, "mjray: note: %s\n", n.c_str());
}

std::optional<JobStatistics> render_job_locally(const SceneDescription& scene, size_t index, const JobOptions& options,
                                                const JobFingerprints& fingerprints, const LocalRunOptions& run,
                                                double parse_seconds) {
  // Decide what a resume keeps before building anything.
  const auto image_path = output_path(scene, index, options.outputs);
  const std::string fingerprint = fingerprints.of(index);
  ResumePlan plan = plan_resume(image_path, fingerprint, run.resume);
  if (plan.keep) {
    if (!run.quiet) std::fprintf(stderr, "mjray: kept %s (complete)\n", image_path.string().c_str());
    return std::nullopt;
  }

  // Compute the flat world, its accelerator, the camera and the integrator; then the image.
  // Preparing cannot stop half-way and has nothing to keep, so Ctrl-C ends it at once.
  const PreparedJob job = [&] {
    const ExitOnInterrupt exit_on_interrupt;
    return PreparedJob(scene, index, options);
  }();
  print_warnings(job.warnings());
  JobStatistics stats = prepared_job_statistics(job, parse_seconds);
  render_prepared_job(job, plan.state, options, fingerprint, run, stats);
  report_written(stats, run);
  return stats;
}

JobStatistics prepared_job_statistics(const PreparedJob& job, double parse_seconds) {
  JobStatistics stats;
  stats.image = job.output().string();
  stats.seconds_parse = parse_seconds;
  stats.seconds_build = job.build_seconds();
  stats.primitives = job.world().primitive_count();
  stats.accel = std::string(job.accelerator().name());
  stats.grid_resolution = job.grid_resolution();
  if (job.photon_statistics()) stats.photons = *job.photon_statistics();
  return stats;
}

RenderOutcome render_job(const PreparedJob& job, const std::optional<RenderCheckpoint>& state, const RenderSettings& settings,
                         const std::function<bool(ImageRender& render)>& run, const TileExecutorFactory& executor) {
  ImageRender render(job.camera(), job.width(), job.height(), job.integrator(), settings, executor);
  if (state) render.resume_from(*state);
  RenderOutcome outcome;
  outcome.finished = run(render);
  outcome.stats = render.stats();
  if (outcome.finished) outcome.image = render.image();
  else outcome.checkpoint = render.checkpoint();
  return outcome;
}

void render_prepared_job(const PreparedJob& job, const std::optional<RenderCheckpoint>& state, const JobOptions& options,
                         const std::string& fingerprint, const LocalRunOptions& run, JobStatistics& stats,
                         const TileExecutorFactory& executor) {
  // Compute the image, watched (progress, snapshots, Ctrl-C, --time-limit), resuming from the saved state.
  bool timed_out = false;
  RenderOutcome outcome = render_job(job, state, options.render, [&](ImageRender& render) {
    const PixelRect& traced = render.region();
    RenderWatcher watcher(render, job.output(),
                          {run.quiet, run.snapshot_interval_seconds, options.outputs.encoding, options.render,
                           traced.x1 - traced.x0, traced.y1 - traced.y0, run.frame, run.deadline});
    const bool finished = run.run_render ? run.run_render(job, render) : render.run();
    if (finished) watcher.finish();
    timed_out = watcher.timed_out();
    return finished;
  }, executor);
  stats.render = outcome.stats;
  stats.seconds_render = stats.render.seconds;

  if (!outcome.finished) {
    // Keep what is done: the partial image and the state to resume from.
    outcome.checkpoint.fingerprint = fingerprint;
    const StopReason reason = timed_out ? StopReason::kTimeLimit : StopReason::kInterrupted;
    const std::string reached =
        progress_reached(outcome.checkpoint, options.render.targets_noise(), pixel_pass_count(options.render));
    write_stopped_image(outcome.checkpoint, job.output(), options.outputs.encoding, reason, reached);
    if (timed_out) throw TimeLimitReached{};
    throw Interrupted{};
  }
  EncodeOptions encoding = options.outputs.encoding;
  encoding.render_seconds = stats.seconds_render;
  write_finished_image(outcome.image, job.output(), encoding, fingerprint);
  stats.peak_rss_bytes = peak_rss_bytes();
}

void report_written(const JobStatistics& stats, const LocalRunOptions& run) {
  if (!run.frame.empty() && (run.print_stats || !run.quiet)) std::fputs(frame_line(stats, run.frame, run.print_stats).c_str(), stderr);
  else if (run.print_stats) std::fputs(summary_text(stats).c_str(), stderr);
  else if (!run.quiet) std::fprintf(stderr, "mjray: wrote %s\n", stats.image.c_str());
}

}  // namespace mjray
