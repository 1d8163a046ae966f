#include "mjray/geometry/box.h"

#include <cmath>
#include <utility>

namespace mjray {

std::optional<float> intersect_unit_cube(const Ray& r, Interval t_range) {
  // Slab test (Williams et al. 2005): IEEE infinities handle axis-parallel rays.
  float t_enter = -kInfinity, t_exit = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    const float inv = 1 / r.direction[axis];
    float t0 = (0 - r.origin[axis]) * inv;
    float t1 = (1 - r.origin[axis]) * inv;
    if (std::isnan(t0) || std::isnan(t1)) {
      // A zero direction component with the origin on a face plane: inside iff within [0,1].
      if (!(r.origin[axis] >= 0 && r.origin[axis] <= 1)) return std::nullopt;
      continue;
    }
    if (t0 > t1) std::swap(t0, t1);
    t_enter = std::max(t_enter, t0);
    t_exit = std::min(t_exit, t1);
  }
  if (!(t_enter <= t_exit)) return std::nullopt;
  // From outside the ray hits the entry face; from inside, the exit face.
  const float t = t_enter > t_range.min ? t_enter : t_exit;
  if (!(t > t_range.min) || !(t < t_range.max)) return std::nullopt;
  return t;
}

CubeFace unit_cube_face(const Point3& p) {
  // Pick the coordinate closest to a face plane (0 or 1).
  CubeFace best{0, -1};
  float best_distance = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    const float d0 = std::abs(p[axis]), d1 = std::abs(p[axis] - 1);
    if (d0 < best_distance) best_distance = d0, best = {axis, -1};
    if (d1 < best_distance) best_distance = d1, best = {axis, +1};
  }
  return best;
}

Normal3 unit_cube_normal(const Point3& p) {
  const CubeFace f = unit_cube_face(p);
  Vector3 n;
  n[f.axis] = float(f.side);
  return Normal3(n);
}

Point2 unit_cube_uv(const Point3& p) {
  // Each face shows the image upright and unmirrored from outside (right × up = the outward
  // normal): the side faces with +y up; the top with its upper edge at the back (−z) and the
  // bottom with its upper edge at the front (+z), as the faces of a cross-shaped net folded
  // around the front face.
  const CubeFace f = unit_cube_face(p);
  const float x = std::clamp(p.x, 0.f, 1.f), y = std::clamp(p.y, 0.f, 1.f), z = std::clamp(p.z, 0.f, 1.f);
  switch (f.axis) {
    case 0: return f.side > 0 ? Point2{1 - z, y} : Point2{z, y};
    case 1: return f.side > 0 ? Point2{x, 1 - z} : Point2{x, z};
    default: return f.side > 0 ? Point2{x, y} : Point2{1 - x, y};
  }
}

}  // namespace mjray
