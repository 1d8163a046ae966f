// mjray-mpi: the mjray recipe over the ranks of an MPI job. Every rank reads the command line,
// runs the scene script and agrees with the others that all loaded the same scene; rank 0
// checks the outputs, then hands out whole frames or tiles and writes every image, while the
// other ranks render what they are given.

#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "agreement.h"
#include "mjray/core/seconds_since.h"
#include "cli.h"
#include "coordinator.h"
#include "interrupts.h"
#include "job_split.h"
#include "job_statistics.h"
#include "local_render.h"
#include "mpi_world.h"
#include "rank_failed.h"
#include "worker.h"
#include "mjray/core/available_memory.h"
#include "mjray/core/error.h"
#include "mjray/core/large_page_heap.h"
#include "mjray/io/video_encoder.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/run_plan.h"
#include "mjray/lua/scene_loader.h"

namespace {

using namespace mjray;

std::string usage(const std::vector<OptionSpec>& own) {
  return R"(usage: mpirun -np N mjray-mpi [options] scene.lua

Renders what mjray renders, over the N ranks of an MPI job, to the same bytes. Every rank runs
the scene script and builds each scene it renders; rank 0 hands out the work, renders too, and
writes every image, the resume state, the statistics and the video. Progress, warnings and
errors come from rank 0 only. -j N is the threads of each rank (default: the host's cores
shared among its ranks). --watch is mjray's alone. Options take their value attached or
apart and group as with getopt: -s4, -s 4, -og 5.

mpirun's --quiet leaves out its own banners when a run fails or is interrupted; as root it
needs --allow-run-as-root, and beyond the host's cores --oversubscribe.

)" + options_text(own, "mjray-mpi's own option");
}

void print_error(const std::string& message) { std::fprintf(stderr, "mjray: error: %s\n", message.c_str()); }

/// Each job's fingerprint, one after another: what every rank must agree on.
std::string all_fingerprints(const JobFingerprints& fingerprints, size_t jobs) {
  std::string text = "gr.render calls=" + std::to_string(jobs) + "\n";
  for (size_t i = 0; i < jobs; ++i) text += fingerprints.of(i);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  back_heap_with_large_pages(size_t(256) << 20);
  std::signal(SIGXFSZ, SIG_IGN);
  MpiWorld world(argc, argv);
  // Read before any rank on this host has loaded a scene or made a photon map.
  const uint64_t memory_at_start = machine_available_bytes();
  const bool root = world.rank() == 0;

  // Compute the command line: mjray's options and the driver's own.
  CommandLine cl;
  Distribution distribution = Distribution::kAuto;
  const std::vector<OptionSpec> own = {distribution_option(distribution)};
  try {
    cl = parse_command_line(std::vector<std::string>(argv + 1, argv + argc), own);
    if (cl.run.report.watch) throw UsageError("--watch: mjray-mpi does not serve the live preview; run mjray --watch instead");
    if (cl.run.report.time_limit_seconds > 0)
      throw UsageError("--time-limit: mjray-mpi renders to the end (its ranks would stop at different points); run "
                       "mjray --time-limit, or stop mjray-mpi with Ctrl-C and --resume");
  } catch (const UsageError& e) {
    if (!root) return 0;
    std::fprintf(stderr, "mjray: %s\n(run 'mjray-mpi --help' for the options)\n", e.what());
    return 2;
  }
  if (cl.show_help || cl.show_version) {
    if (root && cl.show_help) std::fputs(usage(own).c_str(), stdout);
    else if (root) std::printf("mjray-mpi %s\n", MJRAY_VERSION);
    return 0;
  }
  if (root) print_warnings(cl.warnings);
  RunOptions& options = cl.run;
  if (options.job.render.threads == 0) {
    const int threads = std::max(1, int(std::thread::hardware_concurrency()) / world.ranks_on_host());
    options.job.accel.threads = options.job.render.threads = threads;
    options.job.outputs.encoding.threads = threads;
  }
  // The ranks on one host make photon maps at the same time: each may hold its share of what
  // the host had available when they started.
  options.job.photons.processes_sharing_memory = world.ranks_on_host();
  options.job.photons.memory_at_start_bytes = memory_at_start;

  // Compute the scene on every rank, and agree that all have it, and the same one.
  const auto start = std::chrono::steady_clock::now();
  SceneDescription scene;
  std::string load_error;
  try {
    scene = load_scene(options.scene, options.load);
  } catch (const std::exception& e) {
    load_error = error_message(e);
  }
  const double load_seconds = seconds_since(start);
  std::vector<RankStatistics> ranks;
  if (const auto errors = agree_on_load(world, load_seconds, load_error, ranks); !errors.empty()) {
    if (!root) return 0;  // rank 0's exit code stands for the run
    for (const auto& e : errors) print_error(e);
    return 1;
  }
  // A scene that reads the clock may differ from rank to rank: the image would be a patchwork.
  if (world.size() > 1 && !scene.reads_clock.empty()) {
    if (!root) return 0;
    print_error(options.scene.string() + ": the script reads the clock (" + scene.reads_clock +
                "), so each rank may describe another scene; render it with mjray, or on one rank");
    return 1;
  }
  const JobFingerprints fingerprints(scene, options.job);
  if (const std::string verdict = agree_on_scene(world, all_fingerprints(fingerprints, scene.jobs.size()), ranks);
      !verdict.empty()) {
    if (!root) return 0;
    print_error(verdict);
    return 1;
  }
  // Every rank keeps going until rank 0 ends the run (mpirun signals them all on Ctrl-C).
  install_interrupt_handlers();
  if (!root) return run_worker(world, scene, options.job, {world.rank(), world.host(), 0, load_seconds});

  try {
    // The same preamble as mjray's: the jobs --frames selects, every check before rendering.
    const RunPlan plan = plan_run(scene, options);
    print_plan_messages(plan, options.report.quiet);
    const RunSetup setup{scene, options.job, plan, local_run_options(options.report), options.report.stats_json,
                         distribution, ranks};
    run_coordinator(world, setup);
    if (const auto& video = options.report.video) {
      std::vector<std::filesystem::path> files;
      for (const size_t i : plan.jobs) files.push_back(output_path(scene, i, options.job.outputs));
      encode_video(files, *video, options.report.fps);
      if (!options.report.quiet)
        std::fprintf(stderr, "mjray: wrote %s (%zu frames at %d fps)\n", video->c_str(), files.size(), options.report.fps);
    }
  } catch (const Interrupted&) {
    end_run(world);
    return 130;
  } catch (const RankFailed& e) {
    print_error(rank_name(e.rank(), ranks[size_t(e.rank())].host) + ": " + e.what());
    end_run(world);
    return 1;
  } catch (const std::exception& e) {
    print_error(error_message(e));
    end_run(world);
    return 1;
  }
  end_run(world);
  return 0;
}
