#pragma once
/// The preamble every driver runs once the scene is loaded: which jobs render, and every check
/// that can fail before a pixel is traced. Local, --watch and mjray-mpi call the same one.

#include <string>
#include <vector>

#include "mjray/job/job_fingerprint.h"
#include "mjray/job/run_options.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// What a run renders, and what to tell the user before it starts.
struct RunPlan {
  std::vector<size_t> jobs;           ///< the gr.render calls --frames selects, in script order
  JobFingerprints fingerprints;       ///< of every job (for --resume, and ranks' agreement)
  std::vector<std::string> warnings;  ///< the script's, then the outputs' ("mjray: warning: ...")
  std::vector<std::string> notes;     ///< choices made for the user ("mjray: note: ...")
};

/// Selects the jobs (--frames), checks each one's view (size, lens, --crop), its output (format,
/// place, sandbox, names, no file the scene reads), the --video and --stats-json files, and
/// creates the folders the command line names. `scene` and `options` must outlive the plan.
/// Throws SceneError or OutputError.
RunPlan plan_run(const SceneDescription& scene, const RunOptions& options);

}  // namespace mjray
