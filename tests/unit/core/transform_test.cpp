#include "mjray/core/transform.h"

#include <gtest/gtest.h>

namespace mjray {
namespace {

void expect_near(const Point3& a, const Point3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Transform, TranslateThenScaleDependsOnOrder) {
  const Transform t = Transform::translate({1, 2, 3});
  const Transform s = Transform::scale(2, 2, 2);
  // (t·s)(p) scales first; (s·t)(p) translates first.
  expect_near((t * s)(Point3(1, 1, 1)), {3, 4, 5});
  expect_near((s * t)(Point3(1, 1, 1)), {4, 6, 8});
}

TEST(Transform, InverseUndoesComposition) {
  const Transform m = Transform::translate({1, -2, 5}) * Transform::rotate(1, 33) * Transform::scale(2, 0.5f, 3);
  const Point3 p(0.3f, -0.7f, 2.1f);
  expect_near(m.inverse()(m(p)), p);
  expect_near(m(m.inverse()(p)), p);
}

TEST(Transform, RotationIsRightHanded) {
  // Counter-clockwise looking down each axis: x→y about z, y→z about x, z→x about y.
  expect_near(Transform::rotate(2, 90)(Point3(1, 0, 0)), {0, 1, 0});
  expect_near(Transform::rotate(0, 90)(Point3(0, 1, 0)), {0, 0, 1});
  expect_near(Transform::rotate(1, 90)(Point3(0, 0, 1)), {1, 0, 0});
}

TEST(Transform, VectorsIgnoreTranslation) {
  const Transform m = Transform::translate({5, 5, 5}) * Transform::scale(2, 3, 4);
  const Vector3 v = m(Vector3(1, 1, 1));
  EXPECT_FLOAT_EQ(v.x, 2);
  EXPECT_FLOAT_EQ(v.y, 3);
  EXPECT_FLOAT_EQ(v.z, 4);
}

TEST(Transform, NormalStaysPerpendicularUnderNonUniformScale) {
  // The plane x + y = 0 has normal (1,1,0) and tangents (1,-1,0), (0,0,1).
  const Transform m = Transform::rotate(0, 20) * Transform::scale(4, 1, 0.5f);
  const Normal3 n = m(Normal3(1, 1, 0));
  const Vector3 t1 = m(Vector3(1, -1, 0)), t2 = m(Vector3(0, 0, 1));
  EXPECT_NEAR(dot(n, t1), 0, 1e-5f);
  EXPECT_NEAR(dot(n, t2), 0, 1e-5f);
  // Transforming the normal like a vector would be wrong here.
  EXPECT_GT(std::abs(dot(normalize(m(Vector3(1, 1, 0))), normalize(t1))), 0.5f);
}

TEST(Transform, BoundsContainTransformedCorners) {
  const Transform m = Transform::rotate(2, 45);
  const Bounds3 b = m(Bounds3{{0, 0, 0}, {1, 1, 1}});
  EXPECT_NEAR(b.lo.x, -std::sqrt(0.5f), 1e-5f);
  EXPECT_NEAR(b.hi.x, std::sqrt(0.5f), 1e-5f);
  EXPECT_NEAR(b.lo.y, 0, 1e-5f);
  EXPECT_NEAR(b.hi.y, std::sqrt(2.f), 1e-5f);
}

}  // namespace
}  // namespace mjray
