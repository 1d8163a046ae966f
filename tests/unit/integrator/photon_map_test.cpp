// The parts of photon mapping on their own: the kd-tree against brute force, the emission's
// flux against the lights' power, the photon tracer's determinism, the density estimate
// against a known density.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/accel/brute_force.h"
#include "mjray/core/available_memory.h"
#include "mjray/core/error.h"
#include "mjray/core/rng.h"
#include "mjray/integrator/photon/density_estimate.h"
#include "mjray/integrator/photon/kd_tree.h"
#include "mjray/integrator/photon/photon_emission.h"
#include "mjray/integrator/photon/photon_maps.h"
#include "mjray/integrator/photon/photon_tracer.h"
#include "mjray/scene/flatten.h"
#include "support/scene_builder.h"

namespace mjray {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

std::vector<Photon> random_photons(int count, uint64_t seed) {
  RandomStream random(seed, 0, 0);
  std::vector<Photon> photons(static_cast<size_t>(count));
  for (Photon& p : photons) {
    // Clustered on a plane and in a blob: the shapes photon maps have.
    const bool plane = random.uniform() < 0.6f;
    const float x = random.uniform() * 4 - 2, y = random.uniform(), z = random.uniform() * 4 - 2;
    p.position = plane ? Point3{x, 0, z} : Point3{x * 0.1f, 1 + y * 0.1f, z * 0.1f};
    p.power = {random.uniform(), 1, 1};
    p.normal = PackedNormal::pack(random.uniform() < 0.5f ? Normal3{0, 1, 0} : Normal3{0, -1, 0});
  }
  return photons;
}

TEST(KdTree, NearestNeighboursAreThoseOfABruteForceSearch) {
  const std::vector<Photon> photons = random_photons(20000, 1);
  const KdTree<Photon> tree(photons, 3);
  ASSERT_EQ(tree.size(), photons.size());
  RandomStream random(2, 0, 0);
  std::vector<Neighbour> out(50);
  for (int q = 0; q < 200; ++q) {
    Point3 p{random.uniform() * 4 - 2, random.uniform() * 0.2f, random.uniform() * 4 - 2};
    // Some on the photons' plane and on the tree's first splitting planes (about x, z = 0).
    if (q % 3 == 0) p.y = 0;
    if (q % 5 == 0) p.x = 0;
    if (q % 7 == 0) p.z = 0;
    const Normal3 up{0, 1, 0};
    const float max_distance = q % 2 ? 0.1f : 10.f;
    const auto accept = [&](const PackedNormal& normal) { return faces_alike(normal, up); };
    const auto near = tree.nearest(p, max_distance * max_distance, accept, out);
    // Compute the same by sorting every accepted photon by distance.
    std::vector<float> all;
    for (const Photon& photon : photons) {
      const float d2 = dot(photon.position - p, photon.position - p);
      if (accept(photon.normal) && d2 < max_distance * max_distance) all.push_back(d2);
    }
    std::sort(all.begin(), all.end());
    ASSERT_EQ(near.found.size(), std::min(all.size(), out.size())) << q;
    std::vector<float> found;
    for (const Neighbour& n : near.found) found.push_back(n.distance2);
    std::sort(found.begin(), found.end());
    for (size_t i = 0; i < found.size(); ++i) EXPECT_EQ(found[i], all[i]) << q << ", " << i;
    EXPECT_EQ(near.radius2, found.size() == out.size() ? found.back() : max_distance * max_distance);
  }
}

TEST(KdTree, EmptyTreesAndEmptyQueriesFindNothing) {
  const auto any = [](const PackedNormal&) { return true; };
  std::vector<Neighbour> out(4);
  const KdTree<Photon> empty(std::vector<Photon>{}, 2);
  EXPECT_TRUE(empty.empty());
  const auto none = empty.nearest({0, 0, 0}, 1, any, out);
  EXPECT_TRUE(none.found.empty());
  EXPECT_EQ(none.radius2, 1);
  // A query that asks for no neighbours at all reads nothing of its (empty) output.
  const KdTree<Photon> tree(random_photons(100, 4), 2);
  const auto zero = tree.nearest({0, 0, 0}, 2, any, std::span<Neighbour>());
  EXPECT_TRUE(zero.found.empty());
  EXPECT_EQ(zero.radius2, 2);
}

TEST(KdTree, IsTheSameTreeForAnyNumberOfThreads) {
  const std::vector<Photon> photons = random_photons(50000, 3);
  const KdTree<Photon> one(photons, 1);
  for (const int threads : {2, 3, 8}) {
    const KdTree<Photon> many(photons, threads);
    ASSERT_EQ(many.size(), one.size());
    for (size_t i = 0; i < one.size(); ++i) ASSERT_EQ(many.items()[i].position, one.items()[i].position) << threads;
  }
}

TEST(DensityEstimate, UniformPhotonsGiveTheirFluxPerArea) {
  // 400,000 photons of flux 1/400,000 spread uniformly over a 2×2 square: irradiance 1/4.
  constexpr int kCount = 400000;
  RandomStream random(5, 0, 0);
  std::vector<Photon> photons(kCount);
  for (Photon& p : photons) {
    p.position = {random.uniform() * 2 - 1, 0, random.uniform() * 2 - 1};
    p.power = Color{1, 1, 1} / float(kCount);
    p.normal = PackedNormal::pack({0, 1, 0});
  }
  const KdTree<Photon> map(std::move(photons), 2);
  double sum = 0;
  constexpr int kQueries = 400;
  for (int q = 0; q < kQueries; ++q) {
    const Point3 p{random.uniform() - 0.5f, 0, random.uniform() - 0.5f};
    sum += irradiance_estimate(map, p, {0, 1, 0}, {64, 0.5f}).g;
  }
  // k = 64 photons per estimate: each is within about 1/√64 of the truth; the mean of 400
  // (correlated where discs overlap) well within 2%.
  EXPECT_NEAR(sum / kQueries, 0.25, 0.25 * 0.02);
  // Facing away, or beyond every photon, there is nothing.
  EXPECT_EQ(irradiance_estimate(map, {0, 0, 0}, {0, -1, 0}, {64, 0.5f}), Color(0, 0, 0));
  EXPECT_EQ(irradiance_estimate(map, {0, 3, 0}, {0, 1, 0}, {64, 0.5f}), Color(0, 0, 0));
}

TEST(PhotonEmission, FluxOfEveryDirectionAddsUpToTheLightsPower) {
  const World world = test::flattened_world({}, {PointLight{{0, 1, 0}, {1, 0.5f, 0.25f}, {1, 0, 0}},
                                    AreaLight{{0, 4, 0}, {1, 0, 0}, {0, 0, 1}, {0.3f, 0.3f, 0.3f}, {1, 0, 0}}});
  const PhotonSource source(world.lights);
  constexpr uint64_t kCount = 20000;
  Color total;
  Vector3 mean_direction;
  for (uint64_t i = 0; i < kCount; ++i) {
    RandomStream random(0, 7, i);
    const EmittedPhoton e = source.emit(i, kCount, random);
    total += e.flux;
    mean_direction += e.ray.direction / float(kCount);
  }
  const Color power = isotropic_power({1.3f, 0.8f, 0.55f});
  // The choice of light is stratified by index, so the light's shares are nearly exact; the
  // colours within a light are exact.
  EXPECT_NEAR(total.r, power.r, power.r * 0.01f);
  EXPECT_NEAR(total.g, power.g, power.g * 0.01f);
  EXPECT_NEAR(total.b, power.b, power.b * 0.01f);
  EXPECT_LT(length(mean_direction), 0.03f);  // isotropic
}

TEST(PhotonEmission, AimedPhotonsCarryTheFluxOfTheirConesOnceWhereConesOverlap) {
  // Two glass balls seen from the light at overlapping angles, and one alone.
  const Material glass = FresnelMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 1, 1.5f};
  const PointLight light{{0, 0, 0}, {1, 1, 1}, {1, 0, 0}};
  const World world = test::flattened_world({test::sphere({0, 0, 5}, 1, glass), test::sphere({0.8f, 0, 5.5f}, 1, glass),
                                test::sphere({0, -6, 0}, 2, glass), test::sphere({3, 3, 3}, 1)},
                               {light});
  const std::vector<BoundingSphere> targets = specular_targets(world);
  ASSERT_EQ(targets.size(), 3u);  // the Phong ball is no target
  const PhotonSource source(world.lights, targets);
  // Count the flux that reaches each ball, and estimate the union's solid angle directly.
  constexpr uint64_t kCount = 200000;
  double aimed = 0;
  for (uint64_t i = 0; i < kCount; ++i) {
    RandomStream random(0, 9, i);
    aimed += source.emit(i, kCount, random).flux.g;
  }
  constexpr int kDirections = 2000000;
  int inside = 0;
  RandomStream random(11, 0, 0);
  for (int i = 0; i < kDirections; ++i) {
    const float u1 = random.uniform(), u2 = random.uniform();
    const Vector3 w = sample_uniform_sphere(u1, u2);
    for (const BoundingSphere& ball : targets) {
      const Vector3 to = ball.centre - Point3{0, 0, 0};
      const float along = dot(to, w);
      if (along > 0 && dot(to, to) - along * along <= ball.radius * ball.radius) {
        ++inside;
        break;
      }
    }
  }
  // Flux = intensity × the solid angle of the union of the cones.
  const double union_solid_angle = 4 * kPi * double(inside) / kDirections;
  EXPECT_NEAR(aimed, union_solid_angle, union_solid_angle * 0.01);
}

