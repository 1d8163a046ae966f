// Lens points: the (0,2)-sequence's power-of-two prefixes put one point in every elementary
// interval, scrambled or not; the sample order is a permutation; passes and pixels differ.

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/render/lens_points.h"

namespace mjray {
namespace {

/// Whether n = 2^m points have one in every elementary interval of area 1/n: for every split
/// of m into 2^a columns × 2^b rows.
bool one_per_elementary_interval(const std::vector<LensPoint>& points) {
  const size_t n = points.size();
  int m = 0;
  while ((size_t(1) << m) < n) ++m;
  for (int a = 0; a <= m; ++a) {
    const int columns = 1 << a, rows = 1 << (m - a);
    std::vector<int> count(n, 0);
    for (const LensPoint& p : points) ++count[size_t(int(p.v * float(rows)) * columns + int(p.u * float(columns)))];
    if (std::any_of(count.begin(), count.end(), [](int c) { return c != 1; })) return false;
  }
  return true;
}

TEST(LensPoints, EveryPowerOfTwoPassHasOnePointInEveryElementaryInterval) {
  for (const uint32_t n : {1u, 2u, 16u, 64u, 256u, 1024u})
    for (const uint64_t pixel : {0ull, 7ull, 123456ull}) {
      const LensPoints lens(5, pixel, 16, n);
      std::vector<LensPoint> points;
      for (uint32_t k = 0; k < n; ++k) {
        points.push_back(lens.at(k));
        ASSERT_GE(points.back().u, 0.f);
        ASSERT_LT(points.back().u, 1.f);
        ASSERT_GE(points.back().v, 0.f);
        ASSERT_LT(points.back().v, 1.f);
      }
      EXPECT_TRUE(one_per_elementary_interval(points)) << n << " points, pixel " << pixel;
    }
}

TEST(LensPoints, TheUnscrambledSequenceIsTheZeroTwoSequence) {
  // The first points of the (0,2)-sequence, as fractions of 2^32.
  const std::vector<std::pair<double, double>> expected = {{0, 0}, {0.5, 0.5}, {0.25, 0.75}, {0.75, 0.25},
                                                           {0.125, 0.625}, {0.625, 0.125}};
  for (uint32_t i = 0; i < expected.size(); ++i) {
    EXPECT_DOUBLE_EQ(van_der_corput_bits(i) * 0x1p-32, expected[i].first) << i;
    EXPECT_DOUBLE_EQ(sobol_second_bits(i) * 0x1p-32, expected[i].second) << i;
  }
}

TEST(LensPoints, PermutationElementIsABijectionForEveryKeyAndSize) {
  for (const uint32_t n : {1u, 3u, 16u, 100u, 1000u})
    for (const uint32_t key : {0u, 1u, 0xdeadbeefu}) {
      std::vector<uint32_t> seen(n, 0);
      for (uint32_t i = 0; i < n; ++i) ++seen[permutation_element(i, n, key)];
      EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](uint32_t c) { return c == 1; })) << n << " " << key;
    }
  // And the order depends on the key.
  std::vector<uint32_t> a, b;
  for (uint32_t i = 0; i < 16; ++i) a.push_back(permutation_element(i, 16, 1)), b.push_back(permutation_element(i, 16, 2));
  EXPECT_NE(a, b);
}

TEST(LensPoints, PixelsAndPassesGetTheirOwnPoints) {
  const LensPoints a(0, 10, 16, 16), other_pixel(0, 11, 16, 16), other_pass(0, 10, 32, 16), other_seed(1, 10, 16, 16);
  for (const LensPoints* b : {&other_pixel, &other_pass, &other_seed}) {
    int same = 0;
    for (uint32_t k = 0; k < 16; ++k) same += a.at(k).u == b->at(k).u && a.at(k).v == b->at(k).v;
    EXPECT_LT(same, 16);
  }
  EXPECT_EQ(LensPoints(0, 10, 16, 16).at(3).u, a.at(3).u);  // a function of its keys alone
}

}  // namespace
}  // namespace mjray
