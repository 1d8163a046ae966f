#pragma once
/// The files one job leaves, whichever driver rendered it: the finished image, recording the
/// job's fingerprint; or, when interrupted, the partial image and the state to resume from;
/// and what --resume makes of the files it finds.

#include <filesystem>
#include <optional>
#include <string>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"
#include "mjray/render/render_checkpoint.h"

namespace mjray {

/// What --resume decides for one job before anything is built.
struct ResumePlan {
  bool keep = false;                      ///< a complete image that this job made: nothing to render
  std::optional<RenderCheckpoint> state;  ///< an interrupted render of this job to continue
};

/// Without `resume`, render from scratch. With it: continue from the image's state file when
/// there is one, keep a complete image that records `fingerprint`, else render. Throws
/// SceneError saying what differs when the image or the state was made by another scene or
/// other options.
ResumePlan plan_resume(const std::filesystem::path& image, const std::string& fingerprint, bool resume);

/// Writes the finished image recording `fingerprint`, so that a later --resume can keep it,
/// and removes the state file beside it. Throws OutputError.
void write_finished_image(const Image& image, const std::filesystem::path& path, EncodeOptions encoding,
                          const std::string& fingerprint);

/// Why a render stopped before it finished.
enum class StopReason { kInterrupted, kTimeLimit };

/// How far a stopped render got: "first pass, 40 of 920 tiles", "noise pass 3 of 8, 12034
/// pixels to refine", "anti-aliasing pass 2".
std::string progress_reached(const RenderCheckpoint& checkpoint, bool targets_noise, int passes);

/// Writes the partial image (recording no fingerprint, and in its metadata why it stopped and
/// `reached`) and `checkpoint` (with its fingerprint) beside it, and tells the user how to
/// go on. Throws OutputError.
void write_stopped_image(const RenderCheckpoint& checkpoint, const std::filesystem::path& path, EncodeOptions encoding,
                         StopReason reason, const std::string& reached);

}  // namespace mjray
