#include "mjray/integrator/light_visibility.h"

#include "mjray/geometry/spawn_ray.h"
#include "mjray/integrator/shadow_transmittance.h"

namespace mjray {

const ShadowScope& LightVisibility::scope() {
  if (!scope_) {
    if (many_samples_) {
      const uint32_t* blocker = state_.occluders.slot(light_index_);
      scope_.emplace(world_.primitives, queries_.accel, queries_.regions, si_, light_,
                     blocker ? *blocker : ShadowScope::kNoPrimitive);
    } else {
      scope_.emplace(queries_.accel);  // one sample: a search would not pay
    }
  }
  return *scope_;
}

Color LightVisibility::transmittance(const Point3& light_point) {
  constexpr Color kAll{1, 1, 1};
  const ShadowScope& found = scope();
  if (found.clear()) return kAll;
  ++state_.rays.shadow;
  // spawn_ray_to's ray, its origin found once for all of the light's samples where it can be.
  const Point3* origin = found.shared_origin();
  const Ray shadow = origin ? ray_to(*origin, light_point) : spawn_ray_to(si_, light_point);
  // The primitive that blocked the last shadow ray toward this light mostly blocks this one
  // (a scope's list already holds it first).
  uint32_t* cached = state_.occluders.slot(light_index_);
  if (cached && *cached != OccluderCache::kNone && found.whole_scene() &&
      world_.primitives.intersect(*cached, shadow, {0, kShadowTMax}))
    return {};
  const Accelerator& occluders = found.occluders();
  if (!through_glass_ && world_.primitives.any_transmissive()) return occluders.occluded(shadow, kShadowTMax) ? Color{} : kAll;
  const ShadowResult through = shadow_ray_transmittance(world_, occluders, shadow, kShadowTMax);
  if (through.blocker && cached) *cached = *through.blocker;
  return through.kept;
}

}  // namespace mjray
