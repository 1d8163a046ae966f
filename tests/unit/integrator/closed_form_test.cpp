// Tiny scenes whose pixel values are known in closed form.

#include <cmath>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

/// Renders a job with brute force, as the oracle renderer.
Image render_job(const RenderJob& job) { return test::render(job); }

/// A camera straight above the origin looking down, image x along +x and image up along −z.
RenderJob looking_down(float height, int size, float fovy) {
  RenderJob job;
  job.width = job.height = size;
  job.camera = {{0, height, 0}, {0, -1, 0}, {0, 0, -1}, fovy};
  return job;
}

/// Where the ray through pixel centre (i, j) of `looking_down` meets the plane y = 0,
/// computed from the pinhole model independently of Camera.
Point3 floor_point(int i, int j, float height, int size, float fovy) {
  const double half = std::tan(double(fovy) * std::numbers::pi / 360.0);
  const double sx = (2 * (i + 0.5) / size - 1) * half, sy = (1 - 2 * (j + 0.5) / size) * half;
  return {float(sx * height), 0, float(-sy * height)};
}

TEST(ClosedForm, DiffusePlaneUnderPointLightWithFalloff) {
  const float camera_height = 10, fovy = 60;
  const int size = 9;
  const Color kd(0.6f, 0.5f, 0.4f), ambient(0.1f, 0.2f, 0.05f);
  const PointLight light{{0.7f, 2, -0.4f}, {0.9f, 1, 0.8f}, {1, 0.5f, 0.25f}};
  RenderJob job = looking_down(camera_height, size, fovy);
  job.root = test::mesh(test::floor_quad(100), PhongMaterial{kd, {0, 0, 0}, 10});
  job.ambient = ambient;
  job.lights = {light};
  const Image image = render_job(job);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      // Compute ambient⊙kd + kd·cosθ·I / (c0 + c1·d + c2·d²).
      const Point3 p = floor_point(i, j, camera_height, size, fovy);
      const Vector3 to_light = light.position - p;
      const float d = length(to_light), cos_theta = to_light.y / d;
      const float att = 1 / (1 + 0.5f * d + 0.25f * d * d);
      const Color expected = ambient * kd + kd * light.colour * (cos_theta * att);
      EXPECT_NEAR(image.at(i, j).r, expected.r, 2e-5f) << i << "," << j;
      EXPECT_NEAR(image.at(i, j).g, expected.g, 2e-5f) << i << "," << j;
      EXPECT_NEAR(image.at(i, j).b, expected.b, 2e-5f) << i << "," << j;
    }
  // The centre pixel looks straight down at the origin: d² = 0.7² + 2² + 0.4².
  const float d = std::sqrt(0.49f + 4 + 0.16f);
  EXPECT_NEAR(image.at(4, 4).g, 0.2f * 0.5f + 0.5f * (2 / d) / (1 + 0.5f * d + 0.25f * d * d), 1e-5f);
}

TEST(ClosedForm, AmbientOnlyIsAmbientTimesKd) {
  RenderJob job = looking_down(5, 3, 40);
  job.root = test::mesh(test::floor_quad(100), PhongMaterial{{0.3f, 0.5f, 0.7f}, {1, 1, 1}, 20});
  job.ambient = {0.5f, 0.4f, 1};
  job.lights = {PointLight{{0, 3, 0}, {0, 0, 0}, {1, 0, 0}}};
  const Image image = render_job(job);
  for (const Color& c : image.pixels()) {
    EXPECT_FLOAT_EQ(c.r, 0.15f);
    EXPECT_FLOAT_EQ(c.g, 0.2f);
    EXPECT_FLOAT_EQ(c.b, 0.7f);
  }
}

