#include "progress_estimate.h"

#include <algorithm>
#include <cmath>

#include "mjray/render/tile_layout.h"

namespace mjray {

ProgressEstimate::ProgressEstimate(int width, int height, const RenderSettings& settings)
    : first_pass_samples_(double(width) * double(height) * std::max(1, settings.first_pass_samples())),
      // Subdivision needs no anti-aliasing pass: all its work is in the first.
      samples_per_pixel_(settings.antialias_samples > 0 && !settings.subdivides()
                             ? double(settings.antialias_samples) * settings.antialias_samples *
                                   std::max(1, settings.samples_per_pixel)
                             : 0),
      targets_noise_(settings.targets_noise()),
      pixels_(double(width) * double(height)),
      noise_first_samples_(std::max(1, settings.first_pass_samples())),
      max_passes_(pixel_pass_count(settings)) {}

void ProgressEstimate::update(const RenderProgress& progress, double elapsed) {
  // A pass's plan shows as growth of the total (two plans between ticks merge into one).
  if (samples_per_pixel_ > 0 && progress.total > last_.total && progress.antialias_pass > 0 && last_.total > 0) {
    pass_pixels_.push_back(double(progress.total - last_.total) / samples_per_pixel_);
    planned_pass_ = progress.antialias_pass;
  } else if (samples_per_pixel_ > 0 && last_.total == 0 && progress.antialias_pass > 0 &&
             double(progress.total) > first_pass_samples_) {
    // A resumed pass: planned before this run started.
    pass_pixels_.push_back((double(progress.total) - first_pass_samples_) / samples_per_pixel_);
    planned_pass_ = progress.antialias_pass;
  }
  // A noise pass shows its plan as the pixels it refines.
  if (targets_noise_ && progress.antialias_pass > planned_pass_ && progress.pixels_refining > 0) {
    pass_pixels_.push_back(double(progress.pixels_refining));
    planned_pass_ = progress.antialias_pass;
  }
  // Where each phase began in this run, to measure its own rate.
  if (first_ < 0) first_ = double(progress.done);
  if (progress.antialias_pass > 0 && antialias_start_ < 0) {
    antialias_start_ = elapsed;
    first_pass_seconds_ = elapsed;
    antialias_start_done_ = double(progress.done);
  }
  last_ = progress;
  elapsed_ = elapsed;
}

double ProgressEstimate::unplanned_noise_samples() const {
  if (last_.antialias_pass > max_passes_) return 0;
  // Until a pass is planned, guess the share of pixels the first refines.
  double pixels = pass_pixels_.empty() ? pixels_ * kFirstNoisePassShare : pass_pixels_.back();
  double ratio = kNoisePassRatio;
  if (pass_pixels_.size() >= 2 && pass_pixels_[pass_pixels_.size() - 2] > 0)
    ratio = std::min(1.0, pixels / pass_pixels_[pass_pixels_.size() - 2]);
  // Pass k adds first · 2^(k−1) samples to each pixel it refines.
  const int planned = pass_pixels_.empty() ? 0 : planned_pass_;
  double samples = 0;
  for (int k = planned + 1; k <= max_passes_; ++k) {
    if (k > 1 || !pass_pixels_.empty()) pixels *= ratio;
    samples += pixels * noise_first_samples_ * std::ldexp(1.0, k - 1);
  }
  return samples;
}

double ProgressEstimate::unplanned_samples() const {
  if (targets_noise_) return unplanned_noise_samples();
  if (samples_per_pixel_ == 0 || last_.antialias_pass > max_passes_) return 0;
  // The pass to extrapolate from and how it shrinks.
  double pixels = 0, ratio = kLaterPassRatio;
  int passes_left = 0;
  if (last_.antialias_pass == 0) {
    pixels = first_pass_share_ * first_pass_samples_;
    passes_left = max_passes_ - 1;
    const double first = pixels;
    double later = 0;
    for (int k = 0; k < passes_left; ++k) later += (pixels *= ratio);
    return (first + later) * samples_per_pixel_;
  }
  if (pass_pixels_.empty()) return 0;
  pixels = pass_pixels_.back();
  if (pass_pixels_.size() >= 2 && pass_pixels_[pass_pixels_.size() - 2] > 0)
    ratio = std::min(1.0, pixels / pass_pixels_[pass_pixels_.size() - 2]);
  passes_left = max_passes_ - planned_pass_;
  double later = 0;
  for (int k = 0; k < passes_left; ++k) later += (pixels *= ratio);
  return later * samples_per_pixel_;
}

ProgressView ProgressEstimate::view() const {
  ProgressView v;
  // Samples of each phase: done, and in all (the anti-aliasing ones partly estimated).
  const double done = double(last_.done);
  const double first_done = std::min(done, first_pass_samples_);
  const double aa_done = done - first_done;
  const double aa_total = std::max(0.0, double(last_.total) - first_pass_samples_) + unplanned_samples();
  // Each phase's rate in this run (an anti-aliasing sample often costs more: edges, shadows).
  const double first_seconds = antialias_start_ < 0 ? elapsed_ : first_pass_seconds_;
  const double first_rate = first_seconds > 0 ? (first_done - std::min(first_, first_pass_samples_)) / first_seconds : 0;
  const double aa_seconds = antialias_start_ < 0 ? 0 : elapsed_ - antialias_start_;
  const double aa_rate = aa_seconds >= kRateSettleSeconds ? (done - antialias_start_done_) / aa_seconds : 0;
  const double aa_cost = first_rate > 0 && aa_rate > 0 ? first_rate / aa_rate : 1;  // in first-pass samples
  // The fraction counts work by its cost, so that it runs evenly with the clock.
  const double total = first_pass_samples_ + aa_cost * aa_total;
  v.fraction = total > 0 ? std::min(0.999, (first_done + aa_cost * aa_done) / total) : 0;
  const double rate_first = first_rate > 0 ? first_rate : aa_rate;
  const double rate_aa = aa_rate > 0 ? aa_rate : first_rate;
  if (rate_first > 0 && rate_aa > 0)
    v.eta_seconds = (first_pass_samples_ - first_done) / rate_first + std::max(0.0, aa_total - aa_done) / rate_aa;
  const int pass = last_.antialias_pass;
  if (targets_noise_ && pass > 0) {
    v.choosing_pixels = pass <= max_passes_ && last_.pixels_refining == 0;
    v.antialias_pass = std::min(pass, max_passes_);
    // Between passes, the last plan's pixels are still the ones not known clean.
    const double refining = last_.pixels_refining > 0 ? double(last_.pixels_refining)
                            : pass_pixels_.empty()     ? pixels_
                                                       : pass_pixels_.back();
    v.clean_fraction = pixels_ > 0 ? 1 - refining / pixels_ : 1;
  } else if (pass > 0 && pass <= max_passes_ && samples_per_pixel_ > 0) {
    v.choosing_pixels = pass != planned_pass_;
    v.antialias_pass = planned_pass_;
  }
  return v;
}

std::optional<double> supersample_share(const Image& snapshot, int tile_size, float threshold) {
  const int w = snapshot.width(), h = snapshot.height();
  const TileLayout layout{w, h, std::max(1, tile_size)};
  std::vector<uint8_t> finished(size_t(w) * size_t(h), 0);
  size_t finished_pixels = 0;
  for (int t = 0; t < layout.count(); ++t) {
    const PixelRect r = layout.rect(t);
    bool lit = false;
    for (int y = r.y0; y < r.y1 && !lit; ++y)
      for (int x = r.x0; x < r.x1 && !lit; ++x) {
        const Color& c = snapshot.at(x, y);
        lit = c.r != 0 || c.g != 0 || c.b != 0;
      }
    if (!lit) continue;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) finished[size_t(y) * size_t(w) + size_t(x)] = 1;
    finished_pixels += size_t(r.pixel_count());
  }
  if (finished_pixels == 0) return std::nullopt;
  // Bad pixels against their finished neighbours, then the neighbours they bring along.
  std::vector<uint8_t> chosen(finished.size(), 0);
  const auto is_finished = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && finished[size_t(y) * size_t(w) + size_t(x)]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!is_finished(x, y)) continue;
      const Color& c = snapshot.at(x, y);
      bool bad = false;
      for (int dy = -1; dy <= 1 && !bad; ++dy)
        for (int dx = -1; dx <= 1 && !bad; ++dx) {
          if (!is_finished(x + dx, y + dy)) continue;
          const Color& n = snapshot.at(x + dx, y + dy);
          bad = std::abs(c.r - n.r) > threshold || std::abs(c.g - n.g) > threshold || std::abs(c.b - n.b) > threshold;
        }
      if (!bad) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (is_finished(x + dx, y + dy)) chosen[size_t(y + dy) * size_t(w) + size_t(x + dx)] = 1;
    }
  size_t count = 0;
  for (const uint8_t c : chosen) count += c;
  return double(count) / double(finished_pixels);
}

}  // namespace mjray
