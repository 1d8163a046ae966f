// --spp statistically: N stratified samples average to the same pixel values, and the noise of
// a penumbra falls as 1/√N.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

/// A floor seen from above, under a square light of half-size 10 at height 100 whose left half
/// a plane at height 50 hides from x < 0: a penumbra from x = −10 to 10 fills the view. -s 2:
/// each camera sample takes 2 × 2 jittered light samples, so the pixels are noisy.
RenderJob penumbra_scene() {
  RenderJob job;
  job.root = test::group({test::mesh(test::floor_quad(1000), PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1}),
                          test::box({-500, 50, -500}, {0, 51, 500})});
  job.width = job.height = 24;
  job.camera = {{0, 20, 0}, {0, -1, 0}, {0, 0, -1}, 60};
  job.lights = {AreaLight{{-10, 100, -10}, {20, 0, 0}, {0, 0, 20}, {1, 1, 1}, {1, 0, 0}}};
  return job;
}

Image render_penumbra(int spp, uint64_t seed) {
  JobOptions options = test::oracle_options({8, 8, 2});
  options.render.samples_per_pixel = spp;
  options.render.seed = seed;
  return test::render(penumbra_scene(), options);
}

/// Per pixel, the mean and the standard deviation of the red channel over `seeds` renders.
struct PixelStatistics {
  std::vector<double> mean, deviation;
};

PixelStatistics over_seeds(int spp, int seeds) {
  std::vector<double> sum(24 * 24, 0), sum2(24 * 24, 0);
  for (int s = 0; s < seeds; ++s) {
    const Image image = render_penumbra(spp, uint64_t(100 + s));
    for (size_t i = 0; i < sum.size(); ++i) {
      sum[i] += image.pixels()[i].r;
      sum2[i] += double(image.pixels()[i].r) * image.pixels()[i].r;
    }
  }
  PixelStatistics p;
  for (size_t i = 0; i < sum.size(); ++i) {
    const double mean = sum[i] / seeds;
    p.mean.push_back(mean);
    p.deviation.push_back(std::sqrt(std::max(0.0, (sum2[i] - seeds * mean * mean) / (seeds - 1))));
  }
  return p;
}

TEST(StatSupersampling, AUniformlyLitPixelKeepsItsValue) {
  // Ambient light only: every sample of every pixel sees the same radiance.
  RenderJob job = penumbra_scene();
  job.lights = {PointLight{{0, 10, 0}, {0, 0, 0}, {1, 0, 0}}};
  job.ambient = {0.3f, 0.6f, 0.9f};
  const Image one = test::render(job);
  for (const int spp : {2, 7, 16, 64}) {
    JobOptions options = test::oracle_options();
    options.render.samples_per_pixel = spp;
    const Image many = test::render(job, options);
    for (size_t i = 0; i < one.pixels().size(); ++i)
      for (const auto& [a, b] : {std::pair{many.pixels()[i].r, one.pixels()[i].r}, {many.pixels()[i].g, one.pixels()[i].g},
                                 {many.pixels()[i].b, one.pixels()[i].b}})
        EXPECT_NEAR(a, b, 1e-6f) << spp << " samples, pixel " << i;
  }
}

TEST(StatSupersampling, TheMeanOfANoisyPixelIsUnchanged) {
  // Over seeds and the pixels of the penumbra, 16 samples average to what one sample gives.
  const PixelStatistics one = over_seeds(1, 40), sixteen = over_seeds(16, 10);
  double difference = 0, variance = 0;
  for (size_t i = 0; i < one.mean.size(); ++i) {
    difference += sixteen.mean[i] - one.mean[i];
    variance += one.deviation[i] * one.deviation[i] / 40 + sixteen.deviation[i] * sixteen.deviation[i] / 10;
  }
  EXPECT_LT(std::abs(difference), 4 * std::sqrt(variance)) << "the mean moved by " << difference / double(one.mean.size());
  EXPECT_GT(variance, 0);
}

TEST(StatSupersampling, PenumbraNoiseFallsAsOneOverTheRootOfTheSampleCount) {
  const int seeds = 12;
  const PixelStatistics four = over_seeds(4, seeds), sixteen = over_seeds(16, seeds), sixty_four = over_seeds(64, seeds);
  // Pixels well inside the penumbra: lit between 15% and 85%.
  double lit = 0;
  for (const double m : sixty_four.mean) lit = std::max(lit, m);
  double d4 = 0, d16 = 0, d64 = 0;
  int pixels = 0;
  for (size_t i = 0; i < four.mean.size(); ++i) {
    if (sixty_four.mean[i] < 0.15 * lit || sixty_four.mean[i] > 0.85 * lit) continue;
    d4 += four.deviation[i], d16 += sixteen.deviation[i], d64 += sixty_four.deviation[i];
    ++pixels;
  }
  ASSERT_GT(pixels, 100);
  RecordProperty("noise_ratios", "4/16 spp " + std::to_string(d4 / d16) + ", 16/64 spp " + std::to_string(d16 / d64) +
                                     " over " + std::to_string(pixels) + " pixels");
  // Four times the samples, half the noise.
  EXPECT_NEAR(d4 / d16, 2, 0.25);
  EXPECT_NEAR(d16 / d64, 2, 0.25);
}

}  // namespace
}  // namespace mjray
