#pragma once
/// What is known about a surface where a ray hit it: the input of every shading question.

#include <cstdint>

#include "mjray/core/vector.h"

namespace mjray {

/// Everything the integrator needs to shade a hit, computed once for the closest hit.
struct SurfaceInteraction {
  Point3 point;              ///< world space
  /// Per-axis bound on the floating-point error of `point` (world space): rays leave the
  /// surface from outside this box (spawn_ray.h).
  Vector3 point_error;
  Normal3 geometric_normal;  ///< unit, world space, as the surface is oriented (not flipped)
  Normal3 shading_normal;    ///< unit, world space, on the same side as geometric_normal
  Point2 uv;
  /// The hit in the frame the primitive's geometry is written in, where solid textures are
  /// evaluated: the unit shape's frame for gr.sphere/gr.cube, the node's frame for
  /// nh_sphere/nh_box (whose centre and corner are given there) and meshes.
  Point3 object_point;
  uint32_t material = 0;     ///< index into World::materials
  uint32_t prim = 0;         ///< the primitive hit
};

}  // namespace mjray
