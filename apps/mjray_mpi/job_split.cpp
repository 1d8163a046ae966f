#include "job_split.h"

#include "cli.h"

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

Distribution take_distribution(std::vector<std::string>& args) {
  Distribution distribution = Distribution::kAuto;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--") break;
    std::string value;
    if (args[i].rfind("--distribute=", 0) == 0) {
      value = args[i].substr(13);
      args.erase(args.begin() + std::ptrdiff_t(i));
    } else if (args[i] == "--distribute") {
      if (i + 1 >= args.size()) throw UsageError("--distribute needs a value");
      value = args[i + 1];
      args.erase(args.begin() + std::ptrdiff_t(i), args.begin() + std::ptrdiff_t(i + 2));
    } else {
      continue;
    }
    if (value == "auto") distribution = Distribution::kAuto;
    else if (value == "tiles") distribution = Distribution::kTiles;
    else if (value == "frames") distribution = Distribution::kFrames;
    else throw UsageError("--distribute expects auto, tiles or frames, got '" + value + "'");
    --i;
  }
  return distribution;
}

}  // namespace mjray
