#pragma once
/// The unit cube [0,1]³ of its object frame; placed by a transform (gr.cube, gr.nh_box).

#include <optional>

#include "mjray/core/bounds.h"
#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// Nearest t in the open range `t_range` where the object-space ray meets the unit cube's surface.
std::optional<float> intersect_unit_cube(const Ray& object_ray, Interval t_range);

inline Bounds3 unit_cube_bounds() { return {{0, 0, 0}, {1, 1, 1}}; }

/// The axis (0..2) and side (−1 or +1) of the face that `p` (on the surface) lies on.
struct CubeFace {
  int axis;
  int side;
};
CubeFace unit_cube_face(const Point3& p);

/// Outward object-space normal of the face at p.
Normal3 unit_cube_normal(const Point3& p);

/// Per-face (u, v) in [0,1]²: the two coordinates of p other than the face's axis.
Point2 unit_cube_uv(const Point3& p);

}  // namespace mjray
