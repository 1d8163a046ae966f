#pragma once
/// What the live page shows: the frames of the latest render with their current images and
/// progress, and the latest error. The watch loop writes it, the server's threads read it.

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "statistics_json.h"
#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// Where a frame is in its render.
enum class FramePhase { kWaiting, kCoarse, kFirstPass, kAntialiasing, kDone };

/// How far a frame's render has come.
struct FrameProgress {
  FramePhase phase = FramePhase::kWaiting;
  double fraction = 0;         ///< of the frame's work, in [0, 1]
  double eta_seconds = 0;      ///< 0 when unknown
  double rays_per_second = 0;
  int antialias_pass = 0;      ///< with kAntialiasing: 1, 2, ...
};

/// One gr.render call as the page lists it.
struct FrameDescription {
  std::string image;  ///< the output's file name
  int width = 0, height = 0;
};

/// Thread-safe; images stay until a newer one of the same frame replaces them, so a failed
/// script leaves the last good images on the page.
class LiveState {
 public:
  /// `encoding` decides how images are encoded for the page (as the output files are).
  LiveState(std::string scene_name, const EncodeOptions& encoding);

  /// A render of the scene starts (the first, or after a change): a new render id.
  void begin_render();
  /// The script ran and describes these frames; clears the error. Images of frames that
  /// are still there stay until replaced.
  void set_frames(const std::vector<FrameDescription>& frames);
  /// The script, its outputs or the render failed with `message` ("scene.lua:LINE: ...").
  void fail(const std::string& message);
  /// Frame `frame` (0-based) now looks like `image` (the frame's full size).
  void show_image(size_t frame, Image image);
  void show_progress(size_t frame, const FrameProgress& progress);
  /// Frame `frame` is written; `statistics` are its figures.
  void finish_frame(size_t frame, const JobStatistics& statistics);
  /// Every frame is finished.
  void finish_render();

  uint64_t render_id() const;
  /// Everything but the images, as JSON: render id, state, error, frames with progress,
  /// image version and, once finished, statistics.
  std::string status_json() const;
  /// The PNG of frame `frame`'s current image; nothing when it has none (yet).
  std::optional<std::string> frame_png(size_t frame) const;

 private:
  /// One frame's entry.
  struct Frame {
    FrameDescription description;
    std::shared_ptr<const Image> image;
    uint64_t version = 0;               // 0: no image yet
    FrameProgress progress;
    Json statistics;                    // an object once finished; null until then
    mutable std::shared_ptr<const std::string> png;  // encoded image of png_version
    mutable uint64_t png_version = 0;
  };

  mutable std::mutex mutex_;
  std::string scene_name_;
  EncodeOptions encoding_;
  uint64_t render_id_ = 0;
  std::string state_ = "starting";  // loading | rendering | done | error
  std::string error_;
  size_t active_frame_ = 0;
  uint64_t next_version_ = 1;
  std::vector<Frame> frames_;
};

}  // namespace mjray
