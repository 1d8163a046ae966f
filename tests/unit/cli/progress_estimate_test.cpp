// The progress display's arithmetic: anti-aliasing work counted before it is planned, an
// ETA from each phase's own rate, the pass shown as the statistics count it, and the share
// of pixels the first anti-aliasing pass will take, judged from finished tiles only.

#include <gtest/gtest.h>

#include "progress_estimate.h"

namespace mjray {
namespace {

RenderSettings with_antialiasing(int samples) {
  RenderSettings s;
  s.antialias_samples = samples;
  s.antialias_max_passes = 4;
  return s;
}

TEST(ProgressEstimate, WithoutAntialiasingItIsTheShareOfPixelsDone) {
  ProgressEstimate e(100, 100, RenderSettings{});
  e.update({0, 10000, 0, 0}, 0);
  e.update({2500, 10000, 0, 0}, 1);
  EXPECT_DOUBLE_EQ(e.view().fraction, 0.25);
  EXPECT_DOUBLE_EQ(e.view().eta_seconds, 3);
  EXPECT_EQ(e.view().antialias_pass, 0);
}

TEST(ProgressEstimate, AntialiasingIsCountedBeforeItIsPlanned) {
  // 10000 first-pass samples; a fifth of the pixels will take 16 samples each in pass 1,
  // a quarter of that in pass 2, and so on.
  ProgressEstimate e(100, 100, with_antialiasing(4));
  e.update({0, 10000, 0, 0}, 0);
  e.set_first_pass_share(0.2);
  e.update({10000, 10000, 0, 0}, 1);  // the first pass is done, nothing planned yet
  const double expected_aa = 2000 * 16 * (1 + 0.25 + 0.0625 + 0.015625);
  EXPECT_NEAR(e.view().fraction, 10000 / (10000 + expected_aa), 1e-12);
  EXPECT_NEAR(e.view().eta_seconds, expected_aa / 10000, 1e-9);  // at the first pass's rate
}

TEST(ProgressEstimate, PlannedPassesReplaceTheGuessAndTheirOwnRateGivesTheEta) {
  ProgressEstimate e(100, 100, with_antialiasing(4));
  e.update({0, 10000, 0, 0}, 0);
  e.update({10000, 10000, 0, 0}, 1);          // first pass: 10000 samples/s
  e.update({10000, 10000 + 1000 * 16, 0, 1}, 1);  // pass 1 planned: 1000 pixels
  e.update({10000 + 4000, 10000 + 1000 * 16, 0, 1}, 3);  // 2000 samples/s in anti-aliasing
  const double later = 1000 * 16 * (0.25 + 0.0625 + 0.015625);
  const double remaining = 12000 + later;
  EXPECT_NEAR(e.view().eta_seconds, remaining / 2000, 1e-9);
  // Work is weighted by cost: an anti-aliasing sample costs 5 first-pass ones here.
  EXPECT_NEAR(e.view().fraction, (10000 + 5 * 4000.0) / (10000 + 5 * (16000 + later)), 1e-12);
  EXPECT_EQ(e.view().antialias_pass, 1);
  EXPECT_FALSE(e.view().choosing_pixels);
}

TEST(ProgressEstimate, ThePassShownIsOneThatHasPixels) {
  ProgressEstimate e(10, 10, with_antialiasing(2));
  e.update({0, 100, 0, 0}, 0);
  e.update({100, 100, 0, 1}, 1);  // planning pass 1
  EXPECT_TRUE(e.view().choosing_pixels);
  EXPECT_EQ(e.view().antialias_pass, 0);
  e.update({100, 140, 0, 1}, 1.1);  // pass 1 has 10 pixels
  EXPECT_EQ(e.view().antialias_pass, 1);
  e.update({140, 140, 0, 2}, 1.2);  // planning pass 2, which will find none
  EXPECT_TRUE(e.view().choosing_pixels);
  EXPECT_EQ(e.view().antialias_pass, 1);
  e.update({140, 140, 0, 5}, 1.3);  // anti-aliasing over (pass = max + 1): no pass shown
  EXPECT_EQ(e.view().antialias_pass, 0);
  EXPECT_FALSE(e.view().choosing_pixels);
  EXPECT_LT(e.view().fraction, 1);  // 100% only when the render says it finished
}

TEST(ProgressEstimate, AResumedRenderMeasuresOnlyItsOwnRate) {
  ProgressEstimate e(100, 100, with_antialiasing(4));
  // Resumed in pass 1, with the first pass and half of the 1000-pixel pass done before.
  e.update({10000 + 8000, 10000 + 16000, 0, 1}, 0);
  e.update({10000 + 10000, 10000 + 16000, 0, 1}, 1);
  const double later = 1000 * 16 * (0.25 + 0.0625 + 0.015625);
  EXPECT_NEAR(e.view().eta_seconds, (6000 + later) / 2000, 1e-9);
  EXPECT_EQ(e.view().antialias_pass, 1);
}

TEST(ProgressEstimate, NoisePassesAreCountedFromHowTheirPixelsShrink) {
  // 100x100 pixels, 16 samples each first; --max-spp 128: passes of 16, 32 and 64 samples.
  RenderSettings s;
  s.noise_threshold = 0.01f;
  s.max_samples_per_pixel = 128;
  ProgressEstimate e(100, 100, s);
  e.update({0, 160000, 0, 0}, 0);
  e.update({80000, 160000, 0, 0}, 1);
  // Before a plan: a quarter of the pixels in pass 1, three quarters of those in each next.
  const double guess = 2500 * (16 + 0.75 * 32 + 0.5625 * 64);
  EXPECT_NEAR(e.view().fraction, 80000 / (160000 + guess), 1e-12);
  EXPECT_FALSE(e.view().clean_fraction);
  // Pass 1 refines 1000 pixels: 90% are clean; then pass 2 refines 500.
  e.update({160000, 160000 + 16000, 0, 1, 1000}, 2);
  EXPECT_DOUBLE_EQ(*e.view().clean_fraction, 0.9);
  EXPECT_EQ(e.view().antialias_pass, 1);
  EXPECT_NEAR(e.view().fraction, 160000 / (160000 + 16000 + 1000 * (0.75 * 32 + 0.5625 * 64)), 1e-12);
  e.update({176000, 176000, 0, 2, 0}, 3);  // choosing pass 2's pixels
  EXPECT_TRUE(e.view().choosing_pixels);
  EXPECT_DOUBLE_EQ(*e.view().clean_fraction, 0.9);
  e.update({176000, 176000 + 16000, 0, 2, 500}, 4);
  EXPECT_DOUBLE_EQ(*e.view().clean_fraction, 0.95);
  // Pass 2 then has the last two passes' ratio, a half; noise samples ran at a tenth of the
  // first pass's rate (16000 in 2 s against 160000 in 2 s), so each counts ten.
  const double noise_done = 16000, noise_total = 32000 + 500 * 0.5 * 64;
  EXPECT_NEAR(e.view().fraction, (160000 + 10 * noise_done) / (160000 + 10 * noise_total), 1e-12);
}

TEST(SupersampleShare, CountsBadPixelsAndTheirNeighboursInFinishedTilesOnly) {
  // Two 4x4 tiles side by side; the right one is unfinished (black). The left one has a
  // vertical edge between columns 1 and 2: columns 0..3 are bad or next to a bad pixel.
  Image snapshot(8, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) snapshot.at(x, y) = x < 2 ? Color(0.2f, 0.2f, 0.2f) : Color(0.9f, 0.9f, 0.9f);
  EXPECT_EQ(supersample_share(snapshot, 4, 0.1f), 1.0);
  // A flat finished tile beside an unfinished one: the black border is not an edge.
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) snapshot.at(x, y) = Color(0.5f, 0.5f, 0.5f);
  EXPECT_EQ(supersample_share(snapshot, 4, 0.1f), 0.0);
  // A single bright pixel at (0, 0): it and its 3 neighbours are bad (each differs from it),
  // and they bring their neighbours: the 3x3 block at the corner, 9 of 16.
  snapshot.at(0, 0) = Color(1, 1, 1);
  EXPECT_EQ(supersample_share(snapshot, 4, 0.1f), 9.0 / 16.0);
  EXPECT_FALSE(supersample_share(Image(8, 4), 4, 0.1f).has_value());  // nothing finished
}

}  // namespace
}  // namespace mjray
