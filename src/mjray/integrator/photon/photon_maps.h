#pragma once
/// The photon maps of one job: built once before the render, read by every pixel.

#include <cstdint>
#include <vector>

#include "mjray/accel/accelerator.h"
#include "mjray/integrator/photon/density_estimate.h"
#include "mjray/integrator/photon/kd_tree.h"
#include "mjray/integrator/photon/photon.h"
#include "mjray/integrator/photon/photon_settings.h"
#include "mjray/integrator/photon/photon_statistics.h"
#include "mjray/scene/world.h"

namespace mjray {

/// The caustic map (--caustics), the global map (--gi) and the irradiance precomputed at
/// every irradiance_stride-th global photon (Christensen's final-gather acceleration), each
/// in a kd-tree. Identical for any number of threads. A map that would not fit in the memory
/// available (or settings.memory_budget_bytes), shared among settings.processes_sharing_memory,
/// is refused with a SceneError after its first photons, before the rest fill the memory.
class PhotonMaps {
 public:
  PhotonMaps(const World& world, const Accelerator& accel, const PhotonSettings& settings, uint64_t seed, int threads);

  /// The caustic map of pass `pass` (0 to caustic_passes() − 1) and how it is read: each pass
  /// of fresh photons, over a smaller radius than the one before.
  const KdTree<Photon>& caustic(size_t pass = 0) const { return caustic_[pass]; }
  const DensityQuery& caustic_query(size_t pass = 0) const { return caustic_query_[pass]; }
  size_t caustic_passes() const { return caustic_.size(); }
  const KdTree<Photon>& global() const { return global_; }
  const KdTree<IrradianceSample>& irradiance() const { return irradiance_; }
  /// How the global map is read.
  const DensityQuery& global_query() const { return global_query_; }
  const PhotonStatistics& statistics() const { return statistics_; }

 private:
  void precompute_irradiance(int stride, int threads);

  std::vector<KdTree<Photon>> caustic_;
  std::vector<DensityQuery> caustic_query_;
  KdTree<Photon> global_;
  KdTree<IrradianceSample> irradiance_;
  DensityQuery global_query_;
  PhotonStatistics statistics_;
};

}  // namespace mjray
