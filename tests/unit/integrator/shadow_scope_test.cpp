// The shadow scope of an area light: where it hands every sample one shared origin, that is
// the origin spawn_ray_to gives each sample's shadow ray, bit for bit.

#include "mjray/integrator/shadow_scope.h"

#include <random>

#include <gtest/gtest.h>

#include "mjray/accel/bvh.h"
#include "mjray/geometry/spawn_ray.h"
#include "support/random_vectors.h"

namespace mjray {
namespace {

TEST(ShadowScope, TheSharedOriginIsSpawnRayTosForEverySample) {
  // Random surfaces and lights, some lights nearly in the surface's plane; one triangle far
  // away, so that the scope is searched through a real accelerator.
  PrimitiveSet prims;
  prims.add_triangles({{100, 100, 100}, {101, 100, 100}, {100, 101, 100}}, {{0, 1, 2}});
  const Bvh bvh(prims, 1);
  std::mt19937 rng(488);
  std::uniform_real_distribution<float> uniform(0, 1);
  int shared = 0, straddling = 0, grazing = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    SurfaceInteraction si;
    si.point = Point3{20 * uniform(rng), 20 * uniform(rng), 20 * uniform(rng)};
    si.point_error = Vector3{uniform(rng), uniform(rng), uniform(rng)} * 1e-5f;
    const Vector3 n = test::random_unit_vector(rng);
    si.geometric_normal = si.shading_normal = Normal3{n.x, n.y, n.z};
    si.prim = 7;  // not in the accelerator: nothing of the surface's own to find
    // A light anywhere around, or close to the tangent plane (within a few degrees).
    Vector3 to_light = test::random_unit_vector(rng) * (1 + 10 * uniform(rng));
    if (trial % 3 == 0) to_light = to_light - Vector3(n) * (dot(n, to_light) * (1 - 0.05f * uniform(rng)));
    const Vector3 e1 = test::random_unit_vector(rng) * (0.05f + uniform(rng)), e2 = test::random_unit_vector(rng) * (0.05f + uniform(rng));
    const Light light = AreaLight{si.point + to_light - e1 * 0.5f - e2 * 0.5f, e1, e2, {1, 1, 1}, {1, 0, 0}};
    const ShadowScope scope(prims, bvh, &bvh, si, light, ShadowScope::kNoPrimitive);
    const Point3* origin = scope.shared_origin();
    if (!origin) {
      ++straddling;
      continue;
    }
    ++shared;
    grazing += std::abs(dot(n, normalize(to_light))) < 0.1f;
    for (int k = 0; k < 128 + 4; ++k) {
      const Point2 u = k < 128 ? Point2{uniform(rng), uniform(rng)} : Point2{float(k & 1), float((k >> 1) & 1)};
      const Ray ray = spawn_ray_to(si, sample_li(light, si.point, u).position);
      ASSERT_EQ(ray.origin, *origin) << "trial " << trial << ", sample " << k;
    }
  }
  EXPECT_GT(shared, 1500);
  EXPECT_GT(straddling, 50);
  EXPECT_GT(grazing, 100);
}

}  // namespace
}  // namespace mjray
