#pragma once
/// The one place that starts rays at surfaces: every secondary and shadow ray goes through
/// here so that no ray re-hits the surface it leaves.

#include <algorithm>
#include <cmath>

#include "mjray/core/ray.h"
#include "mjray/geometry/surface_interaction.h"

namespace mjray {

/// Distance to move a ray origin off a surface at p: a conservative bound on the float
/// rounding error of a computed hit point, which grows with the magnitude of its coordinates.
inline float surface_offset(const Point3& p) {
  constexpr float kRelative = 1e-5f;  // ~100 ulps of the largest coordinate
  constexpr float kAbsolute = 1e-6f;
  return kRelative * max_component(abs(p)) + kAbsolute;
}

/// The origin for a ray leaving `si` in `direction`: pushed along the geometric normal onto
/// the side the direction points to.
inline Point3 offset_origin(const SurfaceInteraction& si, const Vector3& direction) {
  const float offset = surface_offset(si.point);
  const Vector3 n(si.geometric_normal);
  return si.point + (dot(n, direction) < 0 ? -offset : offset) * n;
}

/// A ray leaving the surface in `direction`.
inline Ray spawn_ray(const SurfaceInteraction& si, const Vector3& direction) {
  return {offset_origin(si, direction), direction};
}

/// A ray from the surface toward `target`, for t in (0, shadow_t_max()): t = 1 is the target.
inline Ray spawn_ray_to(const SurfaceInteraction& si, const Point3& target) {
  const Point3 origin = offset_origin(si, target - si.point);
  return {origin, target - origin};
}

/// The t_max of a spawn_ray_to ray: stops just short of the target.
constexpr float kShadowTMax = 1 - 1e-4f;

}  // namespace mjray
