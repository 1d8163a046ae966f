#pragma once
/// One whole job rendered on this process's threads and stoppable from another thread: what
/// a rank does with a frame of an animation, on rank 0 as on the others.

#include <mutex>
#include <optional>
#include <string>

#include "messages.h"
#include "mjray/job/job_options.h"
#include "mjray/render/image_render.h"
#include "mjray/render/render_checkpoint.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// What became of a frame: the message for rank 0, or why it could not be rendered.
struct FrameOutcome {
  FrameDoneMessage done;
  std::string error;  ///< not empty: the job failed (done is meaningless)
};

/// Renders jobs one at a time; request_stop() may come from any thread.
class FrameRender {
 public:
  /// Prepares and renders job `index` of `scene`, from `state` when given. `rank` names this
  /// rank (rank, host, load seconds) in the statistics. Never throws.
  FrameOutcome run(const SceneDescription& scene, size_t index, const JobOptions& options,
                   const std::optional<RenderCheckpoint>& state, const RankStatistics& rank);
  /// Stops the frame under way (keeping what is done) and every later one before it starts.
  void request_stop();

 private:
  std::mutex mutex_;
  ImageRender* current_ = nullptr;
  bool stop_ = false;
};

}  // namespace mjray
