#include "mjray/scene/world.h"

#include <algorithm>
#include <cmath>

#include "mjray/geometry/spawn_ray.h"

namespace mjray {

namespace {

/// Error bound of a point computed as world_from_object(p) from a unit-shape surface point p
/// (itself within a few ulps of the surface): p's own error carried by |M|, the rounding of the
/// mapped point, and that of mapping a ray origin back into the shape's frame, so that a ray
/// leaving from outside the bound stays on its side in both frames.
Vector3 transformed_point_error(const Matrix4& world_from_object, const Point3& p) {
  const auto& m = world_from_object.m;
  Vector3 error;
  for (int i = 0; i < 3; ++i) {
    const double linear = std::abs(m[i][0] * p.x) + std::abs(m[i][1] * p.y) + std::abs(m[i][2] * p.z);
    error[i] = float(linear * gamma_bound(5) + (linear + std::abs(m[i][3])) * gamma_bound(3));
  }
  return error;
}

}  // namespace

const WorldMesh& World::mesh_of(uint32_t triangle) const {
  const auto after = std::upper_bound(meshes.begin(), meshes.end(), triangle,
                                      [](uint32_t t, const WorldMesh& m) { return t < m.first_triangle; });
  return *(after - 1);
}

SurfaceInteraction World::interaction(const Ray& ray, const Hit& hit) const { return shade<true>(ray, hit); }

SurfaceInteraction World::crossing(const Ray& ray, const Hit& hit) const { return shade<false>(ray, hit); }

template <bool kFull>
SurfaceInteraction World::shade(const Ray& ray, const Hit& hit) const {
  SurfaceInteraction si;
  if (primitives.is_triangle(hit.prim)) {
    // Compute the point and normals from barycentrics, in world space.
    const WorldMesh& mesh = mesh_of(hit.prim);
    // The face's normal and texture coordinate indices, if the mesh has any.
    static constexpr std::array<MeshCorner, 3> kNoCorners{};
    const auto& c = mesh.corners.empty() ? kNoCorners : mesh.corners[hit.prim - mesh.first_triangle];
    const auto [p0, p1, p2] = primitives.triangle_vertices(hit.prim);
    const float b0 = 1 - hit.u - hit.v;
    const Vector3 weighted = Vector3(p0.x, p0.y, p0.z) * b0 + Vector3(p1.x, p1.y, p1.z) * hit.u +
                             Vector3(p2.x, p2.y, p2.z) * hit.v;
    si.point = {weighted.x, weighted.y, weighted.z};
    // The interpolation's error bound (pbrt-v4's, for barycentric points).
    si.point_error = (abs(Vector3(p0.x, p0.y, p0.z) * b0) + abs(Vector3(p1.x, p1.y, p1.z) * hit.u) +
                      abs(Vector3(p2.x, p2.y, p2.z) * hit.v)) * gamma_bound(7);
    si.geometric_normal = normalize(Normal3(cross(p1 - p0, p2 - p0)));
    si.shading_normal = si.geometric_normal;
    if (c[0].normal >= 0 && c[1].normal >= 0 && c[2].normal >= 0) {
      const Vector3 n = Vector3(mesh.normals[size_t(c[0].normal)]) * b0 +
                        Vector3(mesh.normals[size_t(c[1].normal)]) * hit.u +
                        Vector3(mesh.normals[size_t(c[2].normal)]) * hit.v;
      if (length(n) > 0) si.shading_normal = face_forward(normalize(Normal3(n)), Vector3(si.geometric_normal));
    }
    si.material = mesh.material;
    si.prim = hit.prim;
    if (!kFull || !reads_texture(si.material)) return si;
    if (c[0].uv >= 0 && c[1].uv >= 0 && c[2].uv >= 0) {
      const Point2 &t0 = mesh.uvs[size_t(c[0].uv)], &t1 = mesh.uvs[size_t(c[1].uv)], &t2 = mesh.uvs[size_t(c[2].uv)];
      si.uv = {b0 * t0.u + hit.u * t1.u + hit.v * t2.u, b0 * t0.v + hit.u * t1.v + hit.v * t2.v};
    }
    si.object_point = mesh.world_from_object.inverse()(si.point);
    return si;
  }
  // Compute shape data in object space and map it back to the world.
  const ShapeInstance& instance = primitives.shape(hit.prim);
  const WorldShape& s = shapes[hit.prim - primitives.triangles.size()];
  const Ray object_ray = instance.object_from_world(ray);
  const ShapeSurface surface =
      std::visit([&](const auto& shape) { return shape.surface(object_ray.at(hit.t)); }, instance.shape);
  si.point = s.world_from_object(surface.point);
  si.point_error = transformed_point_error(s.world_from_object.matrix(), surface.point);
  si.geometric_normal = normalize(s.world_from_object(surface.normal));
  si.shading_normal = si.geometric_normal;
  si.material = s.material;
  si.prim = hit.prim;
  if (!kFull || !reads_texture(si.material)) return si;
  si.uv = std::visit([&](const auto& shape) { return shape.uv(surface.point); }, instance.shape);
  si.object_point = s.node_from_object(surface.point);
  return si;
}

Color World::background_radiance(const Vector3& direction) const { return background.radiance(direction); }

}  // namespace mjray
