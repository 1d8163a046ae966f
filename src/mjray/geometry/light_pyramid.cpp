#include "mjray/geometry/light_pyramid.h"

#include <algorithm>
#include <cmath>

namespace mjray {

std::optional<LightPyramid> LightPyramid::make(const Point3& apex, const std::array<Point3, 4>& base) {
  LightPyramid p;
  p.vertices_ = {apex, base[0], base[1], base[2], base[3]};
  float magnitude = 0;
  for (const Point3& v : p.vertices_) {
    p.bounds_.expand(v);
    magnitude = std::max(magnitude, max_component(abs(v)));
  }
  // Rounding of a plane test is a few ulps of the coordinates; a generous multiple keeps the
  // answer conservative, at the price of a few more rays traced near the pyramid's faces.
  p.margin_ = 64 * std::numeric_limits<float>::epsilon() * std::max(magnitude, 1.f);
  const Point3 centre = Point3(0, 0, 0) + (Vector3(base[0].x, base[0].y, base[0].z) + Vector3(base[2].x, base[2].y, base[2].z)) * 0.5f;
  const Point3 inside = apex + (centre - apex) * 0.5f;  // a point within the solid
  const auto plane = [&](const Point3& a, const Point3& b, const Point3& c) -> std::optional<Plane> {
    Vector3 n = cross(b - a, c - a);
    const float length = std::sqrt(dot(n, n));
    if (!(length > 0) || !std::isfinite(length)) return std::nullopt;
    n = n / length;
    if (dot(n, inside - a) > 0) n = -n;  // outward
    return Plane{n, dot(n, Vector3(a.x, a.y, a.z))};
  };
  for (int i = 0; i < 4; ++i) {
    const auto side = plane(apex, base[size_t(i)], base[size_t((i + 1) % 4)]);
    if (!side) return std::nullopt;
    p.planes_[size_t(i)] = *side;
  }
  const auto back = plane(base[0], base[1], base[2]);
  if (!back) return std::nullopt;
  p.planes_[4] = *back;
  // The apex must lie off the base's plane by more than the margin.
  if (!(dot(p.planes_[4].n, Vector3(apex.x, apex.y, apex.z)) < p.planes_[4].d - 4 * p.margin_)) return std::nullopt;
  return p;
}

bool LightPyramid::outside(const Bounds3& box) const {
  // The one-lane case of the row test, so that both say the same.
  const std::array<std::array<float, 1>, 6> rows{{{box.lo.x}, {box.lo.y}, {box.lo.z}, {box.hi.x}, {box.hi.y}, {box.hi.z}}};
  return outside(rows) != 0;
}

bool LightPyramid::outside(const Point3& p0, const Point3& p1, const Point3& p2) const {
  Bounds3 box;
  box.expand(p0), box.expand(p1), box.expand(p2);
  for (int a = 0; a < 3; ++a)
    if (box.lo[a] > bounds_.hi[a] + margin_ || box.hi[a] < bounds_.lo[a] - margin_) return true;
  // Wholly beyond one face of the pyramid.
  for (const Plane& plane : planes_) {
    const auto beyond = [&](const Point3& q) { return dot(plane.n, Vector3(q.x, q.y, q.z)) > plane.d + margin_; };
    if (beyond(p0) && beyond(p1) && beyond(p2)) return true;
  }
  // The whole pyramid on one side of the triangle's plane.
  const Vector3 n = cross(p1 - p0, p2 - p0);
  const float length = std::sqrt(dot(n, n));
  if (!(length > 0)) return true;  // a degenerate triangle is never hit
  const Vector3 unit = n / length;
  int above = 0, below = 0;
  for (const Point3& v : vertices_) {
    const float s = dot(unit, v - p0);
    above += s > margin_;
    below += s < -margin_;
  }
  return above == 5 || below == 5;
}

}  // namespace mjray
