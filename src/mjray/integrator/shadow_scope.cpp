#include "mjray/integrator/shadow_scope.h"

#include <cmath>
#include <span>
#include <utility>

#include "mjray/geometry/light_pyramid.h"
#include "mjray/geometry/spawn_ray.h"

namespace mjray {

ShadowScope::ShadowScope(const PrimitiveSet& prims, const Accelerator& accel, const RegionSearch* regions,
                         const SurfaceInteraction& si, const Light& light, uint32_t likely_blocker)
    : occluders_(&accel) {
  // The rays of every sample must leave from one origin: the light wholly on one side of the
  // surface, by a clear angle. On the outer side (where the geometric normal points) the
  // surface itself cannot stand in the way, for a triangle or a convex shape; on the inner
  // side it is searched like everything else.
  const std::array<Point3, 4> region = sample_region(light, si.point);
  int in_front = 0;
  for (const Point3& corner : region) {
    const Vector3 to = corner - si.point;
    const float cosine = dot(si.geometric_normal, to) / length(to);
    if (!(std::abs(cosine) > 1e-3f)) return;
    in_front += cosine > 0;
  }
  if (in_front != 0 && in_front != 4) return;
  // Every sample's direction has the corners' side, so offset_origin moves each the same way.
  origin_ = offset_origin(si, region[0] - si.point);
  if (!regions) return;
  const auto pyramid = LightPyramid::make(*origin_, region);
  if (!pyramid) return;
  const uint32_t own = in_front == 4 ? si.prim : kNoPrimitive;
  const auto found = regions->region_primitives(*pyramid, own, std::span(candidates_).first(kCapacity));
  if (!found) return;
  if (*found == 0) {
    clear_ = true;
    return;
  }
  size_t size = *found;
  // The rays are tested against the surface's own primitive too, exactly as the accelerator
  // would: what cannot stand in the way is not trusted to miss when rounding is involved.
  if (own != kNoPrimitive) candidates_[size++] = own;
  for (size_t i = 0; i < size; ++i)
    if (candidates_[i] == likely_blocker) std::swap(candidates_[i], candidates_[0]);
  list_.emplace(prims, std::span<const uint32_t>(candidates_.data(), size));
  occluders_ = &*list_;
}

}  // namespace mjray
