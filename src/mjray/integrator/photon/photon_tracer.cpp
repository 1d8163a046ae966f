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
      const float falloff = scattered ? 1 : travelled * travelled * attenuation(light, travelled);
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
  const auto trace_chunks = [&](uint64_t from, uint64_t to) {
    parallel_for(int(to - from), threads, [&](int k, int) {
      const uint64_t chunk = from + uint64_t(k);
      const uint64_t first = chunk * kChunk, last = std::min(count, first + kChunk);
      uint64_t chunk_rays = 0;
      for (uint64_t i = first; i < last; ++i) chunk_rays += tracer.trace(i, stored[size_t(chunk)]);
      rays += chunk_rays;
    });
  };
  const auto stored_in = [&](uint64_t to) {
    uint64_t total = 0;
    for (uint64_t chunk = 0; chunk < to; ++chunk) total += stored[size_t(chunk)].size();
    return total;
  };
  // The first photons say how many the whole map will hold (their indices are spread over
  // the lights as all of them are): a map that cannot fit is refused before it fills memory.
  const uint64_t pilot = std::min(chunks, kPilotPhotons / kChunk);
  trace_chunks(0, pilot);
  if (pilot < chunks) {
    const double expected = double(stored_in(pilot)) / double(pilot * kChunk) * double(count);
    if (expected > double(max_stored)) throw PhotonMapTooLarge(uint64_t(expected));
    trace_chunks(pilot, chunks);
  }
  const uint64_t total = stored_in(chunks);
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
