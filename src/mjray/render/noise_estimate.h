#pragma once
/// The noise target (--noise-threshold): how far a pixel's estimate may still be from its
/// converged value, and which pixels the next pass refines.

#include <vector>

#include "mjray/render/film.h"

namespace mjray {

/// The estimated error of a pixel's mean: the standard error of its samples' brightness,
/// relative to the square root of that brightness (as Cycles weighs its noise threshold: noise
/// in dark parts counts for less than in bright ones, but not in proportion). 0 for a pixel
/// with fewer than two samples' spread to measure.
float relative_error(const FilmPixel& pixel);

/// The pixels of the next noise pass, row-major: every pixel whose relative_error is above
/// `threshold` and its 8 neighbours (so that a refined patch has no unrefined holes), leaving
/// out those that already have `max_samples` samples.
std::vector<int> next_noise_set(const Film& film, float threshold, float max_samples);

}  // namespace mjray
