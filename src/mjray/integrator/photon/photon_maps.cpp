#include "mjray/integrator/photon/photon_maps.h"

#include <algorithm>
#include <chrono>

#include "mjray/core/parallel_for.h"
#include "mjray/integrator/photon/photon_tracer.h"

namespace mjray {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The query of a map: its k, and its radius as a share of the diagonal of `box`.
DensityQuery query_for(int neighbours, const Bounds3& box, float radius_share) {
  return {neighbours, box.empty() ? 0.f : std::max(length(box.diagonal()) * radius_share, 1e-6f)};
}

/// The box around the balls photons are aimed at.
Bounds3 bounds_of(const std::vector<BoundingSphere>& balls) {
  Bounds3 box;
  for (const BoundingSphere& b : balls) {
    box.expand(b.centre - Vector3(b.radius, b.radius, b.radius));
    box.expand(b.centre + Vector3(b.radius, b.radius, b.radius));
  }
  return box;
}

}  // namespace

PhotonMaps::PhotonMaps(const World& world, const Accelerator& accel, const PhotonSettings& settings, uint64_t seed,
                       int threads) {
  // Compute each map: trace its photons, then build its tree.
  const auto build_map = [&](const PhotonSource& source, PhotonPaths paths, uint64_t count) {
    auto start = Clock::now();
    TracedPhotons traced = trace_photons(world, accel, source, paths, count, seed, threads);
    statistics_.seconds_trace += seconds_since(start);
    statistics_.rays += traced.rays;
    start = Clock::now();
    KdTree<Photon> tree(std::move(traced.photons), threads);
    statistics_.seconds_build += seconds_since(start);
    return tree;
  };
  if (settings.caustics()) {
    // Caustics are as large as the objects that focus them, wherever stray photons land.
    std::vector<BoundingSphere> targets = specular_targets(world);
    caustic_query_ = query_for(settings.caustic_neighbours, bounds_of(targets), settings.caustic_radius_share);
    caustic_ = build_map(PhotonSource(world.lights, std::move(targets)), PhotonPaths::kCaustic, settings.caustic_photons);
    statistics_.caustic_emitted = settings.caustic_photons;
    statistics_.caustic_stored = caustic_.size();
  }
  if (settings.global_illumination()) {
    global_ = build_map(PhotonSource(world.lights), PhotonPaths::kGlobal, settings.global_photons);
    statistics_.global_emitted = settings.global_photons;
    statistics_.global_stored = global_.size();
  }
  global_query_ = query_for(settings.global_neighbours, global_.bounds(), settings.global_radius_share);
  if (!global_.empty()) precompute_irradiance(std::max(1, settings.irradiance_stride), threads);
  statistics_.memory_bytes = caustic_.memory_bytes() + global_.memory_bytes() + irradiance_.memory_bytes();
}

void PhotonMaps::precompute_irradiance(int stride, int threads) {
  const auto start = Clock::now();
  const auto photons = global_.items();
  std::vector<IrradianceSample> samples((photons.size() + size_t(stride) - 1) / size_t(stride));
  constexpr int kChunk = 1024;
  parallel_for(int((samples.size() + kChunk - 1) / kChunk), threads, [&](int chunk, int) {
    const size_t first = size_t(chunk) * kChunk, last = std::min(samples.size(), first + kChunk);
    for (size_t i = first; i < last; ++i) {
      const Photon& at = photons[i * size_t(stride)];
      const Normal3 n = at.normal.unit();
      samples[i] = {at.position, irradiance_estimate(global_, at.position, n, global_query_), at.normal};
    }
  });
  irradiance_ = KdTree<IrradianceSample>(std::move(samples), threads);
  statistics_.irradiance_samples = irradiance_.size();
  statistics_.seconds_irradiance = seconds_since(start);
}

}  // namespace mjray
