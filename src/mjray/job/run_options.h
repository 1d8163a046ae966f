#pragma once
/// Everything a command line says about a run: the scene, how its script runs, what its images
/// are, and how the run reports. The option table (option_table.h) fills it.

#include <filesystem>
#include <optional>
#include <string>

#include "mjray/job/job_options.h"
#include "mjray/scene/scene_load_options.h"

namespace mjray {

/// How a run reports, what it writes beside the images, and how it is driven.
struct ReportOptions {
  bool quiet = false;        ///< --quiet: only warnings and errors (and what --stats asks for)
  bool print_stats = false;  ///< --stats
  std::optional<std::filesystem::path> stats_json;  ///< --stats-json
  bool resume = false;       ///< --resume
  /// --time-limit: seconds after which the run stops and writes what it has (0: none).
  double time_limit_seconds = 0;
  std::optional<std::filesystem::path> video;  ///< --video: the frames joined by ffmpeg
  int fps = 24;              ///< --fps of the video
  bool watch = false;        ///< --watch: the live preview
  std::optional<int> port;   ///< --port; 0 = any free port; default kDefaultWatchPort
  std::optional<std::string> listen;  ///< --listen ADDR; default 127.0.0.1
};

/// The port --watch serves on without --port (the next free one when it is taken).
inline constexpr int kDefaultWatchPort = 8488;

/// -g, -o and --accel as given: which accelerator they pick depends on all three, whatever
/// their order (resolve_accelerator).
struct AcceleratorRequest {
  std::optional<int> grid_size;  ///< -g
  bool optimal_grid = false;     ///< -o
  std::string named;             ///< --accel; empty = not given
};

/// Everything the command line says about a run.
struct RunOptions {
  std::filesystem::path scene;
  SceneLoadOptions load;
  JobOptions job;
  ReportOptions report;
  AcceleratorRequest accel_request;
};

}  // namespace mjray
