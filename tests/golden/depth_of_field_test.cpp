// Depth of field through whole renders: a thin lens images a point at the focus distance to
// one pixel, spreads a point off focus over the blur circle the thin-lens formula gives, and
// is the pinhole image exactly when its aperture is 0.

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

constexpr float kFovy = 10;  // degrees: a narrow view makes a small point cover whole pixels

/// A white point (a tiny sphere lit by ambient light only) at (x, y, -depth) before a camera
/// at the origin looking along −z, on a black background.
RenderJob point_scene(float depth, float radius, float aperture, float focus, int size, float x = 0, float y = 0) {
  RenderJob job;
  job.root = test::group({test::sphere({x, y, -depth}, radius, PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1})});
  job.width = job.height = size;
  job.camera = {{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, kFovy, aperture, focus};
  job.ambient = {1, 1, 1};
  job.lights = {PointLight{{0, 0, 10}, {0, 0, 0}, {1, 0, 0}}};
  job.background.zenith = job.background.horizon = {0, 0, 0};
  return job;
}

JobOptions samples(int spp) {
  JobOptions o = test::oracle_options();
  o.render.samples_per_pixel = spp;
  return o;
}

/// The size of one pixel at the image centre, in world units at `distance`.
double pixel_size_at(double distance, int size) {
  return 2 * distance * std::tan(kFovy * std::numbers::pi / 360) / size;
}

TEST(DepthOfField, APointAtTheFocusDistanceImagesToOnePixel) {
  const int size = 33;  // odd: the view direction goes through the centre of pixel (16, 16)
  const float focus = 10;
  const float radius = float(0.2 * pixel_size_at(focus, size));
  // A lens that spreads the same point 10 m further away over many pixels.
  const Image sharp = test::render(point_scene(focus, radius, 0.5f, focus, size), samples(256));
  int lit = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      if (sharp.at(x, y).r > 0) {
        ++lit;
        EXPECT_EQ(x, 16);
        EXPECT_EQ(y, 16);
      }
  EXPECT_EQ(lit, 1);
  const Image blurred = test::render(point_scene(focus + 10, radius * 5, 0.5f, focus, size), samples(256));
  int blurred_lit = 0;
  for (const Color& c : blurred.pixels()) blurred_lit += c.r > 0;
  EXPECT_GT(blurred_lit, 20);
}

TEST(DepthOfField, TheBlurCircleOfAPointOffFocusMatchesTheThinLensFormula) {
  // A point at depth Z with the lens focused at F spreads over a disk of diameter
  // R·|F − Z|·H / (Z·F·tan(fovy/2)) pixels: the lens disk of radius R seen from the point,
  // scaled onto the plane in focus.
  const int size = 64;
  for (const auto& [depth, focus, aperture] : {std::tuple{5.f, 10.f, 0.2f}, {20.f, 8.f, 0.15f}}) {
    const double expected = aperture * std::abs(focus - depth) * size /
                            (depth * focus * std::tan(kFovy * std::numbers::pi / 360));
    // A point whose own image is one pixel across; render only the window around it.
    const double point_pixels = 1.0;
    const float radius = float(0.5 * point_pixels * pixel_size_at(depth, size));
    JobOptions options = samples(1024);
    const int margin = int(expected / 2) + 4;
    options.render.crop = PixelRect{32 - margin, 32 - margin, 32 + margin, 32 + margin};
    const Image window = test::render(point_scene(depth, radius, aperture, focus, size), options);
    // The disk's radius from the second moment of the light: E[r²] = ρ²/2 for a uniform disk,
    // plus what the point's own disk and the pixels' width add.
    double energy = 0, cx = 0, cy = 0;
    for (int y = 0; y < window.height(); ++y)
      for (int x = 0; x < window.width(); ++x) {
        const double e = window.at(x, y).r;
        energy += e, cx += e * (x + 0.5), cy += e * (y + 0.5);
      }
    ASSERT_GT(energy, 0);
    cx /= energy, cy /= energy;
    double r2 = 0;
    int outermost = 0;
    for (int y = 0; y < window.height(); ++y)
      for (int x = 0; x < window.width(); ++x) {
        const double e = window.at(x, y).r, dx = x + 0.5 - cx, dy = y + 0.5 - cy;
        r2 += e * (dx * dx + dy * dy);
        if (e > 0) outermost = std::max(outermost, int(std::ceil(std::sqrt(dx * dx + dy * dy))));
      }
    r2 /= energy;
    const double measured = 2 * std::sqrt(2 * (r2 - point_pixels * point_pixels / 8 - 1.0 / 6));
    EXPECT_NEAR(measured, expected, 1.0) << "depth " << depth << ", focus " << focus;
    // In --gtest_output=xml, for the record.
    RecordProperty("depth_" + std::to_string(int(depth)) + "_blur_pixels",
                   std::to_string(measured) + " measured, " + std::to_string(expected) + " by the formula");
    EXPECT_NEAR(cx, margin, 0.5);
    EXPECT_NEAR(cy, margin, 0.5);
    EXPECT_LE(outermost, expected / 2 + 3) << "light outside the blur circle";
  }
}

TEST(DepthOfField, ApertureZeroIsThePinholeImageExactly) {
  RenderJob job = point_scene(10, 0.3f, 0, 0, 24, 0.2f, -0.1f);
  job.lights = {PointLight{{3, 4, 5}, {0.8f, 0.8f, 0.8f}, {1, 0, 0}}};
  job.ambient = {0.2f, 0.2f, 0.2f};
  const Image pinhole = test::render(job, samples(4));
  job.camera.focus_distance = 3;  // a focus distance alone changes nothing
  EXPECT_EQ(test::render(job, samples(4)).pixels(), pinhole.pixels());
  // --aperture 0 over a scene's lens gives the pinhole again.
  job.camera.aperture_radius = 0.4f;
  JobOptions closed = samples(4);
  closed.view.aperture_radius = 0;
  EXPECT_EQ(test::render(job, closed).pixels(), pinhole.pixels());
  EXPECT_NE(test::render(job, samples(4)).pixels(), pinhole.pixels());
}

TEST(DepthOfField, CommandLineLensOverridesTheScenes) {
  RenderJob job = point_scene(10, 0.3f, 0.3f, 4, 24);
  JobOptions options = samples(1);
  options.view = {0.1f, 12.f, std::nullopt, std::nullopt};
  const test::TestJob prepared(job, options);
  EXPECT_TRUE(prepared.prepared().camera().has_lens());
  RenderJob same = job;
  same.camera.aperture_radius = 0.1f;
  same.camera.focus_distance = 12;
  EXPECT_EQ(prepared.render().pixels(), test::render(same, samples(1)).pixels());
}

}  // namespace
}  // namespace mjray
