// Subdivision of one pixel from its corners: closed-form values, which lattice points are
// sampled, and how fine the lattice is for each -a.

#include "mjray/render/subdivided_pixel.h"

#include <map>
#include <utility>

#include <gtest/gtest.h>

namespace mjray {
namespace {

/// A lattice of colours given by `f`, counting how often each point is read and sampled.
class CountingLattice {
 public:
  explicit CountingLattice(std::function<Color(int, int)> f) : f_(std::move(f)) {}

  /// Samples a point the first time it is asked for, as the image sampler does.
  const Color& operator()(int i, int j) {
    auto [at, fresh] = kept_.try_emplace({i, j});
    if (fresh) {
      at->second = f_(i, j);
      ++sampled;
    }
    return at->second;
  }
  int sampled = 0;

 private:
  std::function<Color(int, int)> f_;
  std::map<std::pair<int, int>, Color> kept_;
};

Color estimate(CountingLattice& lattice, int cells, float threshold) {
  return subdivided_estimate(0, 0, cells, threshold, [&](int i, int j) -> const Color& { return lattice(i, j); });
}

TEST(SubdividedPixel, AnUnchangingPixelCostsItsFourCornersAndKeepsTheirValue) {
  CountingLattice lattice([](int, int) { return Color{0.25f, 0.5f, 0.75f}; });
  EXPECT_EQ(estimate(lattice, 4, 0.1f), (Color{0.25f, 0.5f, 0.75f}));
  EXPECT_EQ(lattice.sampled, 4);
}

TEST(SubdividedPixel, AnEdgeIsRefinedAlongItsLengthOnly) {
  // White where the lattice column is 3 or 4 of 0..4: the right quarter of the pixel, with the
  // edge between columns 2 and 3. The left half never splits; the right half splits down to
  // single cells, whose estimates are 1/2 (columns 2..3) and 1 (columns 3..4).
  CountingLattice lattice([](int i, int) { return i >= 3 ? Color{1, 1, 1} : Color{}; });
  const Color value = estimate(lattice, 4, 0.1f);
  // (0 + (1/2 + 1 + 1/2 + 1) / 4 + 0 + (1/2 + 1 + 1/2 + 1) / 4) / 4
  EXPECT_EQ(value, (Color{0.375f, 0.375f, 0.375f}));
  // 4 corners, 5 points splitting the pixel, 5 and then 4 more splitting the right halves.
  EXPECT_EQ(lattice.sampled, 18);
}

TEST(SubdividedPixel, CornersSplitOnlyWhenAChannelSpansMoreThanTheThreshold) {
  for (const auto& [spread, splits] : {std::pair{0.25f, false}, {0.2501f, true}}) {
    CountingLattice lattice([s = spread](int i, int j) { return (i + j) == 4 ? Color{0, s, 0} : Color{}; });
    estimate(lattice, 2, 0.25f);
    EXPECT_EQ(lattice.sampled, splits ? 9 : 4) << spread;
  }
  EXPECT_FALSE(corners_differ({0, 0, 0}, {0.1f, 0.1f, 0.1f}, {0.05f, 0, 0}, {0, 0, 0.1f}, 0.1f));
  EXPECT_TRUE(corners_differ({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0.11f}, 0.1f));
}

TEST(SubdividedPixel, LatticeCellsAreAtMostOneNthOfThePixel) {
  for (const auto& [n, cells] : {std::pair{1, 1}, {2, 2}, {3, 4}, {4, 4}, {5, 8}, {8, 8}, {64, 64}})
    EXPECT_EQ(SubdivisionLattice::finest_for(n).cells(), cells) << "-a " << n;
}

}  // namespace
}  // namespace mjray
