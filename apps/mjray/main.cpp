// mjray: load the scene script → flatten each render job → build the accelerator → render →
// write the image.

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli.h"
#include "mjray/accel/make_accelerator.h"
#include "mjray/camera/pinhole_camera.h"
#include "mjray/integrator/whitted_integrator.h"
#include "mjray/io/image_writer.h"
#include "mjray/lua/scene_loader.h"
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

void render_job(const CommandLine& cl, const RenderJob& job, double parse_seconds) {
  // Compute the flat world and its accelerator.
  auto start = Clock::now();
  std::vector<std::string> warnings;
  const World world = flatten(job, &warnings);
  for (const auto& w : warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
  const auto accel = make_accelerator(world, accelerator_options(cl));
  const double build_seconds = seconds_since(start);

  // Compute the image.
  const PinholeCamera camera(job.camera, job.width, job.height);
  const WhittedIntegrator integrator(world, *accel, {cl.max_reflection_depth, cl.max_refraction_depth, cl.area_light_samples});
  RenderSettings settings;
  settings.threads = cl.threads;
  settings.seed = cl.seed;
  settings.antialias_samples = cl.antialias_samples;
  settings.antialias_threshold = cl.antialias_threshold;
  RenderStats stats;
  const Image image = render_image(camera, job.width, job.height, integrator, settings, &stats);

  const auto path = output_path(cl, job);
  write_image(image, path, cl.srgb ? OutputGamma::kSrgb : OutputGamma::kLinear);

  if (!cl.quiet || cl.print_stats) {
    const double rays_per_second = stats.seconds > 0 ? double(stats.rays.total()) / stats.seconds : 0;
    std::fprintf(stderr,
                 "mjray: wrote %s (%dx%d) | parse %.3fs, build %.3fs (%s), render %.3fs on %d threads | "
                 "%u primitives | rays: %llu primary, %llu secondary, %llu shadow (%.2f M/s) | "
                 "%llu pixels supersampled\n",
                 path.string().c_str(), job.width, job.height, parse_seconds, build_seconds,
                 std::string(accel->name()).c_str(), stats.seconds, stats.threads, world.primitive_count(),
                 (unsigned long long)stats.rays.primary, (unsigned long long)stats.rays.secondary,
                 (unsigned long long)stats.rays.shadow, rays_per_second / 1e6,
                 (unsigned long long)stats.pixels_supersampled);
  }
}

}  // namespace

int main(int argc, char** argv) {
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
    for (const RenderJob& job : scene.jobs) render_job(cl, job, parse_seconds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mjray: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
