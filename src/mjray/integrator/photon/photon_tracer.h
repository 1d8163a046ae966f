#pragma once
/// Photon paths from the lights through the scene, and the photons they leave on surfaces.

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "mjray/accel/accelerator.h"
#include "mjray/core/rng.h"
#include "mjray/integrator/photon/photon.h"
#include "mjray/integrator/photon/photon_emission.h"
#include "mjray/scene/world.h"

namespace mjray {

/// Which paths a photon map keeps.
enum class PhotonPaths {
  kCaustic,  ///< light, one or more specular bounces, then the first diffuse surface (L S+ D)
  kGlobal,   ///< every diffuse surface met, scattering on by the BRDF and the lobes
};

/// The random stream of bounce `bounce` of photon `index` (bounce 0: its emission). Photon
/// streams live in their own pixel slots, one per map, far beyond any pixel index, so they
/// never share a key with a camera sample or with the other map.
inline RandomStream photon_stream(uint64_t seed, PhotonPaths paths, uint64_t index, uint64_t bounce) {
  constexpr uint64_t kPhotonDomain = 0xf07f'0000'0000'0000ULL;
  return RandomStream(seed, kPhotonDomain + uint64_t(paths), index).fork(bounce);
}

/// The photons of one map, in the order of their photon indices, and the rays cast.
struct TracedPhotons {
  std::vector<Photon> photons;
  uint64_t rays = 0;
};

/// Thrown by trace_photons when the map would hold more photons than it may.
class PhotonMapTooLarge : public std::runtime_error {
 public:
  explicit PhotonMapTooLarge(uint64_t expected_photons)
      : std::runtime_error("the photon map would hold too many photons"), expected_photons_(expected_photons) {}
  /// The photons the whole map would hold, as its first photons say.
  uint64_t expected_photons() const { return expected_photons_; }

 private:
  uint64_t expected_photons_;
};

/// Photons of a map traced before the rest, in chunks spread over all of its photon indices,
/// to tell how many the whole map will hold.
inline constexpr uint64_t kPilotPhotons = 65536;

/// Traces photons [0, count) from `source` on `threads` threads. Stored flux respects each
/// light's falloff along the path up to the first diffuse scattering: the density of photons
/// falls as 1/d², so a photon that has travelled d carries d²·att(d) times its share. The
/// result depends only on the scene, the source, count and seed. Throws PhotonMapTooLarge,
/// before the rest are traced, when the kPilotPhotons traced first store at a rate that would
/// make the map hold more than `max_stored` photons (or when it does).
TracedPhotons trace_photons(const World& world, const Accelerator& accel, const PhotonSource& source,
                            PhotonPaths paths, uint64_t count, uint64_t seed, int threads,
                            uint64_t max_stored = UINT64_MAX);

}  // namespace mjray