TEST(PhotonEmission, BallsAroundShapesHoldThemTightly) {
  const Material glass = FresnelMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 1, 1.5f};
  const World world = test::flattened_world({test::sphere({1, 2, 3}, 0.5f, glass), test::box({0, 0, 0}, {1, 2, 2}, glass)}, {});
  const auto balls = specular_targets(world);
  ASSERT_EQ(balls.size(), 2u);
  EXPECT_NEAR(balls[0].radius, 0.5f, 1e-3f);
  EXPECT_NEAR(balls[0].centre.z, 3, 1e-5f);
  EXPECT_NEAR(balls[1].radius, 1.5f, 1e-3f);  // half the box's diagonal √(1 + 4 + 4)
  EXPECT_NEAR(balls[1].centre.y, 1, 1e-5f);
}

/// A floor, a glass ball and a mirror-ish ball under a point light: both maps store photons.
World photon_world() {
  const Material glass = FresnelMaterial{{{0, 0, 0}, {0, 0, 0}, 1}, 1, 1.5f};
  return test::flattened_world({test::mesh(test::floor_quad(10), PhongMaterial{{0.8f, 0.8f, 0.8f}, {0, 0, 0}, 1}),
                   test::sphere({0, 1.5f, 0}, 1, glass),
                   test::sphere({2, 1, 0}, 1, ReflectiveMaterial{{{0.5f, 0.2f, 0.2f}, {0, 0, 0}, 1}, 0.5f})},
                  {PointLight{{0, 6, 1}, {1, 1, 1}, {1, 0, 0}}});
}

