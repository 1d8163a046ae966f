#pragma once
/// What accelerators index: world-space triangles and placed analytic shapes, numbered as
/// primitives. Holds no shading data (normals, uvs, materials live in scene/World).

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mjray/core/affine_map.h"
#include "mjray/core/bounds.h"
#include "mjray/core/ray.h"
#include "mjray/geometry/hit.h"
#include "mjray/geometry/shape.h"

namespace mjray {

/// A unit shape placed in the world.
struct ShapeInstance {
  Shape shape;
  AffineMap object_from_world;  ///< maps world rays into the shape's frame
  Bounds3 world_bounds;         ///< Arvo's box of the transformed unit shape, padded for rounding
};

/// Primitive ids [0, triangles.size()) are triangles; the rest are shapes, id
/// triangles.size() + index.
class PrimitiveSet {
 public:
  std::vector<Point3> vertices;                     ///< world space, of every mesh instance
  std::vector<std::array<uint32_t, 3>> triangles;   ///< indices into vertices
  std::vector<ShapeInstance> shapes;
  /// One flag per primitive when any primitive may let shadow rays through (glass); empty when
  /// every primitive is opaque.
  std::vector<uint8_t> transmissive_flags;

  /// Whether shadow rays may continue past primitive `prim`.
  bool transmissive(uint32_t prim) const { return !transmissive_flags.empty() && transmissive_flags[prim]; }
  bool any_transmissive() const { return !transmissive_flags.empty(); }
  /// Whether a filtered query asks `filter_sees_opaque`-filters about primitive `prim`.
  bool filtered(uint32_t prim, bool filter_sees_opaque) const { return filter_sees_opaque || transmissive(prim); }

  uint32_t size() const { return uint32_t(triangles.size() + shapes.size()); }
  bool is_triangle(uint32_t prim) const { return prim < triangles.size(); }
  const ShapeInstance& shape(uint32_t prim) const { return shapes[prim - triangles.size()]; }

  /// The three world-space corners of triangle primitive `prim`.
  std::array<Point3, 3> triangle_vertices(uint32_t prim) const {
    const auto& t = triangles[prim];
    return {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
  }
  /// Appends a unit shape placed in the world by `world_from_object`.
  void add_shape(const Shape& shape, const Transform& world_from_object);
  /// Appends triangles over `world_positions` (indices local to them).
  void add_triangles(const std::vector<Point3>& world_positions, const std::vector<std::array<uint32_t, 3>>& faces);

  /// World-space bounds of one primitive.
  Bounds3 primitive_bounds(uint32_t prim) const;
  /// Bounds of everything.
  Bounds3 bounds() const;
  /// Intersects one primitive for t in `t_range`.
  std::optional<Hit> intersect(uint32_t prim, const Ray& ray, Interval t_range) const;
  /// Intersects one shape (prim ≥ triangles.size()) for t in `t_range`.
  std::optional<Hit> intersect_shape(uint32_t prim, const Ray& ray, Interval t_range) const {
    const ShapeInstance& s = shape(prim);
    const Ray object_ray = s.object_from_world(ray);
    const auto t = std::visit([&](const auto& shape) { return shape.intersect(object_ray, t_range); }, s.shape);
    if (!t) return std::nullopt;
    return Hit{*t, prim};
  }
};

}  // namespace mjray
