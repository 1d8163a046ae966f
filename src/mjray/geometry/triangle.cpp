#include "mjray/geometry/triangle.h"

#include <cmath>
#include <utility>

namespace mjray {

namespace {

int max_dimension(const Vector3& v) {
  return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}

Vector3 permute(const Vector3& v, int x, int y, int z) { return {v[x], v[y], v[z]}; }

}  // namespace

std::optional<TriangleHit> intersect_triangle(const Ray& ray, float t_max, const Point3& p0,
                                              const Point3& p1, const Point3& p2) {
  // Compute vertices relative to the ray origin, in a frame where the ray's largest
  // direction component is z, sheared so that the ray runs along +z.
  const int kz = max_dimension(abs(ray.direction));
  if (!(std::abs(ray.direction[kz]) > 0)) return std::nullopt;  // zero or NaN direction
  int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
  const Vector3 d = permute(ray.direction, kx, ky, kz);
  Vector3 a = permute(p0 - ray.origin, kx, ky, kz);
  Vector3 b = permute(p1 - ray.origin, kx, ky, kz);
  Vector3 c = permute(p2 - ray.origin, kx, ky, kz);
  const float sx = -d.x / d.z, sy = -d.y / d.z, sz = 1.f / d.z;
  a.x += sx * a.z;
  a.y += sy * a.z;
  b.x += sx * b.z;
  b.y += sy * b.z;
  c.x += sx * c.z;
  c.y += sy * c.z;

  // Compute edge functions; fall back to double when one is exactly zero so that
  // edges shared by two triangles are decided consistently.
  float e0 = b.x * c.y - b.y * c.x;
  float e1 = c.x * a.y - c.y * a.x;
  float e2 = a.x * b.y - a.y * b.x;
  if (e0 == 0 || e1 == 0 || e2 == 0) {
    e0 = float(double(b.x) * c.y - double(b.y) * c.x);
    e1 = float(double(c.x) * a.y - double(c.y) * a.x);
    e2 = float(double(a.x) * b.y - double(a.y) * b.x);
  }
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return std::nullopt;
  const float det = e0 + e1 + e2;
  if (!(det != 0) || !std::isfinite(det)) return std::nullopt;

  // Compute the scaled distance and reject hits outside (0, t_max) before dividing.
  a.z *= sz;
  b.z *= sz;
  c.z *= sz;
  const float t_scaled = e0 * a.z + e1 * b.z + e2 * c.z;
  if (det < 0 && (t_scaled >= 0 || t_scaled < t_max * det)) return std::nullopt;
  if (det > 0 && (t_scaled <= 0 || t_scaled > t_max * det)) return std::nullopt;

  const float inv_det = 1 / det;
  const float t = t_scaled * inv_det;
  if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
  return TriangleHit{t, e1 * inv_det, e2 * inv_det};
}

}  // namespace mjray
