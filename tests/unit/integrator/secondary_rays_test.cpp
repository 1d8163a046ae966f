// Reflection and refraction through the integrator, with closed-form expectations and the
// -r / -f depth limits.

#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

struct Traced {
  Color colour;
  RayCounters rays;
};

/// Traces one ray through a scene with brute force.
Traced trace(const RenderJob& job, const Ray& ray, IntegratorSettings settings = {}) {
  Traced t;
  t.colour = test::TestJob(job, test::oracle_options(settings)).radiance(ray, &t.rays);
  return t;
}

RenderJob scene(std::shared_ptr<const SceneNode> root) {
  RenderJob job;
  job.root = std::move(root);
  job.lights = {PointLight{{0, 50, 0}, {0, 0, 0}, {1, 0, 0}}};  // dark: only ambient and bounces
  return job;
}

const Ray kDown{{0, 5, 0}, {0, -1, 0}};

TEST(SecondaryRays, MirrorShowsWhatIsAboveWeightedByReflectivity) {
  RenderJob job = scene(test::mesh(test::floor_quad(50), ReflectiveMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 0.5f}));
  const Traced t = trace(job, kDown);
  const Color sky = job.background.zenith;  // the mirror sends the ray straight up
  EXPECT_NEAR(t.colour.r, 0.5f * sky.r, 1e-6f);
  EXPECT_NEAR(t.colour.b, 0.5f * sky.b, 1e-6f);
  EXPECT_EQ(t.rays.secondary, 1u);
  EXPECT_EQ(trace(job, kDown, {0, 8}).colour, Color(0, 0, 0));  // -r 0: no reflection
}

TEST(SecondaryRays, DepthLimitsCountReflectionsBetweenParallelMirrors) {
  const Material mirror = ReflectiveMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 0.9f};
  RenderJob job = scene(test::group({test::box({-50, -1, -50}, {50, 0, 50}, mirror),
                                     test::box({-50, 10, -50}, {50, 11, 50}, mirror)}));
  for (const int depth : {0, 1, 3, 7}) {
    const Traced t = trace(job, {{0, 5, 0}, {0, -1, 0}}, {depth, 8});
    // -r N traces N reflections, then one terminal look along the last lobe (none for -r 0).
    EXPECT_EQ(t.rays.secondary, uint64_t(depth + (depth > 0 ? 1 : 0))) << "-r " << depth;
    EXPECT_EQ(t.colour, Color(0, 0, 0));  // nothing but black mirrors to see
  }
}

TEST(SecondaryRays, RefractionThroughASlabSeesTheFloorBelow) {
  const Material glass = RefractiveMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 0, 1, 1.5f};
  const Material floor = PhongMaterial{{0.4f, 0.6f, 0.8f}, {0, 0, 0}, 1};
  RenderJob job = scene(test::group({test::box({-5, 1, -5}, {5, 2, 5}, glass),
                                     test::mesh(test::floor_quad(50), floor)}));
  job.ambient = {1, 1, 1};
  // Straight down: the ray passes both faces undeviated and sees the floor's ambient colour.
  const Traced t = trace(job, kDown);
  EXPECT_NEAR(t.colour.r, 0.4f, 1e-6f);
  EXPECT_NEAR(t.colour.g, 0.6f, 1e-6f);
  EXPECT_EQ(t.rays.secondary, 2u);  // into the slab, out of it
  EXPECT_EQ(trace(job, kDown, {8, 0}).colour, Color(0, 0, 0));  // -f 0: no transmission
  // -f 1: into the slab, then past the limit a straight look out of it, which sees the floor.
  const Traced limited = trace(job, kDown, {8, 1});
  EXPECT_EQ(limited.rays.secondary, 2u);
  EXPECT_NEAR(limited.colour.b, 0.8f, 1e-6f);
}

TEST(SecondaryRays, RayStartingInsideGlassRefractsOut) {
  // From inside a glass sphere the ray leaves through the far side: entering vs leaving is
  // decided by the geometric normal, so it exits toward the floor below.
  const Material glass = RefractiveMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 0, 1, 1.5f};
  RenderJob job = scene(test::group({test::sphere({0, 3, 0}, 1, glass),
                                     test::mesh(test::floor_quad(50), PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1})}));
  job.ambient = {0.25f, 0.5f, 1};
  const Traced t = trace(job, {{0, 3, 0}, {0, -1, 0}});
  EXPECT_NEAR(t.colour.r, 0.25f, 1e-6f);
  EXPECT_NEAR(t.colour.b, 1.f, 1e-6f);
}

TEST(SecondaryRays, ReflectRefractBlendsByKr) {
  // A thin slab of index 1 (no bending) over a white ambient floor, under the sky.
  const float kr = 0.3f;
  const Material blend = RefractiveMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, kr, 1, 1};
  RenderJob job = scene(test::group({test::box({-5, 1, -5}, {5, 2, 5}, blend),
                                     test::mesh(test::floor_quad(50), PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1})}));
  job.ambient = {1, 1, 1};
  const Traced t = trace(job, kDown, {1, 8});  // -r 1: one reflection per path
  // Top face: Kr·sky + (1−Kr)·inside. Inside, the bottom face splits again: Kr back up and
  // (1−Kr) to the floor. Going up, the top face splits once more: (1−Kr) to the sky, and Kr
  // past the -r 1 limit, which ends in a terminal look straight down through the bottom face
  // (keeping 1 − Kr) at the floor.
  const float sky = job.background.zenith.r;
  const float up = kr * (1 - kr) * 1 + (1 - kr) * sky;
  const float inside = kr * up + (1 - kr) * 1;
  EXPECT_NEAR(t.colour.r, kr * sky + (1 - kr) * inside, 1e-5f);
}

TEST(SecondaryRays, TotalInternalReflectionSendsAllLightBack) {
  // Inside glass looking up at 60° from the normal: beyond the critical angle (41.8°).
  const Material glass = FresnelMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 1, 1.5f};
  RenderJob job = scene(test::box({-50, -1, -50}, {50, 1, 50}, glass));
  const float s = std::sin(1.047f), c = std::cos(1.047f);
  const Traced t = trace(job, {{0, 0, 0}, {s, c, 0}}, {1, 8});
  // No transmission at the top face: its one reflection (-r 1), then at the bottom face, past
  // the limit, a terminal look that crosses the top face and leaves: 3 secondary rays.
  EXPECT_EQ(t.rays.secondary, 3u);
}

TEST(SecondaryRays, NegligibleBranchesArePrunedSoGlassStaysCheap) {
  // Fresnel glass splits every ray in two; with -r 30 -f 30 the full tree would have 2^60
  // leaves. Branches whose weight in the pixel falls below half an 8-bit step are not traced.
  const Material glass = FresnelMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 1, 1.5f};
  RenderJob job = scene(test::group({test::sphere({0, 0, 0}, 2, glass), test::sphere({0, 0, 0}, 1, glass),
                                     test::box({-3, -3, -3}, {3, 3, 3}, glass)}));
  const Traced t = trace(job, {{0.3f, 0.2f, 10}, {0, 0, -1}}, {30, 30});
  EXPECT_GT(t.rays.secondary, 10u);
  EXPECT_LT(t.rays.secondary, 2000u);
}

}  // namespace
}  // namespace mjray
