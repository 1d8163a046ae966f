#pragma once
/// What the ranks settle before anything renders: that every one of them loaded the scene,
/// and that they all loaded the same scene from the same files.

#include <string>
#include <vector>

#include "job_statistics.h"
#include "mpi_world.h"

namespace mjray {

/// "rank 2 (node7)".
std::string rank_name(int rank, const std::string& host);

/// Collective: gathers every rank's load outcome (`error` empty when it loaded the scene).
/// Returns, on every rank, the errors that end the run: none when all loaded; on rank 0 one
/// message per distinct error, naming the ranks unless all failed alike. On rank 0 fills
/// `ranks` with each rank's host and load seconds.
std::vector<std::string> agree_on_load(MpiWorld& world, double load_seconds, const std::string& error,
                          std::vector<RankStatistics>& ranks);

/// Collective: compares every rank's job fingerprints (hashes of the script and each file it
/// read, the gr.render calls, the options) with rank 0's. Returns what ends the run: empty
/// when all agree; on rank 0 which rank differs and how.
std::string agree_on_scene(MpiWorld& world, const std::string& fingerprints, const std::vector<RankStatistics>& ranks);

}  // namespace mjray
