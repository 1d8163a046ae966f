// Photon-mapped caustics and global illumination against closed forms: a ball lens focuses at
// its paraxial focal length; a clear slab passes the Fresnel transmittance, as photons and as
// the transmissive-shadow model alike; a closed diffuse sphere converges to direct/(1 − a);
// a white wall beside a red one turns red.

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/accel/brute_force.h"
#include "mjray/integrator/photon/photon_tracer.h"
#include "mjray/material/optics.h"
#include "mjray/scene/flatten.h"
#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

const PhongMaterial kWhite{{1, 1, 1}, {0, 0, 0}, 1};
const FresnelMaterial kGlass{{{0, 0, 0}, {0, 0, 0}, 1}, 1, 1.5f};

/// Brute-force options with photon maps.
JobOptions with_photons(uint64_t caustic, uint64_t global, int threads = 2) {
  JobOptions options = test::oracle_options();
  options.photons.caustic_photons = caustic;
  options.photons.global_photons = global;
  options.render.threads = threads;
  options.accel.kind = "bvh";
  return options;
}

/// The radiance of the floor at (x, floor_y, z), seen from just above it by camera sample
/// `sample` (which reads caustic pass sample mod --caustic-passes).
Color floor_radiance(const test::TestJob& job, float x, float floor_y, float z, uint64_t sample = 0) {
  return job.radiance({{x, floor_y + 0.05f, z}, {0, -1, 0}}, nullptr, sample);
}

TEST(PhotonCaustics, BallLensFocusesAtItsParaxialFocalLength) {
  // A distant light above a glass ball of radius R, index n: parallel rays focus nR/(2(n − 1))
  // below its centre. Scan the floor's depth and find where the spot on the axis is brightest.
  const float radius = 1, n = 1.5f;
  const float focus = n * radius / (2 * (n - 1));  // 1.5
  const PointLight sun{{0, 1000, 0}, {1, 1, 1}, {1, 0, 0}};
  float best_depth = 0, best = 0, open_floor = 0;
  for (float depth = 1.3f; depth <= 1.71f; depth += 0.04f) {
    RenderJob job;
    job.root = test::group({test::sphere({0, 0, 0}, radius, kGlass),
                            test::mesh(test::floor_quad(20), kWhite, Transform::translate({0, -depth, 0}))});
    job.lights = {sun};
    const test::TestJob prepared(job, with_photons(150000, 0));
    const float spot = floor_radiance(prepared, 0, -depth, 0).g;
    if (spot > best) best = spot, best_depth = depth;
    open_floor = floor_radiance(prepared, 5, -depth, 5).g;
  }
  EXPECT_NEAR(best_depth, focus, 0.05f * focus);
  // kd · I (the light's falloff is 1), and a little of what the ball reflects.
  EXPECT_GE(open_floor, 1 - 1e-5f);
  EXPECT_LT(open_floor, 1.02f);
  EXPECT_GT(best, 3 * open_floor);
}

/// A light above a clear slab of Fresnel glass hanging over a white floor. (Its side faces
/// reflect the light that enters near them by total internal reflection, as real glass does,
/// onto the floor at |x| or |z| ≈ 1.7, away from where the tests below look.)
struct SlabScene {
  static constexpr float kLight = 10, kTop = 3.1f, kBottom = 3, kHalfWidth = 2;
  RenderJob job;
  /// By default the physical falloff 1/d²: photons then carry their share unchanged.
  explicit SlabScene(Vector3 falloff = {0, 0, 1}) {
    job.root = test::group({test::box({-kHalfWidth, kBottom, -kHalfWidth}, {kHalfWidth, kTop, kHalfWidth}, kGlass),
                            test::mesh(test::floor_quad(100), kWhite)});
    job.lights = {PointLight{{0, kLight, 0}, {1, 1, 1}, {falloff.x, falloff.y, falloff.z}}};
  }
};

