#pragma once
/// Which jobs go to the ranks as whole frames and which as tiles.

#include <cstddef>
#include <string>
#include <vector>

#include "mjray/job/option_table.h"

namespace mjray {

/// The unit of work: --distribute auto|tiles|frames.
enum class Distribution { kAuto, kTiles, kFrames };

/// Jobs (indices into the scene's jobs, in script order) by how they are distributed.
struct JobSplit {
  std::vector<size_t> frames;  ///< each rendered whole by one rank, handed out as ranks come free
  std::vector<size_t> tiles;   ///< one after another, each image's tiles shared by every rank
};

/// kAuto: with more than one rank, whole frames for the largest multiple of the rank count
/// that the jobs allow (no per-frame waits, each rank builds only its own frames), tiles for
/// the last jobs that would leave ranks idle; with one rank, or fewer jobs than ranks, tiles.
JobSplit split_jobs(const std::vector<size_t>& jobs, int ranks, Distribution distribution);

/// mjray-mpi's own option, --distribute auto|tiles|frames, storing its value in `distribution`
/// (which must outlive the parse).
OptionSpec distribution_option(Distribution& distribution);

}  // namespace mjray
