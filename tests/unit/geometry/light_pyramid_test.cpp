#include "mjray/geometry/light_pyramid.h"

#include <random>

#include <gtest/gtest.h>

namespace mjray {
namespace {

// A unit square light at height 10 above the origin.
LightPyramid square_light_from_origin() {
  const auto pyramid = LightPyramid::make({0, 0, 0}, {Point3{-0.5f, 10, -0.5f}, Point3{0.5f, 10, -0.5f},
                                                      Point3{0.5f, 10, 0.5f}, Point3{-0.5f, 10, 0.5f}});
  EXPECT_TRUE(pyramid.has_value());
  return *pyramid;
}

TEST(LightPyramid, BoxesBesideOrBeyondThePyramidAreOutsideAndBoxesOnItsAxisAreNot) {
  const LightPyramid p = square_light_from_origin();
  EXPECT_FALSE(p.outside(Bounds3{{-0.1f, 4, -0.1f}, {0.1f, 5, 0.1f}}));   // on the axis
  EXPECT_TRUE(p.outside(Bounds3{{0.4f, 4, -0.1f}, {0.6f, 5, 0.1f}}));     // at y = 5 the pyramid ends at x = 0.25
  EXPECT_FALSE(p.outside(Bounds3{{0.2f, 4, -0.1f}, {0.6f, 5, 0.1f}}));    // reaches into it
  EXPECT_TRUE(p.outside(Bounds3{{-0.1f, 10.5f, -0.1f}, {0.1f, 11, 0.1f}}));  // beyond the light
  EXPECT_TRUE(p.outside(Bounds3{{-0.1f, -2, -0.1f}, {0.1f, -1, 0.1f}}));     // behind the apex
}

TEST(LightPyramid, EightBoxesAtOnceAnswerAsOneAtATime) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0, 1), coordinate(-2, 12);
  for (int k = 0; k < 200; ++k) {
    const Point3 apex{coordinate(rng) * 0.2f, coordinate(rng) * 0.2f, coordinate(rng) * 0.2f};
    const Point3 corner{coordinate(rng), 10 + unit(rng), coordinate(rng)};
    const Vector3 e1(1 + unit(rng), unit(rng) * 0.2f, 0), e2(0, unit(rng) * 0.2f, 1 + unit(rng));
    const auto pyramid = LightPyramid::make(apex, {corner, corner + e1, corner + e1 + e2, corner + e2});
    if (!pyramid) continue;
    std::array<std::array<float, 8>, 6> rows;
    std::array<Bounds3, 8> boxes;
    for (size_t i = 0; i < 8; ++i) {
      const Point3 a{coordinate(rng), coordinate(rng), coordinate(rng)};
      const Vector3 size(unit(rng) * 3, unit(rng) * 3, unit(rng) * 3);
      boxes[i] = i == 7 ? Bounds3{} : Bounds3{a, a + size};  // the last one empty, as an unused slot
      for (int axis = 0; axis < 3; ++axis) {
        rows[size_t(axis)][i] = boxes[i].lo[axis];
        rows[size_t(axis) + 3][i] = boxes[i].hi[axis];
      }
    }
    const unsigned mask = pyramid->outside(rows);
    for (size_t i = 0; i < 7; ++i) EXPECT_EQ((mask >> i) & 1, unsigned(pyramid->outside(boxes[i]))) << k << " " << i;
    EXPECT_EQ((mask >> 7) & 1, 1u) << "an empty box is outside";
  }
}

}  // namespace
}  // namespace mjray
