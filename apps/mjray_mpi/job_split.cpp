#include "job_split.h"


namespace mjray {

JobSplit split_jobs(const std::vector<size_t>& jobs, int ranks, Distribution distribution) {
  size_t whole = 0;
  if (distribution == Distribution::kFrames) whole = jobs.size();
  else if (distribution == Distribution::kAuto && ranks > 1) whole = jobs.size() - jobs.size() % size_t(ranks);
  JobSplit split;
  split.frames.assign(jobs.begin(), jobs.begin() + std::ptrdiff_t(whole));
  split.tiles.assign(jobs.begin() + std::ptrdiff_t(whole), jobs.end());
  return split;
}

OptionSpec distribution_option(Distribution& distribution) {
  return {{"--distribute"}, "auto|tiles|frames",
          "the unit of work handed out: tiles of one image (every rank renders each image), or whole images of an "
          "animation (each rank renders its own); default auto: whole images while there are enough to keep every "
          "rank busy, tiles for the rest",
          [&distribution](RunOptions&, const std::string& option, const std::string& value) {
            if (value == "auto") distribution = Distribution::kAuto;
            else if (value == "tiles") distribution = Distribution::kTiles;
            else if (value == "frames") distribution = Distribution::kFrames;
            else throw UsageError(option + " expects auto, tiles or frames, got '" + value + "'");
          }};
}

}  // namespace mjray
