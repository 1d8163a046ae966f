#pragma once
/// Rank 0's frame phase: whole jobs handed to the ranks as they come free (rank 0's own
/// threads take them too); every finished or stopped frame is written on rank 0.

#include <vector>

#include "coordinator.h"
#include "job_images.h"

namespace mjray {

/// Renders `jobs` as whole frames, continuing from `plans[job].state` where there is one.
/// Throws Interrupted after writing the frames stopped part way (their partial images and
/// states), or RankFailed.
void render_frames(MpiWorld& world, const RunSetup& setup, const std::vector<ResumePlan>& plans,
                   const std::vector<size_t>& jobs, StatisticsLog& log);

}  // namespace mjray
