#pragma once
/// What --caustics and --gi ask for, and how their photon maps are read.

#include <cstdint>

namespace mjray {

/// Photon counts (0 = off) and the constants of the estimates.
struct PhotonSettings {
  uint64_t caustic_photons = 0;  ///< --caustics N: photons aimed at objects with specular lobes, per pass
  /// --caustic-passes K: caustic maps of fresh photons, each searched over a smaller radius
  /// than the last (progressive photon mapping); camera sample s of a pixel reads map s mod K.
  int caustic_passes = 1;
  uint64_t global_photons = 0;   ///< --gi N: photons in every direction, for the global map
  int caustic_neighbours = 100;  ///< k of the caustic map's density estimate
  int global_neighbours = 100;   ///< k of the global map's irradiance estimates
  int irradiance_stride = 4;     ///< irradiance is precomputed at every N-th global photon
  int gather_rays = 64;          ///< final-gather rays at a surface seen from the camera (a square grid)
  /// The estimates' largest radius: for caustics a share of the diagonal of the box around
  /// the objects photons are aimed at, for the global map of the box around its photons.
  float caustic_radius_share = 0.02f;
  float global_radius_share = 0.05f;
  /// The memory a map may take while it is made; 0: what the machine has available then.
  uint64_t memory_budget_bytes = 0;
  /// Processes started together on this machine that make maps at the same time (mjray-mpi's
  /// ranks on one host), and what the machine had available when they started. Each may then
  /// hold 1/N of that, everything it holds counted, rather than what is available when its map
  /// is made, which the others' maps may have taken by then or may yet take.
  int processes_sharing_memory = 1;
  uint64_t memory_at_start_bytes = 0;

  bool caustics() const { return caustic_photons > 0; }
  bool global_illumination() const { return global_photons > 0; }
  bool enabled() const { return caustics() || global_illumination(); }
};

}  // namespace mjray
