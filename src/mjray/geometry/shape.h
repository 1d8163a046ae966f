#pragma once
/// The closed set of analytic shapes: unit primitives in their own frame, placed in the world
/// by a transform (gr.sphere and gr.nh_sphere, gr.cube and gr.nh_box).
///
/// To add a shape: write `<name>.h/.cpp` with the unit primitive's intersection, a struct
/// below with `object_bounds()`, `object_bounding_sphere()`, `intersect(object_ray, t_range)`
/// (convex: see kMaxShapeCrossings),
/// `surface(object_point)` and `uv(surface_point)`,
/// add it to `Shape`, bind it in `lua/gr_bindings.cpp`, and test it in
/// `tests/unit/geometry/geometry_test.cpp` (the accelerator oracles then cover it).

#include <optional>
#include <variant>

#include "mjray/core/bounds.h"
#include "mjray/core/ray.h"
#include "mjray/geometry/box.h"
#include "mjray/geometry/sphere.h"

namespace mjray {

/// Where a unit shape's surface is at a hit, in the shape's own frame.
struct ShapeSurface {
  Point3 point;    ///< the hit moved exactly onto the surface
  Normal3 normal;  ///< outward, not necessarily unit
};

/// A ball holding a shape, in its own frame.
struct BoundingSphere {
  Point3 centre;
  float radius = 0;
};

/// The unit sphere at the origin.
struct UnitSphere {
  static Bounds3 object_bounds() { return unit_sphere_bounds(); }
  static BoundingSphere object_bounding_sphere() { return {{0, 0, 0}, 1}; }
  static std::optional<float> intersect(const Ray& object_ray, Interval t_range) {
    return intersect_unit_sphere(object_ray, t_range);
  }
  static ShapeSurface surface(const Point3& hit) {
    const Vector3 radial = normalize(Vector3(hit.x, hit.y, hit.z));
    const Point3 p{radial.x, radial.y, radial.z};  // project back onto the surface
    return {p, unit_sphere_normal(p)};
  }
  static Point2 uv(const Point3& surface_point) { return unit_sphere_uv(surface_point); }
};

/// The unit cube [0,1]³.
struct UnitCube {
  static Bounds3 object_bounds() { return unit_cube_bounds(); }
  static BoundingSphere object_bounding_sphere() { return {{0.5f, 0.5f, 0.5f}, 0.8660254f}; }
  static std::optional<float> intersect(const Ray& object_ray, Interval t_range) {
    return intersect_unit_cube(object_ray, t_range);
  }
  static ShapeSurface surface(const Point3& hit) {
    Point3 p = hit;
    const CubeFace face = unit_cube_face(p);
    p[face.axis] = face.side > 0 ? 1.f : 0.f;  // onto the face, so that textures see its plane exactly
    return {p, unit_cube_normal(p)};
  }
  static Point2 uv(const Point3& surface_point) { return unit_cube_uv(surface_point); }
};

using Shape = std::variant<UnitSphere, UnitCube>;

/// Every shape is convex and its intersect() returns its entry or its exit, nothing else: a ray
/// crosses a shape at most this many times (a shadow ray through glass stops looking after).
constexpr int kMaxShapeCrossings = 2;

}  // namespace mjray
