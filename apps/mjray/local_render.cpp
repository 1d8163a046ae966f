#include "local_render.h"

#include <cstdio>
#include <system_error>

#include "render_watcher.h"
#include "mjray/core/error.h"
#include "mjray/io/image_codec.h"
#include "mjray/job/job_fingerprint.h"
#include "mjray/job/prepared_job.h"
#include "mjray/render/image_render.h"
#include "mjray/render/render_checkpoint.h"

namespace mjray {

JobStatistics render_job_locally(const SceneDescription& scene, size_t index, const JobOptions& options,
                                 const LocalRunOptions& run, double parse_seconds) {
  // Compute the flat world, its accelerator, the camera and the integrator.
  const PreparedJob job(scene, index, options);
  for (const auto& w : job.warnings()) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
  JobStatistics stats;
  stats.image = job.output().string();
  stats.seconds_parse = parse_seconds;
  stats.seconds_build = job.build_seconds();
  stats.primitives = job.world().primitive_count();
  stats.accel = std::string(job.accelerator().name());
  if (job.photon_statistics()) stats.photons = *job.photon_statistics();

  // Compute the image, resuming from a saved state when asked.
  ImageRender render(job.camera(), job.width(), job.height(), job.integrator(), options.render);
  const auto state_path = checkpoint_path(job.output());
  if (run.resume) {
    const RenderCheckpoint saved = read_checkpoint(state_path);
    const std::string now = job_fingerprint(scene, index, options);
    if (saved.fingerprint != now)
      throw SceneError(state_path.string() + ": this resume state was saved by a different scene or different options (" +
                       fingerprint_difference(saved.fingerprint, now) + "); render without --resume to start again");
    render.resume_from(saved);
  }
  bool finished = false;
  {
    RenderWatcher watcher(render, job.output(), {run.quiet, run.snapshot_interval_seconds, options.outputs.encoding});
    finished = render.run();
    if (finished) watcher.finish();
  }
  stats.render = render.stats();
  stats.seconds_render = stats.render.seconds;

  if (!finished) {
    // Keep what is done: the partial image and the state to resume from.
    write_image(render.snapshot(), job.output(), options.outputs.encoding);
    RenderCheckpoint checkpoint = render.checkpoint();
    checkpoint.fingerprint = job_fingerprint(scene, index, options);
    write_checkpoint(checkpoint, state_path);
    std::fprintf(stderr, "mjray: interrupted: wrote the partial image %s and its state; run again with --resume to finish\n",
                 job.output().string().c_str());
    throw Interrupted{};
  }
  write_image(render.image(), job.output(), options.outputs.encoding);
  std::error_code ignored;
  std::filesystem::remove(state_path, ignored);
  stats.peak_rss_bytes = peak_rss_bytes();
  if (!run.quiet || run.print_stats) std::fputs(summary_text(stats).c_str(), stderr);
  return stats;
}

}  // namespace mjray
