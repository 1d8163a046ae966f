#pragma once
/// Renders one job as a user at a terminal expects: progress, incremental images, Ctrl-C
/// keeping the partial image and its state, --resume finishing it. The tiles run on this
/// process's threads or on any other TileExecutor a driver gives.

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "job_statistics.h"
#include "mjray/job/job_fingerprint.h"
#include "mjray/job/job_options.h"
#include "mjray/job/prepared_job.h"
#include "mjray/job/run_options.h"
#include "mjray/job/run_plan.h"
#include "mjray/render/render_checkpoint.h"
#include "mjray/render/tile_executor.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

class ImageRender;
class PreparedJob;

/// How the local driver reports and resumes.
struct LocalRunOptions {
  bool quiet = false;         ///< no progress and no "wrote FILE" line (warnings still print)
  bool print_stats = false;   ///< the statistics after each image, also when quiet
  /// Finish an interrupted run: resume from the image's state file when there is one, keep a
  /// complete image that records this job's fingerprint, render an absent one.
  bool resume = false;
  double snapshot_interval_seconds = 5;
  /// "frame 7/24" when the scene renders several images: shown with the progress, and the
  /// statistics shrink to one line (the caller prints their sum at the end).
  std::string frame;
  /// Runs the built job's render and returns whether it finished; empty = render.run(). The
  /// watch driver's adds a coarse preview and the live page, and throws to drop a stale render.
  std::function<bool(const PreparedJob& job, ImageRender& render)> run_render = nullptr;
  /// --time-limit: when the run must stop (none without it).
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

/// What the command line's reporting options ask of each job's render.
LocalRunOptions local_run_options(const ReportOptions& report);

/// Prints the plan's warnings and (unless quiet) its notes, each on a line of its own.
void print_plan_messages(const RunPlan& plan, bool quiet);

/// Prints "mjray: warning: TEXT" for each of `warnings`.
void print_warnings(const std::vector<std::string>& warnings);

/// Thrown when the user interrupted a render (the partial image and state are written);
/// the program exits 130.
struct Interrupted {};

/// Thrown when --time-limit stopped a render (the partial image and state are written): the
/// run renders nothing more and exits 0.
struct TimeLimitReached {};

/// Prepares and renders job `index` of `scene`, writes its image (recording the job's
/// fingerprint) and returns its statistics; nothing when --resume keeps the image. Throws
/// Interrupted, SceneError (also for a resume refused, saying what differs) or OutputError.
std::optional<JobStatistics> render_job_locally(const SceneDescription& scene, size_t index, const JobOptions& options,
                                                const JobFingerprints& fingerprints, const LocalRunOptions& run,
                                                double parse_seconds);

/// What is known of a prepared job before it renders: build time, primitives, accelerator.
JobStatistics prepared_job_statistics(const PreparedJob& job, double parse_seconds);

/// How a prepared job's render ended: its figures, and the image, or the state to resume from.
struct RenderOutcome {
  bool finished = false;
  RenderStats stats;
  Image image;                  ///< when finished
  RenderCheckpoint checkpoint;  ///< when stopped (without its fingerprint)
};

/// Renders a prepared job, continuing from `state` when given, on the executor that `executor`
/// makes (this process's threads when empty); `run` runs the render (render.run(), with what a
/// driver adds around it) and returns whether it finished. What every driver's render shares.
RenderOutcome render_job(const PreparedJob& job, const std::optional<RenderCheckpoint>& state, const RenderSettings& settings,
                         const std::function<bool(ImageRender& render)>& run, const TileExecutorFactory& executor = {});

/// Renders a prepared job, continuing from `state` when given, on the executor that
/// `executor` makes (this process's threads when empty), watched and interruptible; writes
/// the finished image, or the partial one and its state and then throws Interrupted. Adds the
/// render's figures to `stats`. Throws OutputError.
void render_prepared_job(const PreparedJob& job, const std::optional<RenderCheckpoint>& state, const JobOptions& options,
                         const std::string& fingerprint, const LocalRunOptions& run, JobStatistics& stats,
                         const TileExecutorFactory& executor = {});

/// Prints the statistics (--stats) or the "wrote FILE" line (unless quiet).
void report_written(const JobStatistics& stats, const LocalRunOptions& run);

}  // namespace mjray
