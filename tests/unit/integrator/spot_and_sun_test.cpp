// gr.spotlight and gr.sunlight in closed form: the spot's lit disc of radius h·tan(cone) and
// its penumbra, the sun's light without falloff and its shadows, hard and soft; and the flux
// their photons carry.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "mjray/integrator/photon/photon_emission.h"
#include "mjray/scene/flatten.h"
#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kDegree = kPi / 180;

/// A diffuse floor y = 0 of half-size 50, and a job looking at it.
RenderJob floor_job(std::vector<Light> lights, std::vector<std::shared_ptr<const SceneNode>> more = {}) {
  RenderJob job;
  job.width = job.height = 1;
  job.camera = {{0, 10, 0}, {0, -1, 0}, {0, 0, -1}, 40};
  more.push_back(test::mesh(test::floor_quad(50), PhongMaterial{{0.5f, 0.6f, 0.7f}, {0, 0, 0}, 1}));
  job.root = test::group(std::move(more));
  job.lights = std::move(lights);
  return job;
}

/// The colour of the floor at (x, 0, z), seen from straight above at height `eye`.
Color floor_at(const test::TestJob& job, float x, float z, float eye = 5) {
  return job.radiance({{x, eye, z}, {0, -1, 0}});
}

TEST(SpotLight, LightsTheDiscOfRadiusHeightTimesTanConeAndNothingBeyond) {
  // Straight down from height 4 with a 30° cone and no penumbra: lit within 4·tan 30° = 2.309.
  const float h = 4, cone = 30 * kDegree;
  SpotLight spot;
  spot.position = {0, h, 0};
  spot.direction = {0, -1, 0};
  spot.colour = {0.9f, 0.8f, 0.7f};
  spot.cone = cone;
  const test::TestJob job(floor_job({spot}));
  const float edge = h * std::tan(cone);
  for (const float rho : {0.f, 1.f, 2.f, edge - 0.01f}) {
    // Inside: kd·I·cos θ, as a point light there.
    const float cos_theta = h / std::sqrt(h * h + rho * rho);
    const Color c = floor_at(job, rho * 0.6f, rho * 0.8f);
    EXPECT_NEAR(c.g, 0.6f * 0.8f * cos_theta, 1e-5f) << rho;
    EXPECT_NEAR(c.b, 0.7f * 0.7f * cos_theta, 1e-5f) << rho;
  }
  for (const float rho : {edge + 0.01f, 3.f, 10.f}) EXPECT_EQ(floor_at(job, 0, rho), Color(0, 0, 0)) << rho;
}

TEST(SpotLight, ThePenumbraFadesSmoothlyToHalfAtItsMiddle) {
  const float h = 2;
  SpotLight spot;
  spot.position = {0, h, 0};
  spot.direction = {0, -1, 0};
  spot.colour = {1, 1, 1};
  spot.cone = 20 * kDegree;
  spot.penumbra = 10 * kDegree;
  const test::TestJob job(floor_job({spot}));
  const auto at_angle = [&](float degrees) {
    const float rho = h * std::tan(degrees * kDegree);
    return floor_at(job, rho, 0).r / (0.5f * std::cos(degrees * kDegree));  // the profile alone
  };
  EXPECT_NEAR(at_angle(19.9f), 1, 1e-4f);
  EXPECT_NEAR(at_angle(25), 0.5f, 1e-4f);
  EXPECT_NEAR(at_angle(22.5f), 0.84375f, 1e-4f);  // t = 0.75 of the way in: 3t² − 2t³
  EXPECT_NEAR(at_angle(29.9f), 0, 1e-3f);
  // Monotone across it.
  float last = 1.1f;
  for (float degrees = 19; degrees <= 31; degrees += 0.5f) {
    const float now = at_angle(degrees);
    EXPECT_LE(now, last + 1e-5f) << degrees;
    last = now;
  }
}

TEST(SunLight, LightsEveryPointAlikeWithoutFalloffAndCastsAShadowAlongItsDirection) {
  // From 60° above the horizon toward +x: a floor point gets kd·E·sin 60°, near or far; a
  // ball of radius 0.5 at height 2 shadows the point 2 / tan 60° along +x from below it.
  const Vector3 direction = normalize(Vector3(std::cos(60 * kDegree), -std::sin(60 * kDegree), 0));
  SunLight sun;
  sun.direction = direction;
  sun.colour = {1, 0.9f, 0.8f};
  sun.half_angle = 0;
  const test::TestJob job(floor_job({sun}, {test::sphere({0, 2, 0}, 0.5f)}));
  const float lit = 0.6f * 0.9f * std::sin(60 * kDegree);
  for (const float x : {-30.f, -3.f, 5.f, 40.f}) EXPECT_NEAR(floor_at(job, x, 7).g, lit, 1e-5f) << x;
  const float shadow_x = 2 / std::tan(60 * kDegree);
  EXPECT_EQ(floor_at(job, shadow_x, 0), Color(0, 0, 0));
  // The shadow is the ball's section along the light: an ellipse 0.5 / sin 60° long in x.
  const float half_length = 0.5f / std::sin(60 * kDegree);
  EXPECT_EQ(floor_at(job, shadow_x + half_length - 0.02f, 0), Color(0, 0, 0));
  EXPECT_NEAR(floor_at(job, shadow_x + half_length + 0.02f, 0).g, lit, 1e-5f);
  EXPECT_NEAR(floor_at(job, shadow_x, 0.52f).g, lit, 1e-5f);
}

