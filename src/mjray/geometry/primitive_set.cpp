#include "mjray/geometry/primitive_set.h"

#include "mjray/geometry/triangle.h"

namespace mjray {

namespace {

/// A shape's box grown by 1e-4 of its coordinates' size. A shape is tested in its own frame
/// against the world ray mapped there and rounded, so a grazing hit can lie just outside the
/// box of the exact shape; accelerators cull by these boxes, and would then lose a hit that a
/// test of every primitive finds. The margin covers rays from up to about a thousand times
/// the box's distance from the origin.
Bounds3 padded(const Bounds3& b) {
  const float margin = 1e-4f * (max_component(abs(b.lo)) + max_component(abs(b.hi)));
  const Vector3 pad(margin, margin, margin);
  return {b.lo - pad, b.hi + pad};
}

}  // namespace

void PrimitiveSet::add_shape(const Shape& s, const Transform& world_from_object) {
  const Bounds3 object_bounds = std::visit([](const auto& shape) { return shape.object_bounds(); }, s);
  shapes.push_back({s, AffineMap(world_from_object.inverse_matrix()), padded(world_from_object(object_bounds))});
}

void PrimitiveSet::add_triangles(const std::vector<Point3>& world_positions,
                                 const std::vector<std::array<uint32_t, 3>>& faces) {
  const auto first = uint32_t(vertices.size());
  vertices.insert(vertices.end(), world_positions.begin(), world_positions.end());
  for (const auto& f : faces) triangles.push_back({first + f[0], first + f[1], first + f[2]});
}

Bounds3 PrimitiveSet::primitive_bounds(uint32_t prim) const {
  if (!is_triangle(prim)) return shape(prim).world_bounds;
  Bounds3 b;
  for (const Point3& p : triangle_vertices(prim)) b.expand(p);
  return b;
}

Bounds3 PrimitiveSet::bounds() const {
  Bounds3 b;
  for (const Point3& p : vertices) b.expand(p);
  for (const ShapeInstance& s : shapes) b.expand(s.world_bounds);
  return b;
}

std::optional<Hit> PrimitiveSet::intersect(uint32_t prim, const Ray& ray, Interval t_range) const {
  if (!is_triangle(prim)) return intersect_shape(prim, ray, t_range);
  const auto v = triangle_vertices(prim);
  const auto h = intersect_triangle(ray, t_range, v[0], v[1], v[2]);
  if (!h) return std::nullopt;
  return Hit{h->t, prim, h->b1, h->b2};
}

}  // namespace mjray
