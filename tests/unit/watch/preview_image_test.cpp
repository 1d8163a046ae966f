// The images the page shows while a frame refines: the enlarged coarse pass, and finished
// tiles laid over it.

#include <gtest/gtest.h>

#include "preview_image.h"

namespace mjray {
namespace {

Image numbered(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = Color{float(x), float(y), 0};
  return image;
}

TEST(PreviewImage, EnlargeGivesEachPixelTheCoarsePixelItFallsIn) {
  const Image coarse = numbered(3, 2);
  const Image big = enlarge(coarse, 12, 8);
  ASSERT_EQ(big.width(), 12);
  ASSERT_EQ(big.height(), 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 12; ++x) {
      EXPECT_EQ(big.at(x, y).r, float(x / 4));
      EXPECT_EQ(big.at(x, y).g, float(y / 4));
    }
  // A size that is not a multiple: the last coarse pixel still reaches the edge.
  const Image odd = enlarge(coarse, 7, 5);
  EXPECT_EQ(odd.at(6, 4).r, 2.0f);
  EXPECT_EQ(odd.at(6, 4).g, 1.0f);
  EXPECT_EQ(odd.at(0, 0).r, 0.0f);
}

TEST(PreviewImage, OnlyFinishedTilesReplaceTheUnderlay) {
  const TileLayout layout{20, 10, 8};  // 3 × 2 tiles, the last column and row narrower
  Image underlay(20, 10), snapshot(20, 10);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      underlay.at(x, y) = Color{1, 0, 0};
      snapshot.at(x, y) = Color{0, 0, 1};
    }
  const std::vector<uint8_t> finished = {1, 0, 0, 0, 0, 1};
  const Image out = overlay_finished_tiles(underlay, snapshot, finished, layout);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      const bool from_snapshot = (x < 8 && y < 8) || (x >= 16 && y >= 8);
      EXPECT_EQ(out.at(x, y).b, from_snapshot ? 1.0f : 0.0f) << x << "," << y;
    }
}

}  // namespace
}  // namespace mjray