TEST(SunLight, ADiscOfTheSunsSizeSoftensTheShadowEdgeOverHeightTimesItsAngle) {
  // A wall edge at height 4 under a sun straight above, 2° across: the shadow of the edge
  // x = 0 spreads over |x| ≤ 4·tan 1°, half lit at x = 0 and fully lit or dark beyond.
  SunLight sun;
  sun.direction = {0, -1, 0};
  sun.colour = {1, 1, 1};
  sun.half_angle = 1 * kDegree;
  JobOptions options = test::oracle_options();
  options.integrator.area_light_samples = 32;
  const test::TestJob job(floor_job({sun}, {test::box({-20, 4, -20}, {0, 4.1f, 20})}), options);
  const float half_width = 4.1f * std::tan(1 * kDegree);  // from the box's top face
  const auto under = [&](float x) { return floor_at(job, x, 0, 3).r / 0.5f; };  // eye below the box
  EXPECT_NEAR(under(0), 0.5f, 0.03f);
  EXPECT_EQ(under(-half_width - 0.01f), 0);
  EXPECT_NEAR(under(half_width + 0.01f), 1, 2e-4f);  // the disc: a mean cosine of 1 − θ²/4
  EXPECT_GT(under(0.5f * half_width), under(0) + 0.1f);
  EXPECT_LT(under(-0.5f * half_width), under(0) - 0.1f);
}

TEST(SpotAndSunPhotons, ASpotsPhotonsCarryItsIntensityTimesTheConesSolidAngle) {
  SpotLight spot;
  spot.position = {0, 3, 0};
  spot.direction = normalize(Vector3(0.3f, -1, 0.1f));
  spot.colour = {1, 0.5f, 0.25f};
  spot.cone = 35 * kDegree;
  const World world = test::flattened_world({test::sphere({0, 0, 0}, 1)}, {spot});
  const PhotonSource source(world.lights);
  constexpr uint64_t kCount = 50000;
  Color total;
  for (uint64_t i = 0; i < kCount; ++i) {
    RandomStream random(0, 3, i);
    const EmittedPhoton e = source.emit(i, kCount, random);
    total += e.flux;
    EXPECT_GE(dot(e.ray.direction, spot.direction), std::cos(spot.cone) - 1e-6f);  // none wasted outside
  }
  const float expected = 2 * kPi * (1 - std::cos(spot.cone));
  EXPECT_NEAR(total.r, expected, expected * 1e-3f);
  EXPECT_NEAR(total.b, 0.25f * expected, 0.25f * expected * 1e-3f);
}

TEST(SpotAndSunPhotons, TheSunsPhotonsCrossTheSceneInParallelCarryingItsIrradianceTimesTheArea) {
  SunLight sun;
  sun.direction = normalize(Vector3(1, -2, 0.5f));
  sun.colour = {2, 1, 0.5f};
  const World world = test::flattened_world({test::box({-1, 0, -2}, {3, 1, 2})}, {sun});
  const SunLight& fitted = std::get<SunLight>(world.lights.at(0));
  EXPECT_NEAR(fitted.scene_radius, 0.5f * std::sqrt(16.f + 1 + 16), 1e-3f);
  const PhotonSource source(world.lights);
  constexpr uint64_t kCount = 20000;
  Color total;
  for (uint64_t i = 0; i < kCount; ++i) {
    RandomStream random(0, 4, i);
    const EmittedPhoton e = source.emit(i, kCount, random);
    total += e.flux;
    EXPECT_NEAR(dot(e.ray.direction, sun.direction), 1, 1e-5f);
    // It starts outside the scene's ball and passes within it.
    const Vector3 from_centre = e.ray.origin - fitted.scene_centre;
    EXPECT_GT(length(from_centre), fitted.scene_radius);
    const float along = -dot(from_centre, e.ray.direction);
    EXPECT_LE(length(from_centre + e.ray.direction * along), fitted.scene_radius * 1.0001f);
  }
  const float area = kPi * fitted.scene_radius * fitted.scene_radius;
  EXPECT_NEAR(total.r, 2 * area, 2 * area * 1e-3f);
  EXPECT_NEAR(total.b, 0.5f * area, 0.5f * area * 1e-3f);
}

TEST(SpotAndSunPhotons, AimedSunPhotonsCarryTheFluxThroughTheUnionOfTheTargetsOnce) {
  // Two glass balls that overlap as the sun sees them (straight down), and one apart.
  const Material glass = FresnelMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 1, 1.5f};
  SunLight sun;
  sun.direction = {0, -1, 0};
  sun.colour = {1, 1, 1};
  const World world = test::flattened_world({test::sphere({0, 0, 0}, 1, glass), test::sphere({1, 3, 0}, 1, glass),
                                test::sphere({6, 0, 0}, 0.5f, glass)},
                               {sun});
  const std::vector<BoundingSphere> targets = specular_targets(world);
  ASSERT_EQ(targets.size(), 3u);
  const PhotonSource source(world.lights, targets);
  constexpr uint64_t kCount = 200000;
  double aimed = 0;
  for (uint64_t i = 0; i < kCount; ++i) {
    RandomStream random(0, 5, i);
    aimed += source.emit(i, kCount, random).flux.g;
  }
  // The union's area across the light, from the balls' bounding radii, by counting points.
  RandomStream random(13, 0, 0);
  constexpr int kPoints = 2000000;
  int inside = 0;
  for (int i = 0; i < kPoints; ++i) {
    const float x = random.uniform() * 10 - 2, z = random.uniform() * 6 - 3;
    for (const BoundingSphere& b : targets)
      if ((x - b.centre.x) * (x - b.centre.x) + (z - b.centre.z) * (z - b.centre.z) <= b.radius * b.radius) {
        ++inside;
        break;
      }
  }
  const double union_area = 60.0 * inside / kPoints;
  EXPECT_NEAR(aimed, union_area, union_area * 0.01);
}

}  // namespace
}  // namespace mjray