TEST(ClosedForm, SpecularHighlightSitsAtTheMirrorPoint) {
  // Eye above x = 0 and light above x = 4 at the same height: the mirror point is x = 2.
  const float height = 10, fovy = 60;
  const int size = 101;
  RenderJob job = looking_down(height, size, fovy);
  job.root = test::mesh(test::floor_quad(100), PhongMaterial{{0, 0, 0}, {1, 1, 1}, 2000});
  job.lights = {PointLight{{4, height, 0}, {1, 1, 1}, {1, 0, 0}}};
  const Image image = render_job(job);
  int best_i = -1, best_j = -1;
  float best = -1;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      if (image.at(i, j).r > best) best = image.at(i, j).r, best_i = i, best_j = j;
  const double half = std::tan(double(fovy) * std::numbers::pi / 360.0);
  const double expected_i = (2.0 / height / half + 1) * size / 2 - 0.5;  // pixel whose centre sees x = 2
  EXPECT_NEAR(best_i, expected_i, 0.5);
  EXPECT_EQ(best_j, size / 2);
  EXPECT_GT(best, 0.5f);
}

TEST(ClosedForm, SphereSilhouetteRadiusFollowsFovyAndDistance) {
  const float radius = 1, distance = 6, fovy = 40;
  const int size = 401;
  RenderJob job;
  job.width = job.height = size;
  job.camera = {{0, 0, distance}, {0, 0, -1}, {0, 1, 0}, fovy};
  job.root = test::sphere({0, 0, 0}, radius, PhongMaterial{{1, 0, 0}, {0, 0, 0}, 1});
  job.ambient = {1, 1, 1};
  job.lights = {PointLight{{0, 0, 10}, {0, 0, 0}, {1, 0, 0}}};
  const Image image = render_job(job);
  // Background pixels have green > 0; the sphere is pure red.
  int covered = 0;
  for (int i = 0; i < size; ++i) covered += image.at(i, size / 2).g == 0 ? 1 : 0;
  const double angular_radius = std::asin(radius / distance);
  const double expected_px = std::tan(angular_radius) / std::tan(double(fovy) * std::numbers::pi / 360.0) * size;
  EXPECT_NEAR(covered, expected_px, 2.0);
}

TEST(ClosedForm, ShadowedPointGetsOnlyAmbient) {
  RenderJob job = looking_down(10, 5, 20);
  job.root = test::group({test::mesh(test::floor_quad(100), PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1}),
                          test::box({-20, 4, -20}, {20, 4.5f, 20})});  // a roof between the light and the floor
  job.ambient = {0.25f, 0.25f, 0.25f};
  job.lights = {PointLight{{0, 6, 0}, {1, 1, 1}, {1, 0, 0}}};
  job.camera.eye = {0, 3, 0};  // below the roof
  const Image image = render_job(job);
  for (const Color& c : image.pixels()) EXPECT_FLOAT_EQ(c.r, 0.25f);
}

TEST(ClosedForm, LightBehindSurfaceAddsNothing) {
  RenderJob job = looking_down(10, 3, 20);
  job.root = test::mesh(test::floor_quad(100), PhongMaterial{{1, 1, 1}, {1, 1, 1}, 1});
  job.ambient = {0, 0, 0};
  job.lights = {PointLight{{0, -5, 0}, {1, 1, 1}, {1, 0, 0}}};
  const Image image = render_job(job);
  for (const Color& c : image.pixels()) EXPECT_EQ(c, Color(0, 0, 0));
}

TEST(ClosedForm, ImageIsIdenticalForAnyThreadCountAndTileSize) {
  RenderJob job = looking_down(10, 37, 50);
  job.root = test::group({test::mesh(test::floor_quad(10), PhongMaterial{{0.8f, 0.6f, 0.2f}, {0.5f, 0.5f, 0.5f}, 30}),
                          test::sphere({1, 1, 0}, 1), test::box({-3, 0, -1}, {-1, 2, 1})});
  job.ambient = {0.1f, 0.1f, 0.1f};
  job.lights = {PointLight{{3, 8, 2}, {1, 1, 1}, {1, 0, 0}}};
  const Image reference = test::render(job);
  for (const auto& [threads, tile] : {std::pair{2, 16}, std::pair{3, 5}, std::pair{4, 1}}) {
    JobOptions options = test::oracle_options();
    options.render.threads = threads;
    options.render.tile_size = tile;
    EXPECT_EQ(test::render(job, options).pixels(), reference.pixels()) << threads << " threads, tile " << tile;
  }
}

}  // namespace
}  // namespace mjray

