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
  /// The scope of the rays from `si` to `light`'s sample region. `likely_blocker`, if in the
  /// list, is tested first.
  ShadowScope(const PrimitiveSet& prims, const Accelerator& accel, const SurfaceInteraction& si, const Light& light,
              uint32_t likely_blocker);
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

/// A ShadowScope searched for only when a shadow ray first needs it: samples that the surface
/// reflects none of trace no ray (a glass away from its narrow highlight, for most of an area
/// light), so a shading point may need no search at all.
class DeferredShadowScope {
 public:
  /// Every primitive of `accel`, as ShadowScope(accel).
  explicit DeferredShadowScope(const Accelerator& accel) : accel_(accel) {}
  /// The scope ShadowScope(prims, accel, si, light, *likely_blocker) would be, with the
  /// blocker read when it is searched for (none when `likely_blocker` is null).
  DeferredShadowScope(const PrimitiveSet& prims, const Accelerator& accel, const SurfaceInteraction& si,
                      const Light& light, const uint32_t* likely_blocker)
      : accel_(accel), prims_(&prims), si_(&si), light_(&light), likely_blocker_(likely_blocker) {}

  const ShadowScope& get() {
    if (!scope_) {
      if (prims_)
        scope_.emplace(*prims_, accel_, *si_, *light_, likely_blocker_ ? *likely_blocker_ : ShadowScope::kNoPrimitive);
      else
        scope_.emplace(accel_);
    }
    return *scope_;
  }

 private:
  const Accelerator& accel_;
  const PrimitiveSet* prims_ = nullptr;  // null: the whole accelerator
  const SurfaceInteraction* si_ = nullptr;
  const Light* light_ = nullptr;
  const uint32_t* likely_blocker_ = nullptr;
  std::optional<ShadowScope> scope_;
};

}  // namespace mjray
