#pragma once
/// The unit sphere at the origin of its object frame; placed in the world by a transform
/// (covers gr.sphere and gr.nh_sphere).

#include <optional>

#include "mjray/core/bounds.h"
#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// Nearest t in the open range `t_range` where the object-space ray meets the unit sphere, or nothing.
std::optional<float> intersect_unit_sphere(const Ray& object_ray, Interval t_range);

/// The object-space bounds of the unit sphere.
inline Bounds3 unit_sphere_bounds() { return {{-1, -1, -1}, {1, 1, 1}}; }

/// Outward object-space normal at a point on the unit sphere.
inline Normal3 unit_sphere_normal(const Point3& p) { return Normal3(p.x, p.y, p.z); }

/// Spherical (u, v) in [0,1]²: u from the azimuth φ about y (0 at +x, growing from +x toward
/// −z), v = 1 − θ/π from the polar angle θ (v = 1 at the north pole, +y).
Point2 unit_sphere_uv(const Point3& p);

}  // namespace mjray