namespace mjray {
namespace {

/// A dark light: only ambient light and what the specular lobes bring.
const PointLight kDark{{0, 50, 0}, {0, 0, 0}, {1, 0, 0}};

TEST(ClosedForm, FresnelSlabReflectsTheNormalIncidenceReflectance) {
  // Straight down onto a clear Fresnel slab resting on a black box, the mirror ray sees the
  // zenith colour Z and the refracted light is absorbed: F(0)·Z with F(0) = ((n1 − n2)/(n1 + n2))²,
  // through the whole integrator.
  for (const float n : {1.33f, 1.5f, 2.4f}) {
    RenderJob job;
    job.root = test::group({test::box({-50, -1, -50}, {50, 0, 50}, FresnelMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 1, n}),
                            test::box({-60, -5, -60}, {60, -1, 60}, PhongMaterial{{0, 0, 0}, {0, 0, 0}, 1})});
    job.lights = {kDark};
    const test::TestJob prepared(job);
    const Color seen = prepared.radiance({{0.3f, 5, -0.2f}, {0, -1, 0}});
    const float f0 = ((1 - n) / (1 + n)) * ((1 - n) / (1 + n));
    const Color zenith = Background{}.zenith;
    EXPECT_NEAR(seen.r, f0 * zenith.r, 1e-5f) << "n = " << n;
    EXPECT_NEAR(seen.g, f0 * zenith.g, 1e-5f) << "n = " << n;
    EXPECT_NEAR(seen.b, f0 * zenith.b, 1e-5f) << "n = " << n;
  }
}

/// The floor's brightness at the origin under a light straight above, with `slab` (or
/// nothing) hanging between them, seen from just above the floor; a ball of the slab's
/// material instead when `ball`.
float floor_under_slab(std::optional<Material> slab, bool ball = false) {
  RenderJob job;
  std::vector<std::shared_ptr<const SceneNode>> nodes = {
      test::mesh(test::floor_quad(100), PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1})};
  if (slab && ball) nodes.push_back(test::sphere({0.01f, 4.5f, 0.02f}, 1.5f, *slab));
  if (slab && !ball) nodes.push_back(test::box({-10, 4, -10}, {10, 5, 10}, *slab));
  job.root = test::group(nodes);
  job.lights = {PointLight{{0, 10, 0}, {1, 1, 1}, {1, 0, 0}}};
  return test::TestJob(job).radiance({{0.01f, 1, 0.02f}, {0, -1, 0}}).g;
}

/// One look straight down at the origin of a floor of `floor` material under a 4×4 area
/// light centred at `light_centre`, with a small box in the way of part of it.
Color floor_under_area_light(const PhongMaterial& floor, const Point3& light_centre, RayCounters& counters) {
  RenderJob job;
  // Beside the camera ray, in the way of some samples.
  const Point3 half_way{light_centre.x * 0.5f + 0.2f, light_centre.y * 0.5f, light_centre.z * 0.5f + 0.2f};
  job.root = test::group({test::mesh(test::floor_quad(100), floor),
                          test::box(half_way - Vector3{0.1f, 0.1f, 0.1f}, half_way + Vector3{0.1f, 0.1f, 0.1f})});
  job.lights = {AreaLight{light_centre - Vector3{0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1}, {1, 0, 0}}};
  return test::TestJob(job, test::oracle_options({8, 8, 4})).radiance({{0, 5, 0}, {0, -1, 0}}, &counters);
}

