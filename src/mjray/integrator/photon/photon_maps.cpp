#include "mjray/integrator/photon/photon_maps.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "mjray/core/available_memory.h"
#include "mjray/core/error.h"
#include "mjray/core/parallel_for.h"
#include "mjray/core/rng.h"
#include "mjray/core/seconds_since.h"
#include "mjray/integrator/photon/photon_tracer.h"

namespace mjray {

namespace {

using Clock = std::chrono::steady_clock;


/// The query of a map: its k, and its radius as a share of the diagonal of `box`.
DensityQuery query_for(int neighbours, const Bounds3& box, float radius_share) {
  return {neighbours, box.empty() ? 0.f : std::max(length(box.diagonal()) * radius_share, 1e-6f)};
}

/// An upper bound of what a map takes per photon it holds at its peak, when its chunks' lists
/// are joined into one (each list up to twice its size, and the joined copy): 67 bytes were
/// measured with the irradiance samples of --gi 1e6 on scenes/features/global_illumination.lua.
constexpr uint64_t kPeakBytesPerPhoton = 3 * sizeof(Photon);

/// An amount of memory for messages: "27.8 GiB", or "512 MiB" below a GiB.
std::string memory_text(double bytes) {
  constexpr double kMiB = 1 << 20, kGiB = 1 << 30;
  char text[32];
  if (bytes >= kGiB) std::snprintf(text, sizeof text, "%.1f GiB", bytes / kGiB);
  else std::snprintf(text, sizeof text, "%.0f MiB", bytes / kMiB);
  return text;
}

/// A large count for messages: "355 million", or the number itself below a million.
std::string rounded_count(uint64_t count) {
  if (count < 1'000'000) return std::to_string(count);
  return std::to_string((count + 500'000) / 1'000'000) + " million";
}

/// What a map may take, read when it is made so that an earlier map counts against it; 0:
/// unknown, no limit. `machine` and `sharing` say where it came from, for messages.
struct MapBudget {
  uint64_t bytes = 0;
  uint64_t machine = 0;
  int sharing = 1;
};

MapBudget map_budget(const PhotonSettings& settings) {
  const int sharing = std::max(1, settings.processes_sharing_memory);
  if (settings.memory_budget_bytes > 0)
    return {settings.memory_budget_bytes / uint64_t(sharing), settings.memory_budget_bytes, sharing};
  if (sharing == 1 || settings.memory_at_start_bytes == 0) return {available_memory_bytes(), 0, 1};
  // This process's share of what the machine had at the start, less all it holds now, and no
  // more than it could be given now. At least a byte: 0 would read as "no limit".
  const uint64_t share = settings.memory_at_start_bytes / uint64_t(sharing), held = resident_bytes();
  uint64_t bytes = share > held ? share - held : 1;
  if (const uint64_t now = available_memory_bytes(); now > 0) bytes = std::min(bytes, now);
  return {bytes, settings.memory_at_start_bytes, sharing};
}

/// How the budget was shared: " to each of the 4 processes on this machine (of 23.1 GiB)".
std::string share_text(uint64_t machine_bytes, int processes) {
  if (processes == 1) return "";
  return " to each of the " + std::to_string(processes) + " processes on this machine (of " +
         memory_text(double(machine_bytes)) + ")";
}

/// Progressive photon mapping's α: the share of photons a search keeps as its area shrinks.
constexpr double kProgressiveAlpha = 2.0 / 3.0;
/// The fewest photons a pass's estimate gathers, however small its area.
constexpr int kMinPassNeighbours = 8;

/// The search area of caustic pass `pass` over the first's: Π_{i=1..pass} (i + α) / (i + 1).
double caustic_area_share(int pass) {
  double share = 1;
  for (int i = 1; i <= pass; ++i) share *= (i + kProgressiveAlpha) / (i + 1);
  return share;
}

/// The photons' seed of caustic pass `pass`: the run's own for the first, so that one pass is
/// the map a run without passes makes.
uint64_t pass_seed(uint64_t seed, int pass) { return pass == 0 ? seed : mix64(seed ^ mix64(uint64_t(pass))); }

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
  const auto build_map = [&](const PhotonSource& source, PhotonPaths paths, uint64_t count, uint64_t map_seed) {
    auto start = Clock::now();
    const MapBudget budget = map_budget(settings);
    TracedPhotons traced;
    try {
      traced = trace_photons(world, accel, source, paths, count, map_seed, threads,
                             budget.bytes ? budget.bytes / kPeakBytesPerPhoton : UINT64_MAX);
    } catch (const PhotonMapTooLarge& e) {
      const std::string option = paths == PhotonPaths::kCaustic ? "--caustics " : "--gi ";
      throw SceneError(option + std::to_string(count) + ": the photon map would hold about " +
                       rounded_count(e.expected_photons()) + " photons and need about " +
                       memory_text(double(e.expected_photons() * kPeakBytesPerPhoton)) + " of memory, more than the " +
                       memory_text(double(budget.bytes)) + " available" + share_text(budget.machine, budget.sharing) +
                       "; ask for fewer photons");
    }
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
    const DensityQuery first = query_for(settings.caustic_neighbours, bounds_of(targets), settings.caustic_radius_share);
    const PhotonSource source(world.lights, std::move(targets));
    for (int pass = 0; pass < std::max(1, settings.caustic_passes); ++pass) {
      // Each pass's photons are numbered apart (pass 0's as a single map's), and searched over
      // an area that shrinks as progressive photon mapping's: r'² = r² (i + α) / (i + 1).
      const double area = caustic_area_share(pass);
      caustic_query_.push_back({std::max(kMinPassNeighbours, int(std::lround(first.neighbours * area))),
                                float(first.max_radius * std::sqrt(area))});
      caustic_.push_back(build_map(source, PhotonPaths::kCaustic, settings.caustic_photons, pass_seed(seed, pass)));
      statistics_.caustic_emitted += settings.caustic_photons;
      statistics_.caustic_stored += caustic_.back().size();
    }
  }
  if (settings.global_illumination()) {
    global_ = build_map(PhotonSource(world.lights), PhotonPaths::kGlobal, settings.global_photons, seed);
    statistics_.global_emitted = settings.global_photons;
    statistics_.global_stored = global_.size();
  }
  global_query_ = query_for(settings.global_neighbours, global_.bounds(), settings.global_radius_share);
  if (!global_.empty()) precompute_irradiance(std::max(1, settings.irradiance_stride), threads);
  statistics_.memory_bytes = global_.memory_bytes() + irradiance_.memory_bytes();
  for (const KdTree<Photon>& pass : caustic_) statistics_.memory_bytes += pass.memory_bytes();
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