TEST(PhotonTracer, PhotonsAreTheSameForAnyNumberOfThreads) {
  const World world = photon_world();
  const BruteForce accel(world.primitives);
  for (const PhotonPaths paths : {PhotonPaths::kCaustic, PhotonPaths::kGlobal}) {
    const PhotonSource source =
        paths == PhotonPaths::kCaustic ? PhotonSource(world.lights, specular_targets(world)) : PhotonSource(world.lights);
    const TracedPhotons one = trace_photons(world, accel, source, paths, 10000, 5, 1);
    ASSERT_GT(one.photons.size(), 2000u);
    for (const int threads : {2, 3}) {
      const TracedPhotons many = trace_photons(world, accel, source, paths, 10000, 5, threads);
      ASSERT_EQ(many.photons.size(), one.photons.size());
      EXPECT_EQ(many.rays, one.rays);
      for (size_t i = 0; i < one.photons.size(); ++i) {
        ASSERT_EQ(many.photons[i].position, one.photons[i].position) << i;
        ASSERT_EQ(many.photons[i].power, one.photons[i].power) << i;
      }
    }
    // Another seed draws other photons.
    const TracedPhotons other = trace_photons(world, accel, source, paths, 10000, 6, 2);
    EXPECT_NE(other.photons.front().position, one.photons.front().position);
  }
}