TEST(ClosedForm, LightTheSurfaceCannotReflectNeedsNoShadowRay) {
  // A mirror-like Phong surface (no diffuse part, shininess 500) reflects an area light only
  // near the mirror direction: from the light straight above, all 16 samples count and each
  // needs its shadow ray; from a light far to the side, max(0, r·v)^500 is exactly zero for
  // every sample, so the pixel is black and no shadow ray is traced.
  const PhongMaterial mirror_like{{0, 0, 0}, {1, 1, 1}, 500};
  RayCounters counters;
  EXPECT_GT(floor_under_area_light(mirror_like, {0, 10, 0}, counters).g, 0.1f);
  EXPECT_EQ(counters.shadow, 16u);
  EXPECT_EQ(floor_under_area_light(mirror_like, {20, 5, 0}, counters), Color(0, 0, 0));
  EXPECT_EQ(counters.shadow, 0u);
  // A diffuse part reflects every sample: all are traced.
  EXPECT_GT(floor_under_area_light({{0.5f, 0.5f, 0.5f}, {1, 1, 1}, 500}, {20, 5, 0}, counters).g, 0);
  EXPECT_EQ(counters.shadow, 16u);
}

TEST(ClosedForm, ShadowsThroughASlabKeepTheRefractedShare) {
  const float open = floor_under_slab(std::nullopt);
  ASSERT_GT(open, 0.9f);
  // Two interfaces at normal incidence, each passing 1 − F(0) = 0.96 for index 1.5.
  const PhongMaterial clear{{0, 0, 0}, {0, 0, 0}, 1};
  EXPECT_NEAR(floor_under_slab(FresnelMaterial{clear, 1, 1.5f}) / open, 0.96f * 0.96f, 0.01f * 0.9216f);
  EXPECT_EQ(floor_under_slab(RefractiveMaterial{clear, 0, 1, 1.5f}), open);   // refracted: all of it
  EXPECT_NEAR(floor_under_slab(RefractiveMaterial{clear, 0.25f, 1, 1.5f}) / open, 0.75f * 0.75f, 1e-5f);
  EXPECT_EQ(floor_under_slab(PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1}), 0);      // opaque: none
  EXPECT_EQ(floor_under_slab(ReflectiveMaterial{clear, 0.5f}), 0);
  // Through the middle of a glass ball: in and out at normal incidence too.
  EXPECT_NEAR(floor_under_slab(FresnelMaterial{clear, 1, 1.5f}, true) / open, 0.96f * 0.96f, 1e-4f);
}

TEST(ClosedForm, TiltedVertexNormalsShadeWithTheirNormal) {
  // A flat floor whose vertex normals all lean the same way: the diffuse term follows the
  // interpolated normal, kd·max(0, n·l)·I, not the face's.
  const Normal3 tilted = normalize(Normal3(0.6f, 1, -0.3f));
  TriangleMesh quad = test::floor_quad(100);
  quad.normals = {tilted};
  for (auto& triangle : quad.triangles)
    for (MeshCorner& corner : triangle) corner.normal = 0;
  const Color kd(0.7f, 0.5f, 0.3f);
  RenderJob job;
  job.root = test::mesh(quad, PhongMaterial{kd, {0, 0, 0}, 1});
  const PointLight light{{-3, 4, 2}, {1, 0.9f, 0.8f}, {1, 0, 0}};
  job.lights = {light};
  const test::TestJob prepared(job);
  for (const Point3 target : {Point3(0.5f, 0, 0.25f), Point3(-2, 0, 1), Point3(1.5f, 0, -3)}) {
    const Color seen = prepared.radiance({target + Vector3(0, 3, 0), {0, -1, 0}});
    const Vector3 l = normalize(light.position - target);
    const Color expected = kd * light.colour * std::max(0.f, dot(tilted, l));
    EXPECT_NEAR(seen.r, expected.r, 1e-5f);
    EXPECT_NEAR(seen.g, expected.g, 1e-5f);
    EXPECT_NEAR(seen.b, expected.b, 1e-5f);
    // The face's own normal would give a clearly different value.
    EXPECT_GT(std::abs(seen.r - kd.r * light.colour.r * l.y), 0.05f);
  }
}

/// The share of directions, uniform over the cone of half-angle alpha around +y, that meet the
/// plane y = h at x > 0, seen from (p, 0, 0): numerical quadrature over the cone.
double white_fraction(double p, double h, double alpha) {
  constexpr int kRings = 400, kSectors = 800;
  const double cos_max = std::cos(alpha);
  double white = 0;
  for (int i = 0; i < kRings; ++i) {
    const double cos_theta = 1 - (i + 0.5) / kRings * (1 - cos_max);  // uniform in cos θ
    const double sin_theta = std::sqrt(1 - cos_theta * cos_theta);
    for (int j = 0; j < kSectors; ++j) {
      const double phi = 2 * std::numbers::pi * (j + 0.5) / kSectors;
      white += p + h * sin_theta * std::cos(phi) / cos_theta > 0 ? 1 : 0;
    }
  }
  return white / (kRings * kSectors);
}

