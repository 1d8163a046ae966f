#include "mjray/scene/world.h"

#include <algorithm>

#include "mjray/geometry/box.h"
#include "mjray/geometry/sphere.h"
#include "mjray/geometry/triangle.h"

namespace mjray {

std::array<Point3, 3> World::triangle_vertices(uint32_t prim) const {
  const WorldTriangle& tri = triangles[prim];
  const WorldMesh& mesh = meshes[tri.mesh];
  const auto& c = mesh.triangles[tri.face];
  return {mesh.positions[size_t(c[0].position)], mesh.positions[size_t(c[1].position)],
          mesh.positions[size_t(c[2].position)]};
}

Bounds3 World::primitive_bounds(uint32_t prim) const {
  if (is_triangle(prim)) {
    Bounds3 b;
    for (const Point3& p : triangle_vertices(prim)) b.expand(p);
    return b;
  }
  const WorldShape& s = shapes[prim - triangles.size()];
  return s.world_from_object(s.kind == NodeShape::kSphere ? unit_sphere_bounds() : unit_cube_bounds());
}

Bounds3 World::bounds() const {
  Bounds3 b;
  for (const WorldMesh& m : meshes)
    for (const Point3& p : m.positions) b.expand(p);
  for (uint32_t i = 0; i < shapes.size(); ++i) b.expand(primitive_bounds(uint32_t(triangles.size()) + i));
  return b;
}

std::optional<Hit> World::intersect_primitive(uint32_t prim, const Ray& ray, float t_max) const {
  if (is_triangle(prim)) {
    const auto v = triangle_vertices(prim);
    const auto h = intersect_triangle(ray, t_max, v[0], v[1], v[2]);
    if (!h) return std::nullopt;
    return Hit{h->t, prim, h->b1, h->b2};
  }
  const WorldShape& s = shapes[prim - triangles.size()];
  const Ray object_ray = s.world_from_object.inverse()(ray);
  const auto t = s.kind == NodeShape::kSphere ? intersect_unit_sphere(object_ray, t_max)
                                              : intersect_unit_cube(object_ray, t_max);
  if (!t) return std::nullopt;
  return Hit{*t, prim};
}

SurfaceInteraction World::interaction(const Ray& ray, const Hit& hit) const {
  SurfaceInteraction si;
  if (is_triangle(hit.prim)) {
    // Compute the point and normals from barycentrics, in world space.
    const WorldTriangle& tri = triangles[hit.prim];
    const WorldMesh& mesh = meshes[tri.mesh];
    const auto& c = mesh.triangles[tri.face];
    const Point3& p0 = mesh.positions[size_t(c[0].position)];
    const Point3& p1 = mesh.positions[size_t(c[1].position)];
    const Point3& p2 = mesh.positions[size_t(c[2].position)];
    const float b0 = 1 - hit.u - hit.v;
    const Vector3 weighted = Vector3(p0.x, p0.y, p0.z) * b0 + Vector3(p1.x, p1.y, p1.z) * hit.u +
                             Vector3(p2.x, p2.y, p2.z) * hit.v;
    si.point = {weighted.x, weighted.y, weighted.z};
    si.geometric_normal = normalize(Normal3(cross(p1 - p0, p2 - p0)));
    si.shading_normal = si.geometric_normal;
    if (c[0].normal >= 0 && c[1].normal >= 0 && c[2].normal >= 0) {
      const Vector3 n = Vector3(mesh.normals[size_t(c[0].normal)]) * b0 +
                        Vector3(mesh.normals[size_t(c[1].normal)]) * hit.u +
                        Vector3(mesh.normals[size_t(c[2].normal)]) * hit.v;
      if (length(n) > 0) si.shading_normal = face_forward(normalize(Normal3(n)), Vector3(si.geometric_normal));
    }
    if (c[0].uv >= 0 && c[1].uv >= 0 && c[2].uv >= 0) {
      const Point2 &t0 = mesh.uvs[size_t(c[0].uv)], &t1 = mesh.uvs[size_t(c[1].uv)], &t2 = mesh.uvs[size_t(c[2].uv)];
      si.uv = {b0 * t0.u + hit.u * t1.u + hit.v * t2.u, b0 * t0.v + hit.u * t1.v + hit.v * t2.v};
    }
    si.object_point = mesh.world_from_object.inverse()(si.point);
    si.material = mesh.material;
    return si;
  }
  // Compute shape data in object space and map it back to the world.
  const WorldShape& s = shapes[hit.prim - triangles.size()];
  const Ray object_ray = s.world_from_object.inverse()(ray);
  Point3 p = object_ray.at(hit.t);
  Normal3 n;
  if (s.kind == NodeShape::kSphere) {
    const Vector3 radial = normalize(Vector3(p.x, p.y, p.z));
    p = {radial.x, radial.y, radial.z};  // project back onto the surface
    n = unit_sphere_normal(p);
    si.uv = unit_sphere_uv(p);
  } else {
    const CubeFace face = unit_cube_face(p);
    p[face.axis] = face.side > 0 ? 1.f : 0.f;  // onto the face, so that textures see its plane exactly
    n = unit_cube_normal(p);
    si.uv = unit_cube_uv(p);
  }
  si.object_point = s.node_from_object(p);
  si.point = s.world_from_object(p);
  si.geometric_normal = normalize(s.world_from_object(n));
  si.shading_normal = si.geometric_normal;
  si.material = s.material;
  return si;
}

Color World::background_radiance(const Vector3& direction) const {
  const float up = std::clamp(direction.y / length(direction), 0.f, 1.f);
  return background.horizon * (1 - up) + background.zenith * up;
}

}  // namespace mjray