TEST(PhotonCaustics, StoredPowerUnderASlabIsThePowerThroughItTimesTheFresnelTransmittance) {
  // Compute the closed form: the intensity times ∫ over the top face of T(θ) dΩ, where a photon
  // entering at θ leaves below with T = (1 − F)² Σ F²ᵏ = (1 − F)/(1 + F) (F the same at both
  // faces by reciprocity), integrated by the midpoint rule.
  const double h = SlabScene::kLight - SlabScene::kTop, a = SlabScene::kHalfWidth;
  constexpr int kCells = 800;
  double expected = 0;
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const double x = -a + 2 * a * (i + 0.5) / kCells, z = -a + 2 * a * (j + 0.5) / kCells;
      const double d2 = x * x + z * z + h * h, cos_theta = h / std::sqrt(d2);
      const double f = fresnel_dielectric(float(cos_theta), 1, 1.5f);
      expected += (1 - f) / (1 + f) * cos_theta / d2 * (2 * a / kCells) * (2 * a / kCells);
    }
  const SlabScene scene;
  const World world = flatten(scene.job, nullptr);
  const BruteForce accel(world.primitives);
  const PhotonSource source(world.lights, specular_targets(world));
  const TracedPhotons traced = trace_photons(world, accel, source, PhotonPaths::kCaustic, 200000, 0, 2);
  double stored = 0;
  for (const Photon& p : traced.photons) {
    EXPECT_LT(p.position.y, 1e-3f);  // on the floor
    stored += p.power.g;
  }
  EXPECT_NEAR(stored, expected, 0.02 * expected);
  // The flux that reached the slab without the Fresnel losses is ≈ 1/0.92 of it: the test
  // tells the two apart.
  EXPECT_GT(std::abs(stored / expected - 0.92), 0.04);
}

/// Flat glass does not focus: the photon map's floor under the slab matches the shadow rays
/// that keep (1 − F)² there (and nothing counts twice: that would double it), within the
/// estimate's noise (121 points that share no photons) plus 1% for what sets the two apart
/// (the slab's apparent depth 0.5%, its inner reflections 0.2%).
void expect_slab_floor_as_shadow_model(const SlabScene& scene) {
  const test::TestJob photons(scene.job, with_photons(300000, 0));
  const test::TestJob shadows(scene.job, test::oracle_options());
  double sum = 0, sum2 = 0;
  int count = 0;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) {
      const float x = 0.25f * float(i), z = 0.25f * float(j);
      const double ratio = floor_radiance(photons, x, 0, z).g / floor_radiance(shadows, x, 0, z).g;
      sum += ratio, sum2 += ratio * ratio, ++count;
    }
  const double mean = sum / count, deviation = std::sqrt(sum2 / count - mean * mean);
  const double standard_error = deviation / std::sqrt(double(count));
  EXPECT_NEAR(mean, 1, 3 * standard_error + 0.01) << "standard error " << standard_error;
  EXPECT_LT(deviation, 0.25);
}

TEST(PhotonCaustics, ASlabLightsTheFloorAsTheTransmissiveShadowModelDoes) {
  expect_slab_floor_as_shadow_model(SlabScene());
}

TEST(PhotonCaustics, ProgressivePassesConvergeUnderASlabToTheTransmissiveShadowModel) {
  // The floor under the slab read as a pixel reads it: the mean over its camera samples, one
  // per caustic pass. Fresh photons in every pass and a shrinking radius: the error against
  // the closed form (within the 1% that sets the two models apart) falls as passes grow.
  const SlabScene scene;
  const test::TestJob shadows(scene.job, test::oracle_options());
  const auto rms_error = [&](int passes) {
    JobOptions options = with_photons(20000, 0);
    options.photons.caustic_passes = passes;
    const test::TestJob photons(scene.job, options);
    double sum2 = 0;
    int count = 0;
    for (int i = -5; i <= 5; ++i)
      for (int j = -5; j <= 5; ++j) {
        const float x = 0.25f * float(i), z = 0.25f * float(j);
        double estimate = 0;
        for (int s = 0; s < passes; ++s) estimate += floor_radiance(photons, x, 0, z, uint64_t(s)).g;
        const double ratio = estimate / passes / floor_radiance(shadows, x, 0, z).g;
        sum2 += (ratio - 1) * (ratio - 1), ++count;
      }
    return std::sqrt(sum2 / count);
  };
  // Each pass's estimate is about as noisy as a single map's (its radius shrinks as its k
  // does), so K passes cut the error by about √(K · the mean area share): 0.39 for 16, 0.2
  // for 64 (measured 0.18, 0.115, 0.066, 0.041).
  const double one = rms_error(1), four = rms_error(4), sixteen = rms_error(16), sixty_four = rms_error(64);
  EXPECT_LT(four, 0.75 * one) << one << " " << four;
  EXPECT_LT(sixteen, 0.45 * one) << one << " " << sixteen;
  EXPECT_LT(sixty_four, 0.75 * sixteen) << sixteen << " " << sixty_four;
  EXPECT_LT(sixty_four, 0.05);
}

