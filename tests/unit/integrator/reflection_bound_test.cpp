// Lights a surface reflects none of: ruled out only where every sample's Phong term is
// exactly zero, so that skipping them changes no bit of an image.

#include "mjray/integrator/reflection_bound.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "support/random_vectors.h"

namespace mjray {
namespace {

/// The Phong term of the light sample at u, as the integrator computes it.
Color reflected(const LocalShading& local, const ShadingFrame& frame, const Point3& point, const Light& light,
                Point2 u) {
  const LightSample sample = sample_li(light, point, u);
  const Vector3 to_light = sample.position - point;
  const float distance = length(to_light);
  if (!(distance > 0)) return {};
  const Vector3 l = to_light / distance;
  const float n_dot_l = dot(frame.n, l);
  if (n_dot_l <= 0) return {};
  return local.phong(frame, l, n_dot_l) * sample.intensity;
}

const AreaLight kSquareLight{{-0.5f, 10, -0.5f}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1}, {1, 0, 0}};

ShadingFrame looking_down_at_floor(const Vector3& wo) { return {wo, Normal3{0, 1, 0}, Normal3{0, 1, 0}}; }

TEST(ReflectionBound, OnlyASurfaceWithoutDiffusePartFarFromItsHighlightReflectsNothing) {
  const Point3 origin{0, 0, 0};
  const LocalShading glass{{0, 0, 0}, {0.8f, 0.8f, 0.8f}, 500};
  // Viewed straight down, the highlight of a light straight above is in the mirror direction.
  EXPECT_TRUE(may_reflect(glass, looking_down_at_floor({0, 1, 0}), origin, kSquareLight));
  // Viewed from 45°, the mirror direction is 45° from the light: x^500 for x ≤ cos 40° is 0.
  EXPECT_FALSE(may_reflect(glass, looking_down_at_floor(normalize(Vector3{1, 1, 0})), origin, kSquareLight));
  EXPECT_FALSE(may_reflect(glass, looking_down_at_floor(normalize(Vector3{1, 1, 0})), origin,
                               PointLight{{0, 10, 0}, {1, 1, 1}, {1, 0, 0}}));
  // A diffuse part reflects every light above the surface; a low shininess, a broad highlight.
  EXPECT_TRUE(may_reflect({{0.1f, 0, 0}, {0.8f, 0.8f, 0.8f}, 500}, looking_down_at_floor(normalize(Vector3{1, 1, 0})),
                                origin, kSquareLight));
  EXPECT_TRUE(may_reflect({{0, 0, 0}, {0.8f, 0.8f, 0.8f}, 5}, looking_down_at_floor(normalize(Vector3{1, 1, 0})),
                                origin, kSquareLight));
  // Black terms reflect nothing from anywhere.
  EXPECT_FALSE(may_reflect({{0, 0, 0}, {0, 0, 0}, 10}, looking_down_at_floor({0, 1, 0}), origin, kSquareLight));
  // A light whose intensity may be infinite (no falloff at all) is always sampled: 0·∞ is not 0.
  const AreaLight unbounded{{-0.5f, 10, -0.5f}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1}, {0, 0, 0}};
  EXPECT_TRUE(may_reflect(glass, looking_down_at_floor(normalize(Vector3{1, 1, 0})), origin, unbounded));
}

TEST(ReflectionBound, EverySampleOfALightRuledOutIsExactlyBlack) {
  // Random surfaces, viewers and lights: wherever a light is ruled out, 256 jittered
  // samples of it (and its corners) must all reflect exactly zero. Enough are ruled out,
  // some close to their limit, for the check to mean something.
  std::mt19937 rng(2026);
  std::uniform_real_distribution<float> uniform(0, 1);
  int ruled_out = 0, near_limit = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vector3 n = test::random_unit_vector(rng);
    Vector3 wo = test::random_unit_vector(rng);
    if (dot(wo, n) < 0) wo = -wo;
    const ShadingFrame frame{wo, Normal3{n.x, n.y, n.z}, Normal3{n.x, n.y, n.z}};
    const float shininess = std::pow(10.f, 1 + 3 * uniform(rng));  // 10 to 10,000
    const LocalShading local{{0, 0, 0}, {0.8f, 0.5f, 1}, shininess};
    const Point3 point{uniform(rng), uniform(rng), uniform(rng)};
    const Vector3 to_light = test::random_unit_vector(rng) * (2 + 10 * uniform(rng));
    const Vector3 edge1 = test::random_unit_vector(rng) * (0.1f + 3 * uniform(rng)), edge2 = test::random_unit_vector(rng) * (0.1f + 3 * uniform(rng));
    // Every other light a point: its one direction tests the bound's edge most closely.
    const Light light = trial % 2 ? Light(PointLight{point + to_light, {1, 1, 1}, {1, 0.1f, 0.01f}})
                                  : Light(AreaLight{point + to_light - edge1 * 0.5f - edge2 * 0.5f, edge1, edge2,
                                                    {1, 1, 1}, {1, 0.1f, 0.01f}});
    if (may_reflect(local, frame, point, light)) continue;
    ++ruled_out;
    float brightest_cos = 0;
    for (int k = 0; k < 256 + 4; ++k) {
      const Point2 u = k < 256 ? Point2{uniform(rng), uniform(rng)} : Point2{float(k & 1), float((k >> 1) & 1)};
      ASSERT_EQ(reflected(local, frame, point, light, u), Color(0, 0, 0)) << "trial " << trial << ", sample " << k;
      const Vector3 l = normalize(sample_li(light, point, u).position - point);
      brightest_cos = std::max(brightest_cos, dot(Vector3(n) * (2 * dot(n, l)) - l, wo));
    }
    // Within a factor of 2^60 of the smallest float: the bound did not give up much.
    near_limit += std::pow(double(brightest_cos), double(shininess)) > 0x1p-260;
  }
  EXPECT_GT(ruled_out, 1000);
  EXPECT_GT(near_limit, 20);
}

}  // namespace
}  // namespace mjray
