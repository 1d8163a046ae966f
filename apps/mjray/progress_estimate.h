#pragma once
/// How much of a render is done and how long the rest will take, counting the work of passes
/// before they are planned: -a's from the share of bad pixels, --noise-threshold's from how
/// the set of noisy pixels shrinks, each corrected as every pass is planned.

#include <optional>
#include <vector>

#include "mjray/core/image.h"
#include "mjray/render/image_render.h"

namespace mjray {

/// What the progress display shows.
struct ProgressView {
  double fraction = 0;     ///< of the work done, estimate included; below 1 until finished
  double eta_seconds = 0;  ///< the rest at the rate so far; 0 when unknown
  /// The anti-aliasing pass under way, as the statistics count passes (0: first pass, or none
  /// planned yet); with choosing_pixels, the next pass is being planned.
  int antialias_pass = 0;
  bool choosing_pixels = false;
  /// With --noise-threshold, after the first pass: the share of pixels clean (or at --max-spp).
  std::optional<double> clean_fraction;
};

/// Turns the counters of one ImageRender into a ProgressView.
class ProgressEstimate {
 public:
  /// width × height: the pixels the render traces (ImageRender::region()).
  ProgressEstimate(int width, int height, const RenderSettings& settings);

  /// Every tick: the render's counters and the seconds since this run started.
  void update(const RenderProgress& progress, double elapsed);
  /// Now and then during the first pass: the share of finished pixels that the first
  /// anti-aliasing pass will supersample (see supersample_share).
  void set_first_pass_share(double share) { first_pass_share_ = share; }
  ProgressView view() const;

  /// Later passes are assumed to shrink by this factor per pass until two are known.
  static constexpr double kLaterPassRatio = 0.25;
  /// Noise passes are assumed to refine this share of the pixels in the first, and each this
  /// share of the last one's pixels, until two are known (typical of the feature scenes; the
  /// passes end at --max-spp, so the sum is finite whatever the share).
  static constexpr double kFirstNoisePassShare = 0.25;
  static constexpr double kNoisePassRatio = 0.75;
  /// Seconds of anti-aliasing before its own rate is trusted.
  static constexpr double kRateSettleSeconds = 0.5;

 private:
  /// Anti-aliasing samples expected beyond those already planned.
  double unplanned_samples() const;
  /// The same for the noise target's passes.
  double unplanned_noise_samples() const;

  double first_pass_samples_;
  double samples_per_pixel_;  // 0 without anti-aliasing
  bool targets_noise_;
  double pixels_;             // traced
  double noise_first_samples_;  // per pixel in the first pass under --noise-threshold
  int max_passes_;
  double first_pass_share_ = 0;
  RenderProgress last_;
  double elapsed_ = 0;
  double first_ = -1;                // samples done when this run began (a resume starts with some)
  double antialias_start_ = -1;      // seconds into this run when anti-aliasing began
  double first_pass_seconds_ = 0;
  double antialias_start_done_ = 0;  // samples done then
  std::vector<double> pass_pixels_;  // pixels of each pass seen planned in this run
  int planned_pass_ = 0;             // the pass whose plan was seen last
};

/// The share of finished first-pass pixels that the first anti-aliasing pass would choose
/// (bad pixels and their neighbours), judged within the tiles of `snapshot` that are
/// finished: those with a pixel that is not black (ImageRender::snapshot leaves unfinished
/// tiles black). None when no tile is finished yet.
std::optional<double> supersample_share(const Image& snapshot, int tile_size, float threshold);

}  // namespace mjray
