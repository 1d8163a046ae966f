#pragma once
/// How watch mode renders one frame: coarse passes first, so that an image shows at once,
/// then the real render refining over them on the page. The real render is the one
/// render_job_locally built, so the finished image is the normal render's, byte for byte.

#include <array>
#include <cstddef>
#include <functional>
#include <optional>

#include "live_state.h"
#include "mjray/render/image_render.h"

namespace mjray {

class PreparedJob;

/// Thrown out of a render that a change to the scene's files made stale; nothing is written.
struct RenderSuperseded {};

/// A LocalRunOptions::run_render for frame `frame` of the page. When the user interrupts it
/// returns false (the caller keeps the partial image and state as usual); when `stale()`
/// turns true it stops the render and throws RenderSuperseded.
class ProgressiveRender {
 public:
  /// `page` must outlive every call; `settings` are the job's; `stale` is asked from another
  /// thread while a pass runs.
  ProgressiveRender(LiveState& page, size_t frame, const RenderSettings& settings, std::function<bool()> stale)
      : page_(page), frame_(frame), settings_(settings), stale_(std::move(stale)) {}

  bool operator()(const PreparedJob& job, ImageRender& render) const;

  /// The coarse passes, by the factor that divides width and height: 1/64 of the first
  /// pass's work, then 1/16.
  static constexpr std::array<int, 2> kCoarseFactors = {8, 4};

 private:
  /// The job's image at 1/factor of its size, with the job's options but no anti-aliasing;
  /// nothing when stopped.
  std::optional<Image> coarse_pass(const PreparedJob& job, int factor, const std::function<bool()>& stop_wanted) const;

  LiveState& page_;
  size_t frame_;
  RenderSettings settings_;
  std::function<bool()> stale_;
};

}  // namespace mjray