TEST(ClosedForm, GlossyReflectionBlursAStepEdgeOverItsCone) {
  // A glossy floor under a ceiling that is white (ambient 1, kd 1) for x > 0 and black for
  // x < 0. Straight down at offset p from the edge, the floor shows the cone's white share.
  const float height = 10, reflectivity = 0.8f;
  const double alpha = (1 - reflectivity) * std::numbers::pi / 4;
  RenderJob job;
  job.root = test::group({test::box({-100, -1, -100}, {100, 0, 100},
                                    GlossyMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, reflectivity, 1024}),
                          test::box({0, height, -100}, {100, height + 1, 100}, PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1}),
                          test::box({-100, height, -100}, {0, height + 1, 100}, PhongMaterial{{0, 0, 0}, {0, 0, 0}, 1})});
  job.ambient = {1, 1, 1};
  job.lights = {kDark};
  const test::TestJob prepared(job);
  for (const double offset : {-0.8, -0.5, -0.2, 0.0, 0.3, 0.6, 1.2}) {
    const double p = height * std::tan(offset * alpha);  // the mirror ray misses the edge by offset·alpha
    const Color seen = prepared.radiance({{float(p), 1, 0}, {0, -1, 0}});
    const double expected = reflectivity * white_fraction(p, height, alpha);
    EXPECT_NEAR(seen.r, expected, 0.01) << "offset " << offset << " of the cone";
  }
}

TEST(ClosedForm, GlossyWithOneSampleIsOnePerturbedRayWhoseMeanIsTheBlur) {
  // The step-edge ceiling above: one glossy sample is one ray somewhere in the cone, so single
  // samples scatter between black and white where the cone straddles the edge, and their mean
  // is the blur that many samples give. A mirror would show one value.
  const float height = 10, reflectivity = 0.8f;
  const double alpha = (1 - reflectivity) * std::numbers::pi / 4;
  auto scene = [&](int samples) {
    RenderJob job;
    job.root = test::group({test::box({-100, -1, -100}, {100, 0, 100},
                                      GlossyMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, reflectivity, samples}),
                            test::box({0, height, -100}, {100, height + 1, 100}, PhongMaterial{{1, 1, 1}, {0, 0, 0}, 1}),
                            test::box({-100, height, -100}, {0, height + 1, 100}, PhongMaterial{{0, 0, 0}, {0, 0, 0}, 1})});
    job.ambient = {1, 1, 1};
    job.lights = {kDark};
    return job;
  };
  const test::TestJob one(scene(1)), many(scene(1024));
  const double p = height * std::tan(-0.3 * alpha);  // the mirror ray sees black
  const Ray ray{{float(p), 1, 0}, {0, -1, 0}};
  constexpr int kTrials = 4000;
  double sum = 0;
  int white = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    RayCounters counters;
    const Color c = one.radiance(ray, &counters, uint64_t(trial));
    ASSERT_EQ(counters.secondary, 1u) << "one sample is one ray";
    ASSERT_TRUE(c.r == 0 || std::abs(c.r - reflectivity) < 1e-6f) << c.r;
    sum += c.r;
    white += c.r > 0;
  }
  const double share = reflectivity * white_fraction(p, height, alpha);  // about 0.3 of 0.8
  const double sigma = std::sqrt(share * (reflectivity - share) / kTrials);
  EXPECT_GT(white, kTrials / 10) << "some single rays leave the mirror direction and see white";
  EXPECT_NEAR(sum / kTrials, share, 4 * sigma);
  EXPECT_NEAR(sum / kTrials, many.radiance(ray).r, 4 * sigma + 0.01);
}

}  // namespace
}  // namespace mjray
