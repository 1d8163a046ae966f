// mjray: read the command line → run the scene script → check every output → for each
// gr.render job --frames selects: prepare (flatten, build, camera, integrator) → render →
// write → with --video, encode the frames.

#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli.h"
#include "mjray/core/error.h"
#include "mjray/core/large_page_heap.h"
#include "interrupts.h"
#include "job_statistics.h"
#include "local_render.h"
#include "video_encoder.h"
#include "watch/watch_session.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/job_view.h"
#include "mjray/lua/scene_loader.h"

namespace {

using namespace mjray;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// --video: the frames' files and sizes, checked before anything renders.
void check_video(const CommandLine& cl, const SceneDescription& scene, const std::vector<size_t>& frames,
                 const JobOptions& options) {
  std::vector<std::filesystem::path> files;
  std::vector<std::string> sizes;
  for (const size_t i : frames) {
    files.push_back(output_path(scene, i, options.outputs));
    const PixelRect crop = options.render.crop.value_or(PixelRect{});
    const ImageSize size = job_image_size(scene.jobs[i], options.view);
    sizes.push_back(options.render.crop ? std::to_string(crop.x1 - crop.x0) + "x" + std::to_string(crop.y1 - crop.y0)
                                        : std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  check_not_an_input(scene, *cl.video, {cl.scene.string(), 0}, "--video");
  check_video_output(*cl.video, files, sizes);
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
  for (const auto& w : cl.warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());

  // --watch: the live preview's loop renders, again after every change (apps/mjray/watch/).
  if (cl.watch) {
    try {
      return run_watch_session(cl);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "mjray: error: %s\n", error_message(e).c_str());
      return 1;
    }
  }

  // Ctrl-C ends the run at once until a render has something to keep (interrupts.h).
  install_interrupt_handlers();
  try {
    const auto start = std::chrono::steady_clock::now();
    const SceneDescription scene = [&] {
      const ExitOnInterrupt exit_on_interrupt;
      return load_scene(cl.scene, cl.load);
    }();
    const double parse_seconds = seconds_since(start);
    for (const auto& w : scene.warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
    if (!cl.quiet)
      for (const auto& n : scene.notes) std::fprintf(stderr, "mjray: note: %s\n", n.c_str());
    const JobOptions options = job_options(cl);
    // Before rendering, so that a bad output costs no render time.
    const std::vector<size_t> frames = selected_jobs(scene, options.frames);
    check_job_views(scene, frames, options);
    for (const auto& w : check_outputs(scene, options.outputs, frames)) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
    if (cl.video) check_video(cl, scene, frames, options);
    if (cl.stats_json) check_statistics_output(scene, *cl.stats_json);
    const bool animation = scene.jobs.size() > 1;
    std::vector<JobStatistics> statistics;
    const JobFingerprints fingerprints(scene, options);
    for (const size_t i : frames) {
      LocalRunOptions run;
      run.quiet = cl.quiet;
      run.print_stats = cl.print_stats;
      run.resume = cl.resume;
      if (animation) run.frame = "frame " + std::to_string(i + 1) + "/" + std::to_string(scene.jobs.size());
      if (auto stats = render_job_locally(scene, i, options, fingerprints, run, parse_seconds)) statistics.push_back(*stats);
      if (cl.stats_json) write_statistics_json(statistics, *cl.stats_json);
    }
    if (animation && (cl.print_stats || !cl.quiet))
      std::fputs(animation_summary(statistics, frames.size() - statistics.size(), cl.print_stats).c_str(), stderr);
    if (cl.video) {
      std::vector<std::filesystem::path> files;
      for (const size_t i : frames) files.push_back(output_path(scene, i, options.outputs));
      encode_video(files, *cl.video, cl.fps);
      if (!cl.quiet) std::fprintf(stderr, "mjray: wrote %s (%zu frames at %d fps)\n", cl.video->c_str(), files.size(), cl.fps);
    }
  } catch (const Interrupted&) {
    return 130;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mjray: error: %s\n", error_message(e).c_str());
    return 1;
  }
  return 0;
}
