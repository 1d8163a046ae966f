#pragma once
/// What decides a job's pixels, written down so that a resume can be refused with the reason.

#include <string>

#include "mjray/job/job_options.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// One "name=value" line per thing that shapes the image file of job `index`: the bytes of
/// the script and of every file it read (as hashes), the -D globals, the job's place in the
/// script, its size, transform order, lens, and every option that changes pixels or their
/// encoding (not threads or the accelerator, which never do). Reads the files, so call it only when a state is saved or resumed.
std::string job_fingerprint(const SceneDescription& scene, size_t index, const JobOptions& options);

/// The fingerprints of every job of one scene, reading each file once.
class JobFingerprints {
 public:
  /// Hashes the script and every file it read; both arguments must outlive this object.
  JobFingerprints(const SceneDescription& scene, const JobOptions& options);
  /// job_fingerprint(scene, index, options).
  std::string of(size_t index) const;

 private:
  const SceneDescription& scene_;
  const JobOptions& options_;
  std::string inputs_;  // the "scene" and "file" lines
};

/// The lines of `saved` and `current` that differ, for a refused resume ("-s: 2 then, 4 now").
std::string fingerprint_difference(const std::string& saved, const std::string& current);

}  // namespace mjray
