// The gr.render camera: a thin lens focuses on its plane, starts rays on its disk, and is the
// pinhole exactly when the aperture is 0; --size keeps the vertical field of view.

#include "mjray/camera/camera.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "mjray/core/error.h"
#include "mjray/core/rng.h"
#include "mjray/core/sampling.h"

namespace mjray {
namespace {

CameraDescription tilted_camera(float aperture = 0, float focus = 0) {
  CameraDescription d;
  d.eye = {1, 2, 3};
  d.view = {0.3f, -0.2f, -1};
  d.up = {0.1f, 1, 0};
  d.fovy_degrees = 40;
  d.aperture_radius = aperture;
  d.focus_distance = focus;
  return d;
}

TEST(ThinLens, ApertureZeroIsThePinholeBitForBit) {
  const Camera pinhole(tilted_camera(), 64, 48);
  const Camera closed(tilted_camera(0, 5), 64, 48);
  EXPECT_FALSE(closed.has_lens());
  for (const auto& [x, y] : {std::pair{0.f, 0.f}, {31.5f, 20.25f}, {64.f, 48.f}})
    for (const auto& [u, v] : {std::pair{0.f, 0.f}, {0.9f, 0.1f}}) {
      const Ray a = pinhole.generate_ray(x, y), b = closed.generate_ray(x, y, u, v);
      EXPECT_EQ(a.origin, b.origin);
      EXPECT_EQ(a.direction, b.direction);
    }
}

TEST(ThinLens, EveryLensRayPassesThroughThePinholeRaysPointOnTheFocusPlane) {
  const float focus = 6.5f, radius = 0.4f;
  const Camera pinhole(tilted_camera(), 64, 48);
  const Camera lens(tilted_camera(radius, focus), 64, 48);
  ASSERT_TRUE(lens.has_lens());
  const Vector3 forward = normalize(Vector3{0.3f, -0.2f, -1});
  RandomStream random(1, 2, 3);
  for (int i = 0; i < 200; ++i) {
    const float x = 64 * random.uniform(), y = 48 * random.uniform();
    const Ray p = pinhole.generate_ray(x, y);
    // Where the pinhole ray crosses the plane focus_distance along the view direction.
    const Point3 in_focus = p.origin + p.direction * (focus / dot(p.direction, forward));
    const Ray r = lens.generate_ray(x, y, random.uniform(), random.uniform());
    // The lens point lies on the disk of the aperture, in the plane through the eye across the view.
    const Vector3 offset = r.origin - p.origin;
    EXPECT_LE(length(offset), radius * 1.0001f);
    EXPECT_NEAR(dot(offset, forward), 0, 1e-5f);
    // And the ray reaches the point in focus.
    const float t = dot(in_focus - r.origin, r.direction);
    EXPECT_LT(length(r.origin + r.direction * t - in_focus), 1e-4f * focus) << x << "," << y;
    EXPECT_NEAR(length(r.direction), 1, 1e-6f);
  }
}

TEST(ThinLens, LensPointsCoverTheDiskUniformly) {
  // Uniform on the unit disk: E[r²] = 1/2, and each quarter holds a quarter of the points.
  RandomStream random(7, 0, 0);
  double r2 = 0;
  int quadrant[4] = {0, 0, 0, 0};
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    const Point2 p = sample_concentric_disk(random.uniform(), random.uniform());
    ASSERT_LE(p.u * p.u + p.v * p.v, 1.0001f);
    r2 += p.u * p.u + p.v * p.v;
    ++quadrant[(p.u > 0 ? 1 : 0) + (p.v > 0 ? 2 : 0)];
  }
  EXPECT_NEAR(r2 / n, 0.5, 0.01);
  for (const int q : quadrant) EXPECT_NEAR(double(q) / n, 0.25, 0.01);
}

TEST(ThinLens, ALensNeedsAFiniteRadiusAndAPositiveFocusDistance) {
  EXPECT_THROW(Camera(tilted_camera(0.1f, 0), 8, 8), SceneError);
  EXPECT_THROW(Camera(tilted_camera(-0.1f, 3), 8, 8), SceneError);
  EXPECT_THROW(Camera(tilted_camera(INFINITY, 3), 8, 8), SceneError);
  EXPECT_THROW(Camera(tilted_camera(0.1f, NAN), 8, 8), SceneError);
  EXPECT_NO_THROW(Camera(tilted_camera(0, 0), 8, 8));
}

TEST(CameraSize, AnotherAspectKeepsTheVerticalFieldOfView) {
  // The top and bottom edges of the centre column are fovy apart at every size.
  const CameraDescription d = tilted_camera();
  for (const auto& [w, h] : {std::pair{64, 48}, {200, 48}, {48, 64}, {640, 360}}) {
    const Camera camera(d, w, h);
    const Vector3 top = camera.generate_ray(float(w) / 2, 0).direction;
    const Vector3 bottom = camera.generate_ray(float(w) / 2, float(h)).direction;
    EXPECT_NEAR(std::acos(dot(top, bottom)) * 180 / std::numbers::pi, 40, 1e-3) << w << "x" << h;
  }
}

}  // namespace
}  // namespace mjray
