#pragma once
/// The one place that starts rays at surfaces: every secondary and shadow ray goes through
/// here so that no ray re-hits the surface it leaves (pbrt-v4's OffsetRayOrigin: the origin
/// moves off the surface by the error bound of the hit point along the normal, then one more
/// float step away, so that neither the rounding of the hit point nor of the move can leave it
/// on the wrong side).

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "mjray/core/float_steps.h"
#include "mjray/core/ray.h"
#include "mjray/geometry/surface_interaction.h"

namespace mjray {

/// γ(n) = n·u / (1 − n·u), u = 2⁻²⁴: the relative error bound of n chained float operations.
constexpr float gamma_bound(int n) {
  constexpr float u = std::numeric_limits<float>::epsilon() * 0.5f;
  return (float(n) * u) / (1 - float(n) * u);
}

/// How far along the geometric normal the hit point's error box reaches.
inline float surface_offset(const SurfaceInteraction& si) {
  const Normal3& n = si.geometric_normal;
  return std::abs(n.x) * si.point_error.x + std::abs(n.y) * si.point_error.y + std::abs(n.z) * si.point_error.z;
}

/// The origin for a ray leaving `si` in `direction`: pushed along the geometric normal onto
/// the side the direction points to, out of the point's error box.
inline Point3 offset_origin(const SurfaceInteraction& si, const Vector3& direction) {
  Vector3 offset = Vector3(si.geometric_normal) * surface_offset(si);
  if (dot(si.geometric_normal, direction) < 0) offset = -offset;
  Point3 origin = si.point + offset;
  // Round away from the surface: the addition itself may have rounded toward it.
  for (int axis = 0; axis < 3; ++axis) {
    if (offset[axis] > 0) origin[axis] = next_float(origin[axis], true);
    else if (offset[axis] < 0) origin[axis] = next_float(origin[axis], false);
  }
  return origin;
}

/// A ray leaving the surface in `direction`.
inline Ray spawn_ray(const SurfaceInteraction& si, const Vector3& direction) {
  return {offset_origin(si, direction), direction};
}

/// The ray from `origin` whose t = 1 is `target`.
inline Ray ray_to(const Point3& origin, const Point3& target) { return {origin, target - origin}; }

/// A ray from the surface toward `target`, for t in (0, kShadowTMax): t = 1 is the target.
inline Ray spawn_ray_to(const SurfaceInteraction& si, const Point3& target) {
  return ray_to(offset_origin(si, target - si.point), target);
}

/// The t_max of a spawn_ray_to ray: stops just short of the target.
constexpr float kShadowTMax = 1 - 1e-4f;

}  // namespace mjray
