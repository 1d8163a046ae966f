#pragma once
/// What building a job's photon maps took, for the statistics.

#include <cstddef>
#include <cstdint>

namespace mjray {

/// What building the maps took.
struct PhotonStatistics {
  uint64_t caustic_emitted = 0, caustic_stored = 0;
  uint64_t global_emitted = 0, global_stored = 0;
  uint64_t irradiance_samples = 0;
  uint64_t rays = 0;                ///< photon rays of both maps
  double seconds_trace = 0;         ///< emission and tracing
  double seconds_build = 0;         ///< the kd-trees
  double seconds_irradiance = 0;    ///< precomputing irradiance at global photons
  size_t memory_bytes = 0;          ///< the maps and the irradiance samples

  double seconds() const { return seconds_trace + seconds_build + seconds_irradiance; }
};

}  // namespace mjray