TEST(PhotonTracer, AMapThatWouldHoldTooManyIsRefusedFromASampleOfItsPhotons) {
  // Two lights of equal power: photon indices give the first half to the far one, whose
  // photons almost all miss, and the second half to the near one. A sample from the first
  // indices alone would expect next to nothing.
  World world = photon_world();
  world.lights.insert(world.lights.begin(), PointLight{{0, 5000, 0}, {1, 1, 1}, {1, 0, 0}});
  const BruteForce accel(world.primitives);
  const PhotonSource source(world.lights);
  constexpr uint64_t kCount = 4 * kPilotPhotons;
  const TracedPhotons all = trace_photons(world, accel, source, PhotonPaths::kGlobal, kCount, 5, 2);
  const uint64_t held = all.photons.size();
  ASSERT_GT(held, kCount / 10);
  // With room, the map is the one traced without a limit: the sample traced first changes nothing.
  const TracedPhotons with_room = trace_photons(world, accel, source, PhotonPaths::kGlobal, kCount, 5, 2, held + held / 10);
  ASSERT_EQ(with_room.photons.size(), held);
  EXPECT_EQ(with_room.rays, all.rays);
  for (size_t i = 0; i < held; ++i) ASSERT_EQ(with_room.photons[i].position, all.photons[i].position) << i;
  // Without, the sample's expectation is within a few percent of what the map holds.
  try {
    trace_photons(world, accel, source, PhotonPaths::kGlobal, kCount, 5, 2, held / 2);
    FAIL() << "a map of " << held << " photons with room for " << held / 2;
  } catch (const PhotonMapTooLarge& e) {
    EXPECT_NEAR(double(e.expected_photons()), double(held), 0.05 * double(held));
  }
  // A map of no more photons than a sample is refused once they are traced.
  EXPECT_THROW(trace_photons(world, accel, source, PhotonPaths::kGlobal, 1000, 5, 2, 10), PhotonMapTooLarge);
}

/// The SceneError PhotonMaps throws for `settings` on photon_world(), or "" when the maps are made.
std::string refusal(const PhotonSettings& settings) {
  const World world = photon_world();
  const BruteForce accel(world.primitives);
  try {
    const PhotonMaps maps(world, accel, settings, 5, 2);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(PhotonMaps, AMapThatWouldNotFitSaysWhichOptionAndHowMuchMemory) {
  PhotonSettings settings;
  settings.global_photons = 4 * kPilotPhotons;
  settings.memory_budget_bytes = 1 << 20;
  const std::string message = refusal(settings);
  ASSERT_NE(message, "") << "the map fitted in 1 MiB";
  EXPECT_EQ(message.rfind("--gi 262144: the photon map would hold about ", 0), 0u) << message;
  EXPECT_NE(message.find(" of memory, more than the 1 MiB available; ask for fewer photons"), std::string::npos)
      << message;
}

TEST(PhotonMaps, ProcessesOnOneMachineEachTakeTheirShareOfItsMemory) {
  const World world = photon_world();
  const BruteForce accel(world.primitives);
  PhotonSettings settings;
  settings.global_photons = 4 * kPilotPhotons;
  settings.memory_budget_bytes = uint64_t(64) << 20;
  const PhotonMaps alone(world, accel, settings, 5, 2);
  const uint64_t held = alone.global().size();
  ASSERT_GT(held, 0u);
  // Enough processes that each share holds half of the map's photons: refused, saying so.
  settings.processes_sharing_memory = int(settings.memory_budget_bytes / (held * sizeof(Photon) / 2));
  ASSERT_GT(settings.processes_sharing_memory, 1);
  const std::string message = refusal(settings);
  ASSERT_NE(message, "") << "a map of " << held << " photons fitted in 1/" << settings.processes_sharing_memory
                         << " of 64 MiB";
  EXPECT_NE(message.find(" available to each of the " + std::to_string(settings.processes_sharing_memory) +
                         " processes on this machine (of 64 MiB); ask for fewer photons"),
            std::string::npos)
      << message;
}

TEST(PhotonMaps, AProcessSharingItsMachineCountsAllItHoldsAgainstItsShareOfTheStart) {
  const World world = photon_world();
  const BruteForce accel(world.primitives);
  PhotonSettings settings;
  settings.global_photons = 4 * kPilotPhotons;
  settings.processes_sharing_memory = 2;
  // A share no larger than what this process holds already: refused.
  settings.memory_at_start_bytes = 2 * resident_bytes();
  EXPECT_THROW(PhotonMaps(world, accel, settings, 5, 2), SceneError);
  // A share of a GiB more: made, the same map as alone.
  settings.memory_at_start_bytes = 2 * (resident_bytes() + (uint64_t(1) << 30));
  const PhotonMaps shared(world, accel, settings, 5, 2);
  const PhotonMaps alone(world, accel, PhotonSettings{.global_photons = 4 * kPilotPhotons}, 5, 2);
  EXPECT_EQ(shared.global().size(), alone.global().size());
}

}  // namespace
}  // namespace mjray
