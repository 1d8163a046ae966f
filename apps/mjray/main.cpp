// mjray: read the command line → run the scene script → check every output → for each
// gr.render job: prepare (flatten, build, camera, integrator) → render → write.

#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli.h"
#include "job_statistics.h"
#include "local_render.h"
#include "render_watcher.h"
#include "watch/watch_session.h"
#include "mjray/job/job_outputs.h"
#include "mjray/lua/scene_loader.h"

namespace {

using namespace mjray;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
  for (const auto& w : cl.warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());

  // --watch: the live preview's loop renders, again after every change (apps/mjray/watch/).
  if (cl.watch) {
    try {
      return run_watch_session(cl);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "mjray: error: %s\n", e.what());
      return 1;
    }
  }

  try {
    const auto start = std::chrono::steady_clock::now();
    const SceneDescription scene = load_scene(cl.scene, cl.load);
    const double parse_seconds = seconds_since(start);
    for (const auto& w : scene.warnings) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
    if (!cl.quiet)
      for (const auto& n : scene.notes) std::fprintf(stderr, "mjray: note: %s\n", n.c_str());
    const JobOptions options = job_options(cl);
    // Before rendering, so that a bad output costs no render time.
    for (const auto& w : check_outputs(scene, options.outputs)) std::fprintf(stderr, "mjray: warning: %s\n", w.c_str());
    if (cl.stats_json) check_not_an_input(scene, *cl.stats_json, {cl.scene.string(), 0}, "--stats-json");
    install_interrupt_handlers();
    const LocalRunOptions run{cl.quiet, cl.print_stats, cl.resume};
    std::vector<JobStatistics> statistics;
    const JobFingerprints fingerprints(scene, options);
    for (size_t i = 0; i < scene.jobs.size(); ++i) {
      if (auto stats = render_job_locally(scene, i, options, fingerprints, run, parse_seconds)) statistics.push_back(*stats);
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
