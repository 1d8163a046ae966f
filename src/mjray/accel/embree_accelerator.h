#pragma once
/// Intel Embree 3 behind the Accelerator seam. The Embree API stays inside this file pair:
/// the header names its handles only as opaque forward declarations.

#include <atomic>
#include <cstdint>

#include "mjray/accel/accelerator.h"
#include "mjray/geometry/primitive_set.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace mjray {

/// Embree's high-quality BVH over a PrimitiveSet: triangles as one native triangle geometry
/// (Embree primID = mjray primitive id), shapes as one user geometry whose callbacks call
/// PrimitiveSet::intersect_shape, so shapes hit exactly as with every other accelerator.
class EmbreeAccelerator final : public Accelerator {
 public:
  /// Builds over `prims` (which must outlive this); `threads` build threads, 0 = all cores.
  /// Throws SceneError when Embree cannot create a device or build the scene.
  /// With `exact_hits` (the default) each hit is recomputed with mjray's own triangle test, so
  /// images match the other accelerators bit for bit; benchmarks turn it off to time Embree alone.
  /// `robust` (the default) sets Embree's robust scene flag, which makes its triangle test
  /// watertight as mjray's is; benchmarks may compare Embree's faster default too.
  explicit EmbreeAccelerator(const PrimitiveSet& prims, int threads = 0, bool exact_hits = true, bool robust = true);
  ~EmbreeAccelerator() override;
  EmbreeAccelerator(const EmbreeAccelerator&) = delete;
  EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

  std::optional<Hit> intersect(const Ray& ray, Interval t_range) const override;
  bool occluded(const Ray& ray, float t_max) const override;
  bool occluded(const Ray& ray, Interval t_range, HitFilter& filter) const override;
  Bounds3 bounds() const override { return bounds_; }
  std::string_view name() const override { return "embree"; }
  /// Bytes Embree's device holds (its memory monitor), which is mostly the scene's BVH.
  size_t memory_bytes() const override;

 private:
  void release();
  /// Among the primitives hit at exactly hit.t, the one of the lowest id (hit if alone).
  Hit lowest_at_same_t(const Ray& ray, const Hit& hit) const;

  const PrimitiveSet& prims_;
  Bounds3 bounds_;
  bool exact_hits_ = true;
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
  std::atomic<int64_t> device_bytes_{0};  ///< updated by Embree's memory monitor callback
};

}  // namespace mjray
