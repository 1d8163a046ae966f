// The noise target's arithmetic: a pixel's relative error from the spread of its samples
// (closed forms, and its fall as 1/√n), and the pixels the next pass refines (the noisy ones,
// their neighbours, never one at --max-spp).

#include <cmath>

#include <gtest/gtest.h>

#include "mjray/core/rng.h"
#include "mjray/render/noise_estimate.h"

namespace mjray {
namespace {

FilmPixel grey_samples(std::initializer_list<float> values) {
  FilmPixel pixel;
  for (const float v : values) pixel.add({v, v, v});
  return pixel;
}

TEST(NoiseEstimate, RelativeErrorIsTheStandardErrorOverTheRootOfTheBrightness) {
  // Samples 0.2 and 0.6: mean 0.4, sample variance 0.08, standard error √(0.08 / 2) = 0.2.
  EXPECT_NEAR(relative_error(grey_samples({0.2f, 0.6f})), 0.2 / std::sqrt(0.4), 1e-6);
  // The brightness is the mean of the channels.
  FilmPixel coloured;
  coloured.add({0.6f, 0, 0});
  coloured.add({1.8f, 0, 0});
  EXPECT_NEAR(relative_error(coloured), 0.2 / std::sqrt(0.4), 1e-6);
  // Nothing to measure: one sample, or samples that agree.
  EXPECT_EQ(relative_error(grey_samples({0.7f})), 0);
  EXPECT_NEAR(relative_error(grey_samples({0.5f, 0.5f, 0.5f})), 0, 1e-3);
  // Near black, the error is weighed as at brightness 0.001, not without bound.
  EXPECT_NEAR(relative_error(grey_samples({0, 0.0002f})), 0.0001 / std::sqrt(0.001), 1e-6);
}

TEST(NoiseEstimate, RelativeErrorFallsAsOneOverTheRootOfTheSamples) {
  // Uniform samples on [0, 1): σ = 1/√12, mean 1/2; four times the samples halve the error.
  const auto error_of = [](int n) {
    FilmPixel pixel;
    RandomStream random(7, 1, 2);
    for (int i = 0; i < n; ++i) {
      const float v = random.uniform();
      pixel.add({v, v, v});
    }
    return relative_error(pixel);
  };
  const double expected = 1 / std::sqrt(12.0) / std::sqrt(0.5);
  EXPECT_NEAR(error_of(4096) * std::sqrt(4096.0), expected, 0.05 * expected);
  EXPECT_NEAR(error_of(1024) / error_of(4096), 2, 0.15);
}

TEST(NoiseEstimate, TheNextPassTakesNoisyPixelsAndTheirNeighboursBelowTheCap) {
  Film film(5, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) film.at(x, y) = grey_samples({0.5f, 0.5f});
  film.at(2, 1) = grey_samples({0.1f, 0.9f});  // error 0.4 / √0.5 ≈ 0.57
  film.at(4, 3) = grey_samples({0.4f, 0.6f});  // error 0.1 / √0.5 ≈ 0.14
  EXPECT_EQ(next_noise_set(film, 0.2f, 1000), (std::vector<int>{1, 2, 3, 6, 7, 8, 11, 12, 13}));
  EXPECT_EQ(next_noise_set(film, 0.1f, 1000), (std::vector<int>{1, 2, 3, 6, 7, 8, 11, 12, 13, 14, 18, 19}));
  EXPECT_TRUE(next_noise_set(film, 0.6f, 1000).empty());
  // A pixel with --max-spp samples is done, though it is noisy; its neighbours are not.
  EXPECT_EQ(next_noise_set(film, 0.2f, 2), std::vector<int>{});
  film.at(2, 1).add({0.5f, 0.5f, 0.5f});
  EXPECT_EQ(next_noise_set(film, 0.2f, 3), (std::vector<int>{1, 2, 3, 6, 8, 11, 12, 13}));
}

}  // namespace
}  // namespace mjray
