#include "mjray/integrator/photon/photon_tracer.h"

#include <algorithm>
#include <atomic>

#include "mjray/core/parallel_for.h"
#include "mjray/geometry/spawn_ray.h"
#include "mjray/integrator/closest_surface.h"
#include "mjray/integrator/photon/path_choice.h"

namespace mjray {

namespace {

constexpr int kMaxBounces = 64;  // Russian roulette ends paths long before (albedo 0.8: 0.8⁶⁴ ≈ 10⁻⁶)
constexpr uint64_t kChunk = 4096;  ///< photons per unit of parallel work

/// Everything one photon path reads.
struct Tracer {
  const World& world;
  const Accelerator& accel;
  const PhotonSource& source;
  PhotonPaths paths;
  uint64_t count, seed;

  /// Traces photon `index`, appending what it stores to `out`; returns the rays cast.
  uint64_t trace(uint64_t index, std::vector<Photon>& out) const {
    RandomStream emission = photon_stream(seed, paths, index, 0);
    const EmittedPhoton emitted = source.emit(index, count, emission);
    const Light& light = world.lights[emitted.light];
    Ray ray = emitted.ray;
    Color flux = emitted.flux;
    float travelled = 0;
    bool scattered = false;  // by a BRDF: the light's falloff is behind it
    int specular_bounces = 0;
    uint64_t rays = 0;
    for (int bounce = 1; bounce <= kMaxBounces; ++bounce) {
      ++rays;
      const auto hit = closest_surface(world, accel, ray);
      if (!hit) break;
      RandomStream random = photon_stream(seed, paths, index, uint64_t(bounce));
      if (!scattered) travelled += length(hit->point - ray.origin);
      const float falloff = scattered ? 1 : photon_falloff(light, travelled);
      const Material& material = world.materials[hit->material];
      const ShadingFrame frame = frame_facing(*hit, ray.direction);
      const LocalShading brdf = scattering(material, *hit);
      if (!brdf.kd.is_black() && (paths == PhotonPaths::kGlobal || specular_bounces > 0))
        out.push_back({hit->point, flux * falloff, PackedNormal::pack(frame.n)});
      const SpecularLobes lobes = specular_lobes(material, frame);
      const float albedo = paths == PhotonPaths::kGlobal ? (brdf.kd + brdf.ks).max_component() : 0;
      const PathChoice choice = PathChoice::pick(lobes, albedo, random.uniform());
      const float u1 = random.uniform(), u2 = random.uniform();
      Vector3 next;
      if (choice.lobe) {
        next = lobe_direction(*choice.lobe, frame, u1, u2);
        ++specular_bounces;
      } else if (choice.brdf) {
        const auto sample = brdf.sample(frame, u1, u2);
        if (!sample) break;
        flux = flux * falloff * sample->f * (dot(sample->wi, frame.n) / (sample->pdf * albedo));
        scattered = true;
        next = sample->wi;
      } else {
        break;
      }
      ray = spawn_ray(*hit, next);
    }
    return rays;
  }
};

}  // namespace

TracedPhotons trace_photons(const World& world, const Accelerator& accel, const PhotonSource& source,
                            PhotonPaths paths, uint64_t count, uint64_t seed, int threads, uint64_t max_stored) {
  static_assert(kPilotPhotons % kChunk == 0);
  TracedPhotons result;
  if (source.empty() || count == 0) return result;
  const Tracer tracer{world, accel, source, paths, count, seed};
  // Each chunk of photon indices fills its own list; joined in chunk order they are the same
  // for any number of threads.
  const uint64_t chunks = (count + kChunk - 1) / kChunk;
  std::vector<std::vector<Photon>> stored(chunks);
  std::atomic<uint64_t> rays{0};
  std::vector<uint8_t> traced(chunks, 0);
  const auto trace_chunks = [&](const std::vector<uint64_t>& list) {
    parallel_for(int(list.size()), threads, [&](int k, int) {
      const uint64_t chunk = list[size_t(k)];
      const uint64_t first = chunk * kChunk, last = std::min(count, first + kChunk);
      uint64_t chunk_rays = 0;
      for (uint64_t i = first; i < last; ++i) chunk_rays += tracer.trace(i, stored[size_t(chunk)]);
      rays += chunk_rays;
    });
    for (const uint64_t chunk : list) traced[size_t(chunk)] = 1;
  };
  // A sample of chunks spread evenly over the indices (which stratify the lights and targets in
  // order) says how many photons the whole map will hold: one that cannot fit is refused
  // before the rest fill the memory.
  constexpr uint64_t kPilotChunks = kPilotPhotons / kChunk;
  if (chunks > kPilotChunks) {
    std::vector<uint64_t> pilot;
    for (uint64_t j = 0; j < kPilotChunks; ++j) pilot.push_back(j * chunks / kPilotChunks);
    trace_chunks(pilot);
    uint64_t pilot_photons = 0, pilot_stored = 0;
    for (const uint64_t chunk : pilot) {
      pilot_photons += std::min(count, (chunk + 1) * kChunk) - chunk * kChunk;
      pilot_stored += stored[size_t(chunk)].size();
    }
    const double expected = double(pilot_stored) / double(pilot_photons) * double(count);
    if (expected > double(max_stored)) throw PhotonMapTooLarge(uint64_t(expected));
  }
  std::vector<uint64_t> rest;
  for (uint64_t chunk = 0; chunk < chunks; ++chunk)
    if (!traced[size_t(chunk)]) rest.push_back(chunk);
  trace_chunks(rest);
  uint64_t total = 0;
  for (const auto& list : stored) total += list.size();
  if (total > max_stored) throw PhotonMapTooLarge(total);
  result.photons.reserve(total);
  for (auto& list : stored) {
    result.photons.insert(result.photons.end(), list.begin(), list.end());
    std::vector<Photon>().swap(list);
  }
  result.rays = rays;
  return result;
}

}  // namespace mjray