TEST(PhotonCaustics, PhotonsFallOffWithTheLightsAttenuationAsShadowRaysDo) {
  // 1/(c0 + c1·d + c2·d²) with every term: at the floor (d ≈ 10) it is 1/9, not 1/d² = 1/100,
  // so photons that kept only their inverse-square spreading would be 11 times too dark.
  expect_slab_floor_as_shadow_model(SlabScene({1, 0.3f, 0.05f}));
}

/// The radiance inside a closed diffuse sphere of albedo `albedo` lit by a point light at its
/// centre, averaged over directions, with global illumination from `photons` photons.
double furnace_radiance(float albedo, uint64_t photons) {
  RenderJob job;
  job.root = test::sphere({0, 0, 0}, 2, PhongMaterial{{albedo, albedo, albedo}, {0, 0, 0}, 1});
  job.lights = {PointLight{{0, 0, 0}, {1, 1, 1}, {0, 0, 1}}};
  job.ambient = {0.3f, 0.3f, 0.3f};  // global illumination replaces it
  const test::TestJob prepared(job, with_photons(0, photons));
  RandomStream random(1, 0, 0);
  double sum = 0;
  constexpr int kDirections = 64;
  for (int i = 0; i < kDirections; ++i) {
    const float u1 = random.uniform(), u2 = random.uniform();
    sum += prepared.radiance({{0.1f, -0.2f, 0.05f}, sample_uniform_sphere(u1, u2)}).g;
  }
  return sum / kDirections;
}

TEST(PhotonGlobalIllumination, WhiteFurnaceConvergesToDirectOverOneMinusAlbedo) {
  // Inside a sphere every point sees the same: the direct a·I/R² plus the albedo times the
  // total, so the total is direct/(1 − a).
  for (const float albedo : {0.5f, 0.8f}) {
    const double direct = albedo * 1.0 / 4;  // I = 1, R = 2, falloff 1/d²
    EXPECT_NEAR(furnace_radiance(albedo, 100000), direct / (1 - albedo), 0.03 * direct / (1 - albedo))
        << "albedo " << albedo;
  }
}

/// A box room, white but for a red left wall (x = −2), lit by a lamp under the ceiling.
RenderJob red_wall_room() {
  const PhongMaterial white{{0.75f, 0.75f, 0.75f}, {0, 0, 0}, 1}, red{{0.75f, 0.05f, 0.05f}, {0, 0, 0}, 1};
  RenderJob job;
  job.root = test::group({test::box({-2.5f, -0.5f, -2.5f}, {2.5f, 0, 2.5f}, white),
                          test::box({-2.5f, 4, -2.5f}, {2.5f, 4.5f, 2.5f}, white),
                          test::box({-2.5f, 0, 2}, {2.5f, 4, 2.5f}, white),
                          test::box({-2.5f, 0, -2.5f}, {2.5f, 4, -2}, white),
                          test::box({-2.5f, 0, -2}, {-2, 4, 2}, red),
                          test::box({2, 0, -2}, {2.5f, 4, 2}, white)});
  job.lights = {PointLight{{0, 3.5f, 0}, {1, 1, 1}, {1, 0, 0.1f}}};
  job.ambient = {0.2f, 0.2f, 0.2f};
  return job;
}

TEST(PhotonGlobalIllumination, AWhiteWallBesideARedOneTurnsRed) {
  const RenderJob job = red_wall_room();
  const test::TestJob whitted(job, test::oracle_options());
  const test::TestJob gi(job, with_photons(0, 100000));
  // The back wall (z = 2) near the red wall, and near the white one opposite.
  const auto redness = [](const Color& c) { return c.r / c.g; };
  const Ray near_red{{-1.8f, 2, 0}, {0, 0, 1}}, near_white{{1.8f, 2, 0}, {0, 0, 1}};
  EXPECT_FLOAT_EQ(redness(whitted.radiance(near_red)), 1);
  EXPECT_GT(redness(gi.radiance(near_red)), 1.15f);
  EXPECT_GT(redness(gi.radiance(near_red)), redness(gi.radiance(near_white)) + 0.05f);
}

}  // namespace
}  // namespace mjray
