#pragma once
/// Rank 0's part of a run: decide what --resume keeps, split the jobs into whole frames and
/// tiled images, have every rank render them, and write every image and the statistics.

#include <filesystem>
#include <map>
#include <optional>
#include <vector>

#include "job_split.h"
#include "job_statistics.h"
#include "statistics_json.h"
#include "local_render.h"
#include "mpi_world.h"
#include "mjray/job/run_plan.h"
#include "mjray/job/job_options.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// What rank 0 knows when the rendering starts.
struct RunSetup {
  const SceneDescription& scene;
  const JobOptions& options;
  const RunPlan& plan;  ///< the jobs to render (--frames) and their fingerprints
  LocalRunOptions run;
  std::optional<std::filesystem::path> stats_json;
  Distribution distribution = Distribution::kAuto;
  std::vector<RankStatistics> ranks;  ///< by rank: its host and the seconds it took to load the scene
};

/// The statistics of the jobs rendered so far, in script order, rewritten to --stats-json
/// after each job.
class StatisticsLog {
 public:
  explicit StatisticsLog(std::optional<std::filesystem::path> json) : json_(std::move(json)) {}
  void add(size_t job, const JobStatistics& stats) {
    jobs_[job] = stats;
    if (!json_) return;
    std::vector<JobStatistics> list;
    for (const auto& [index, s] : jobs_) list.push_back(s);
    write_statistics_json(list, *json_);
  }

 private:
  std::optional<std::filesystem::path> json_;
  std::map<size_t, JobStatistics> jobs_;
};

/// Runs every job of the plan over the ranks. Throws Interrupted (the partial images and
/// their states written), RankFailed, SceneError or OutputError; the caller then ends the
/// other ranks with end_run.
void run_coordinator(MpiWorld& world, const RunSetup& setup);

/// Tells every other rank that the run is over.
void end_run(MpiWorld& world);

}  // namespace mjray
