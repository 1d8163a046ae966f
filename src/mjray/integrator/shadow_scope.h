#pragma once
/// What the shadow rays from one shading point toward one light can hit, found once for all
/// of that light's N×N samples: nothing (none needs tracing), a few primitives (each ray tests
/// just those), or anything (each ray traverses the accelerator). The answer of every ray is
/// the same in all three cases; only the work differs.

#include <array>
#include <cstdint>
#include <optional>

#include "mjray/accel/accelerator.h"
#include "mjray/accel/primitive_list.h"
#include "mjray/accel/region_search.h"
#include "mjray/geometry/surface_interaction.h"
#include "mjray/light/light.h"

namespace mjray {

class ShadowScope {
 public:
  /// Most primitives a list holds; a region touching more is traced through the accelerator.
  /// Small, because the BVH's own leaf tests beat a longer list (measured on the glass and
  /// mesh bench scenes).
  static constexpr size_t kCapacity = 2;
  /// A `likely_blocker` that names no primitive.
  static constexpr uint32_t kNoPrimitive = ~uint32_t(0);

  /// Every primitive of `accel` (for one-sample lights, where a search would not pay).
  explicit ShadowScope(const Accelerator& accel) : occluders_(&accel) {}
  /// The scope of the rays from `si` to `light`'s sample region, searched with `regions` when
  /// the accelerator has a region search (else every ray traverses it). `likely_blocker`, if
  /// in the list, is tested first.
  ShadowScope(const PrimitiveSet& prims, const Accelerator& accel, const RegionSearch* regions,
              const SurfaceInteraction& si, const Light& light, uint32_t likely_blocker);
  ShadowScope(const ShadowScope&) = delete;
  ShadowScope& operator=(const ShadowScope&) = delete;

  /// Every ray reaches the light.
  bool clear() const { return clear_; }
  /// Whether rays traverse the whole accelerator (rather than a list).
  bool whole_scene() const { return !list_; }
  /// What answers the rays' visibility queries.
  const Accelerator& occluders() const { return *occluders_; }
  /// The origin spawn_ray_to gives every sample's shadow ray, when the light lies wholly on one
  /// side of the surface by a clear angle (always so for a clear scope or a list); else null.
  const Point3* shared_origin() const { return origin_ ? &*origin_ : nullptr; }

 private:
  std::array<uint32_t, kCapacity + 1> candidates_;  // one more for the shading point's own primitive
  std::optional<PrimitiveList> list_;
  const Accelerator* occluders_;
  std::optional<Point3> origin_;
  bool clear_ = false;
};

}  // namespace mjray
