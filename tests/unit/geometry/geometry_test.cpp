// Geometry invariants: closed meshes trap rays, spawned rays never re-hit their origin,
// shared edges are watertight, NaN/Inf rays are harmless.

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "mjray/accel/brute_force.h"
#include "mjray/geometry/box.h"
#include "mjray/geometry/primitive_set.h"
#include "mjray/geometry/sphere.h"
#include "mjray/geometry/triangle.h"
#include "mjray/geometry/spawn_ray.h"
#include "mjray/scene/flatten.h"
#include "support/random_vectors.h"
#include "support/scene_builder.h"

namespace mjray {
namespace {

World world_of(std::shared_ptr<const SceneNode> root) {
  RenderJob job;
  job.root = std::move(root);
  return flatten(job);
}

TEST(Geometry, UnitSphereHitsAtClosedFormDistance) {
  const auto t = intersect_unit_sphere({{0, 0, 5}, {0, 0, -1}}, {});
  ASSERT_TRUE(t);
  EXPECT_FLOAT_EQ(*t, 4);
  const auto inside = intersect_unit_sphere({{0, 0, 0}, {0, 0, -2}}, {});
  ASSERT_TRUE(inside);
  EXPECT_FLOAT_EQ(*inside, 0.5f);  // t measured in units of the unnormalised direction
  EXPECT_FALSE(intersect_unit_sphere({{0, 0, 5}, {0, 0, -1}}, {0, 3.9f}));
  EXPECT_FALSE(intersect_unit_sphere({{0, 2, 5}, {0, 0, -1}}, {}));
}

TEST(Geometry, UnitCubeHitsEntryFromOutsideAndExitFromInside) {
  const auto outside = intersect_unit_cube({{0.5f, 0.5f, 3}, {0, 0, -1}}, {});
  ASSERT_TRUE(outside);
  EXPECT_FLOAT_EQ(*outside, 2);
  const auto inside = intersect_unit_cube({{0.5f, 0.5f, 0.5f}, {1, 0, 0}}, {});
  ASSERT_TRUE(inside);
  EXPECT_FLOAT_EQ(*inside, 0.5f);
  EXPECT_EQ(unit_cube_face({1, 0.5f, 0.2f}).axis, 0);
  EXPECT_EQ(unit_cube_face({1, 0.5f, 0.2f}).side, 1);
  // Axis-parallel ray grazing outside the slab misses.
  EXPECT_FALSE(intersect_unit_cube({{1.5f, 0.5f, 3}, {0, 0, -1}}, {}));
}

TEST(Geometry, RaysFromInsideClosedMeshAlwaysHit) {
  const World world = world_of(test::mesh(test::uv_sphere(24, 48), default_material(),
                                          Transform::translate({3, -2, 7}) * Transform::scale(2, 1, 3)));
  const BruteForce accel(world.primitives);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0, 0.9f);
  for (int i = 0; i < 20000; ++i) {
    // A point inside the ellipsoid (the polygonal sphere holds the sphere of radius 0.99).
    const Vector3 offset = test::random_unit_vector(rng) * u(rng);
    const Point3 inside(3 + 2 * offset.x, -2 + offset.y, 7 + 3 * offset.z);
    ASSERT_TRUE(accel.intersect({inside, test::random_unit_vector(rng)}, {})) << "ray " << i;
  }
}

TEST(Geometry, SpawnedRaysNeverReHitTheirSurface) {
  // Far from the origin, where float rounding of hit points is largest.
  const Transform far = Transform::translate({1000, 500, -2000});
  const World world = world_of(test::group(
      {test::sphere({0, 0, 0}, 3), test::box({5, -2, -2}, {9, 2, 2}),
       test::mesh(test::uv_sphere(16, 32), default_material(), Transform::translate({-8, 0, 0}) * Transform::scale(3, 3, 3))},
      far));
  const BruteForce accel(world.primitives);
  std::mt19937 rng(11);
  const Point3 centre = far(Point3(0, 0, 0));
  int spawned = 0;
  for (int i = 0; i < 20000; ++i) {
    const Point3 origin = centre + test::random_unit_vector(rng) * 40.f;
    const Point3 target = far(Point3(std::uniform_real_distribution<float>(-10, 10)(rng), 0, 0));
    const Ray aimed{origin, normalize(target - origin)};
    const auto hit = accel.intersect(aimed, {});
    if (!hit) continue;
    const SurfaceInteraction si = world.interaction(aimed, *hit);
    // Leave on the side the ray came from, in a random direction of that hemisphere.
    Vector3 d = test::random_unit_vector(rng);
    if (dot(d, si.geometric_normal) * dot(aimed.direction, si.geometric_normal) > 0) d = -d;
    const auto again = accel.intersect(spawn_ray(si, d), {});
    if (again) {
      EXPECT_NE(again->prim, hit->prim) << "re-hit at t=" << again->t;
    }
    ++spawned;
  }
  EXPECT_GT(spawned, 5000);
}

TEST(Geometry, TrianglesAreWatertightOnSharedEdgesAndVertices) {
  // A fan of 8 triangles around a centre vertex: rays through the centre, every shared
  // edge and every vertex must hit at least one of them.
  std::vector<Point3> ring;
  for (int i = 0; i < 8; ++i) {
    const float a = float(i) * 0.785398163f;
    ring.push_back({std::cos(a) * 1.7f + 0.13f, std::sin(a) * 0.9f - 0.21f, 0.37f});
  }
  const Point3 centre(0.13f, -0.21f, 0.37f);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0, 1);
  int rays = 0;
  for (int i = 0; i < 8; ++i) {
    const Point3& a = ring[size_t(i)];
    for (const float s : {0.f, 0.25f, 0.5f, 0.75f, 0.999f}) {
      const Point3 target = centre + (a - centre) * s;
      for (int k = 0; k < 50; ++k) {
        const Point3 origin(u(rng) * 4 - 2, u(rng) * 4 - 2, 3 + u(rng));
        const Ray ray{origin, target - origin};
        bool hit = false;
        for (int j = 0; j < 8 && !hit; ++j)
          hit = intersect_triangle(ray, {}, centre, ring[size_t(j)], ring[size_t((j + 1) % 8)]).has_value();
        ASSERT_TRUE(hit) << "edge " << i << " at " << s;
        ++rays;
      }
    }
  }
  EXPECT_EQ(rays, 8 * 5 * 50);
}

