// The report's "bad pixel" rule: a pixel is bad when any channel differs from a neighbour's by
// more than the threshold, so an edge in one channel only (a blue object on black) is found.

#include "mjray/render/adaptive_antialiasing.h"

#include <vector>

#include <gtest/gtest.h>

namespace mjray {
namespace {

/// 6 × 4 pixels: `left` in columns 0-2, `right` in columns 3-5.
Image edge(Color left, Color right) {
  Image image(6, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 6; ++x) image.at(x, y) = x < 3 ? left : right;
  return image;
}

TEST(AdaptiveAntialiasing, AnEdgeInAnyOneChannelMakesBadPixelsOnBothSides) {
  for (const Color right : {Color(0.5f, 0, 0), Color(0, 0.5f, 0), Color(0, 0, 0.5f)}) {
    SCOPED_TRACE(std::to_string(right.r) + " " + std::to_string(right.g) + " " + std::to_string(right.b));
    const Image image = edge({0, 0, 0}, right);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 6; ++x) EXPECT_EQ(is_bad_pixel(image, x, y, 0.1f), x == 2 || x == 3) << x << "," << y;
  }
}

TEST(AdaptiveAntialiasing, DifferencesAtOrBelowTheThresholdAreNotBad) {
  const Image image = edge({0.2f, 0.2f, 0.2f}, {0.3f, 0.25f, 0.3f});
  for (int x = 0; x < 6; ++x) EXPECT_FALSE(is_bad_pixel(image, x, 1, 0.11f)) << x;
  EXPECT_TRUE(is_bad_pixel(image, 2, 1, 0.09f));
}

TEST(AdaptiveAntialiasing, TheFirstPassSupersamplesABlueEdgeAndItsNeighbours) {
  const Image image = edge({0, 0, 0}, {0, 0, 1});
  std::vector<uint8_t> none(6 * 4, 0);
  std::vector<int> expected;
  for (int y = 0; y < 4; ++y)
    for (int x = 1; x <= 4; ++x) expected.push_back(y * 6 + x);
  EXPECT_EQ(next_supersample_set(image, 0.1f, none), expected);
}

}  // namespace
}  // namespace mjray
