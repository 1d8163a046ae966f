// mjray: load the scene script → flatten each render job → build the accelerator → render →
// write the image.

#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "cli.h"
#include "job_statistics.h"
#include "render_watcher.h"
#include "mjray/accel/make_accelerator.h"
#include "mjray/camera/pinhole_camera.h"
#include "mjray/integrator/whitted_integrator.h"
#include "mjray/io/image_writer.h"
#include "mjray/lua/scene_loader.h"
#include "mjray/render/render_checkpoint.h"
#include "mjray/render/renderer.h"
#include "mjray/scene/flatten.h"

namespace {

using namespace mjray;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Where a job's image goes: --output, --outdir, or the script's own folder.
std::filesystem::path output_path(const CommandLine& cl, const RenderJob& job) {
  if (cl.output) return *cl.output;
  if (cl.outdir) return *cl.outdir / job.output.filename();
  if (job.output.is_absolute()) return job.output;
  return std::filesystem::absolute(cl.scene).parent_path() / job.output;
}

/// The accelerator the flags ask for: --accel wins, then -o, then -g (0 = none), else bvh.
AcceleratorOptions accelerator_options(const CommandLine& cl) {
  AcceleratorOptions options;
  options.threads = cl.threads;
  if (cl.optimal_grid) {
    options.kind = "grid";
    options.grid_size = 0;
  } else if (cl.grid_size) {
    options.kind = *cl.grid_size == 0 ? "none" : "grid";
    options.grid_size = *cl.grid_size;
  }
  if (!cl.accel.empty()) options.kind = cl.accel;
  return options;
}

/// Thrown when the user interrupted a render; main exits 130.
struct Interrupted {};

/// A hash of everything that decides a job's pixels: the script's text, which job, and the
/// options that change the image, so --resume refuses a state saved by something else.
uint64_t render_fingerprint(const CommandLine& cl, size_t job_index, const RenderSettings& settings) {
  std::ifstream script(cl.scene, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(script)), {});
  char options[256];
  std::snprintf(options, sizeof options, "|job=%zu r=%d f=%d s=%d a=%d t=%.9g seed=%llu order=%d tile=%d", job_index,
                cl.max_reflection_depth, cl.max_refraction_depth, cl.area_light_samples, cl.antialias_samples,
                double(cl.antialias_threshold), (unsigned long long)cl.seed, int(cl.load.transform_order),
                settings.tile_size);
  text += options;
  uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a
  for (const unsigned char c : text) hash = (hash ^ c) * 0x100000001b3ULL;
  return hash;
}

JobStatistics render_job(const CommandLine& cl, const RenderJob& job, size_t job_index, double parse_seconds) {
  JobStatistics stats;
  stats.seconds_parse = parse_seconds;
  const auto path = output_path(cl, job);
  stats.image = path.string();
  const auto state_path = checkpoint_path(path);

  // Compute the flat world and its accelerator.
  auto start = Clock::now();
  std::vector<std::string> warnings;
  const World world = flatten(job, &warnings);
  for (const auto& w : warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
  const auto accel = make_accelerator(world.primitives, accelerator_options(cl));
  stats.seconds_build = seconds_since(start);
  stats.primitives = world.primitive_count();
  stats.accel = std::string(accel->name());

  // Compute the image, resuming from a saved state when asked.
  const PinholeCamera camera(job.camera, job.width, job.height);
  const WhittedIntegrator integrator(world, *accel, {cl.max_reflection_depth, cl.max_refraction_depth, cl.area_light_samples});
  RenderSettings settings;
  settings.threads = cl.threads;
  settings.seed = cl.seed;
  settings.antialias_samples = cl.antialias_samples;
  settings.antialias_threshold = cl.antialias_threshold;
  TileRender render(camera, job.width, job.height, integrator, settings);
  const uint64_t fingerprint = render_fingerprint(cl, job_index, settings);
  if (cl.resume) {
    RenderCheckpoint saved = read_checkpoint(state_path);
    if (saved.fingerprint != fingerprint)
      throw SceneError(state_path.string() + ": this resume state was saved by a different scene or different "
                       "options; render without --resume to start again");
    render.resume_from(saved);
  }
  const OutputGamma gamma = cl.srgb ? OutputGamma::kSrgb : OutputGamma::kLinear;
  bool finished = false;
  {
    RenderWatcher watcher(render, path, {cl.quiet, 5.0, gamma});
    finished = render.run();
    if (finished) watcher.finish();
  }
  stats.render = render.stats();
  stats.seconds_render = stats.render.seconds;

  if (!finished) {
    // Keep what is done: the partial image and the state to resume from.
    write_image(render.snapshot(), path, gamma);
    RenderCheckpoint checkpoint = render.checkpoint();
    checkpoint.fingerprint = fingerprint;
    write_checkpoint(checkpoint, state_path);
    std::fprintf(stderr, "mjray: interrupted: wrote the partial image %s and its state; run again with --resume to finish\n",
                 path.string().c_str());
    throw Interrupted{};
  }
  write_image(render.image(), path, gamma);
  std::error_code ignored;
  std::filesystem::remove(state_path, ignored);
  stats.peak_rss_bytes = peak_rss_bytes();
  if (!cl.quiet || cl.print_stats) std::fputs(summary_text(stats).c_str(), stderr);
  return stats;
}

}  // namespace

int main(int argc, char** argv) {
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

  try {
    const auto start = Clock::now();
    const SceneDescription scene = load_scene(cl.scene, cl.load);
    const double parse_seconds = seconds_since(start);
    for (const auto& w : scene.warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
    if (cl.output && scene.jobs.size() > 1)
      throw SceneError(cl.scene.string() + ": --output names one file but the scene renders " +
                       std::to_string(scene.jobs.size()) + " images; use --outdir");
    if (cl.outdir) {
      // Before rendering, so that a bad folder costs no render time.
      std::error_code ec;
      std::filesystem::create_directories(*cl.outdir, ec);
      if (ec) throw OutputError("cannot create the output folder '" + cl.outdir->string() + "': " + ec.message());
    }
    // Before rendering: no output may replace the script or a file it read.
    for (const RenderJob& job : scene.jobs) check_not_an_input(scene, output_path(cl, job), job.where, "gr.render");
    if (cl.stats_json) check_not_an_input(scene, *cl.stats_json, {cl.scene.string(), 0}, "--stats-json");
    install_interrupt_handlers();
    std::vector<JobStatistics> statistics;
    for (size_t i = 0; i < scene.jobs.size(); ++i) {
      // With --resume, jobs whose image is complete (no state file beside it) are done.
      const auto path = output_path(cl, scene.jobs[i]);
      if (cl.resume && !std::filesystem::exists(checkpoint_path(path)) && std::filesystem::exists(path)) continue;
      statistics.push_back(render_job(cl, scene.jobs[i], i, parse_seconds));
      if (cl.stats_json) write_statistics_json(statistics, *cl.stats_json);
    }
  } catch (const Interrupted&) {
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mjray: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