TEST(Geometry, NanAndInfRaysReturnNoHit) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = kInfinity;
  const World world = world_of(test::group({test::sphere({0, 0, 0}, 1), test::box({2, 0, 0}, {3, 1, 1}),
                                            test::mesh(test::floor_quad(5))}));
  const BruteForce accel(world.primitives);
  const Ray bad[] = {{{nan, 0, 5}, {0, 0, -1}}, {{0, 0, 5}, {nan, nan, nan}}, {{0, 0, 5}, {0, 0, 0}},
                     {{inf, 0, 5}, {0, 0, -1}}, {{0, 0, 5}, {inf, 0, -inf}}, {{-inf, -inf, -inf}, {1, 1, 1}}};
  for (const Ray& ray : bad) {
    EXPECT_FALSE(accel.intersect(ray, {}));
    EXPECT_FALSE(accel.occluded(ray, kInfinity));
  }
}

// Accelerators cull a shape by its world box, and a shape's hit is found in its own frame
// from the world ray mapped and rounded there: every hit must lie within the box's slabs as
// the ray sees them, or a hit that a test of every primitive finds is lost. Large, offset
// shapes seen from far away round the most.
TEST(Geometry, ShapeHitsLieWithinTheirWorldBoxes) {
  PrimitiveSet set;
  set.add_shape(UnitCube{}, Transform::translate({-30, -60, -30}) * Transform::scale(60, 60, 60));
  set.add_shape(UnitSphere{}, Transform::translate({200, 5, -70}) * Transform::scale(40, 25, 40));
  std::mt19937 rng(41);
  std::uniform_real_distribution<float> unit(0, 1);
  int hits = 0, outside = 0;
  for (uint32_t prim = 0; prim < set.size(); ++prim) {
    const Bounds3 box = set.primitive_bounds(prim);
    for (int i = 0; i < 200000; ++i) {
      // Aim at a point on the box's top face from up to 1000 units away, mostly grazing.
      const Point3 target{box.lo.x + unit(rng) * (box.hi.x - box.lo.x), box.hi.y - unit(rng) * unit(rng) * 2,
                          box.lo.z + unit(rng) * (box.hi.z - box.lo.z)};
      const Vector3 away = test::random_unit_vector(rng);
      const Ray ray{target + away * (1 + 1000 * unit(rng)), -away};
      const auto hit = set.intersect(prim, ray, {});
      if (!hit) continue;
      ++hits;
      float t_near = 0, t_far = kInfinity;
      for (int a = 0; a < 3; ++a) {
        const float t0 = (box.lo[a] - ray.origin[a]) / ray.direction[a];
        const float t1 = (box.hi[a] - ray.origin[a]) / ray.direction[a];
        t_near = std::max(t_near, std::min(t0, t1));
        t_far = std::min(t_far, std::max(t0, t1));
      }
      outside += hit->t < t_near || hit->t > t_far;
    }
  }
  EXPECT_GT(hits, 100000);
  EXPECT_EQ(outside, 0);
}

TEST(Geometry, SphereUvCoversTheUnitSquare) {
  const Point2 north = unit_sphere_uv({0, 1, 0}), south = unit_sphere_uv({0, -1, 0});
  EXPECT_FLOAT_EQ(north.v, 1);
  EXPECT_FLOAT_EQ(south.v, 0);
  EXPECT_NEAR(unit_sphere_uv({1, 0, 0}).u, 0, 1e-6f);
  EXPECT_NEAR(unit_sphere_uv({0, 0, -1}).u, 0.25f, 1e-6f);
  EXPECT_NEAR(unit_sphere_uv({0, 0, 1}).u, 0.75f, 1e-6f);
  // Seen from +z, u grows to the right (toward +x) and v upward: images are not mirrored.
  EXPECT_GT(unit_sphere_uv(Point3(0.1f, 0, 0.995f)).u, unit_sphere_uv(Point3(-0.1f, 0, 0.995f)).u);
  EXPECT_GT(unit_sphere_uv(Point3(0, 0.1f, 0.995f)).v, unit_sphere_uv(Point3(0, -0.1f, 0.995f)).v);
  EXPECT_NEAR(unit_sphere_uv({-1, 0, 0}).v, 0.5f, 1e-6f);
}

}  // namespace
}  // namespace mjray
