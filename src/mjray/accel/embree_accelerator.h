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

/// Embree's high-quality BVH over a PrimitiveSet, primitives as a user geometry whose callbacks
/// call PrimitiveSet::intersect, so that they hit exactly as with every other accelerator (or,
/// for benchmarks, triangles as Embree's own native geometry).
class EmbreeAccelerator final : public Accelerator {
 public:
  /// What the user geometry's callbacks read: the primitives, and the mjray id of Embree
  /// primID 0 (0, or the first shape when triangles are native).
  struct UserPrimitives {
    const PrimitiveSet* prims;
    uint32_t first;
    /// Whether the triangles are Embree's native geometry (then the shapes alone are user
    /// primitives, from id triangles.size() on).
    bool native_triangles() const { return first > 0; }
  };

  /// Builds over `prims` (which must outlive this); `threads` build threads, 0 = all cores.
  /// Throws SceneError when Embree cannot create a device or build the scene.
  /// With `exact_hits` (the default) Embree only traverses and mjray's own tests decide every
  /// hit, so images match the other accelerators bit for bit; benchmarks turn it off to time
  /// Embree's native triangles alone.
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

  const PrimitiveSet& prims_;
  Bounds3 bounds_;
  UserPrimitives user_{};
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
  std::atomic<int64_t> device_bytes_{0};  ///< updated by Embree's memory monitor callback
};

}  // namespace mjray
