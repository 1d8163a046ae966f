#include "local_render.h"

#include <cstdio>
#include <system_error>

#include "render_watcher.h"
#include "mjray/core/error.h"
#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/prepared_job.h"
#include "mjray/render/image_render.h"
#include "mjray/render/render_checkpoint.h"

namespace mjray {

namespace {

constexpr const char* kFingerprintKey = "mjray job";

/// The fingerprint a finished image records, or "" when it records none.
std::string recorded_fingerprint(const std::filesystem::path& image) {
  for (const auto& [key, value] : read_image_metadata(image))
    if (key == kFingerprintKey) return value;
  return "";
}

/// With --resume and a complete image (no state beside it): true when this scene and these
/// options made it; else throws SceneError saying what differs.
bool complete_image_matches(const std::filesystem::path& image, const std::string& fingerprint) {
  const std::string recorded = recorded_fingerprint(image);
  const std::string advice = "; render without --resume to start again, or remove the image to render just it again";
  if (recorded.empty())
    throw SceneError(image.string() + ": --resume keeps a complete image only when it records the scene and options "
                     "that made it, and this one records none (a partial image whose state file is gone, or not "
                     "written by mjray)" + advice);
  if (recorded != fingerprint)
    throw SceneError(image.string() + ": --resume keeps a complete image only when this scene and these options made "
                     "it, and a different scene or different options made this one (" +
                     fingerprint_difference(recorded, fingerprint) + ")" + advice);
  return true;
}

}  // namespace

std::optional<JobStatistics> render_job_locally(const SceneDescription& scene, size_t index, const JobOptions& options,
                                                const JobFingerprints& fingerprints, const LocalRunOptions& run,
                                                double parse_seconds) {
  // Decide what a resume keeps before building anything.
  const auto image_path = output_path(scene, index, options.outputs);
  const auto state_path = checkpoint_path(image_path);
  const std::string fingerprint = fingerprints.of(index);
  std::error_code ec;
  const bool has_state = run.resume && std::filesystem::exists(state_path, ec);
  if (run.resume && !has_state && std::filesystem::exists(image_path, ec) && complete_image_matches(image_path, fingerprint)) {
    if (!run.quiet) std::fprintf(stderr, "mjray: kept %s (complete)\n", image_path.string().c_str());
    return std::nullopt;
  }

  // Compute the flat world, its accelerator, the camera and the integrator.
  const PreparedJob job(scene, index, options);
  for (const auto& w : job.warnings()) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
  JobStatistics stats;
  stats.image = job.output().string();
  stats.seconds_parse = parse_seconds;
  stats.seconds_build = job.build_seconds();
  stats.primitives = job.world().primitive_count();
  stats.accel = std::string(job.accelerator().name());

  // Compute the image, resuming from a saved state when there is one.
  ImageRender render(job.camera(), job.width(), job.height(), job.integrator(), options.render);
  if (has_state) {
    const RenderCheckpoint saved = read_checkpoint(state_path);
    if (saved.fingerprint != fingerprint)
      throw SceneError(state_path.string() + ": this resume state was saved by a different scene or different options (" +
                       fingerprint_difference(saved.fingerprint, fingerprint) + "); render without --resume to start again");
    render.resume_from(saved);
  }
  bool finished = false;
  {
    RenderWatcher watcher(render, job.output(), {run.quiet, run.snapshot_interval_seconds, options.outputs.encoding,
                                                 options.render, job.width(), job.height()});
    finished = run.run_render ? run.run_render(job, render) : render.run();
    if (finished) watcher.finish();
  }
  stats.render = render.stats();
  stats.seconds_render = stats.render.seconds;

  if (!finished) {
    // Keep what is done: the partial image (recording no fingerprint) and the state to resume from.
    write_image(render.snapshot(), job.output(), options.outputs.encoding);
    RenderCheckpoint checkpoint = render.checkpoint();
    checkpoint.fingerprint = fingerprint;
    write_checkpoint(checkpoint, state_path);
    std::fprintf(stderr, "mjray: interrupted: wrote the partial image %s and its state; run again with --resume to finish\n",
                 job.output().string().c_str());
    throw Interrupted{};
  }
  // The finished image records what made it, so that a later --resume can keep it.
  EncodeOptions encoding = options.outputs.encoding;
  encoding.metadata.emplace_back(kFingerprintKey, fingerprint);
  write_image(render.image(), job.output(), encoding);
  std::filesystem::remove(state_path, ec);
  stats.peak_rss_bytes = peak_rss_bytes();
  if (run.print_stats) std::fputs(summary_text(stats).c_str(), stderr);
  else if (!run.quiet) std::fprintf(stderr, "mjray: wrote %s\n", stats.image.c_str());
  return stats;
}

}  // namespace mjray
