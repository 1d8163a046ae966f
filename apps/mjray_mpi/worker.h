#pragma once
/// The life of every rank but 0: render what rank 0 hands over, send it back, until rank 0
/// ends the run. Such a rank prints nothing; rank 0 speaks for the job.

#include "job_statistics.h"
#include "mpi_world.h"
#include "mjray/job/job_options.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// Serves rank 0 until it sends Finish; returns the process's exit code (0: rank 0 reports
/// how the run ended). `rank` names this rank (rank, host, load seconds) in its reports.
int run_worker(MpiWorld& world, const SceneDescription& scene, const JobOptions& options, const RankStatistics& rank);

}  // namespace mjray
