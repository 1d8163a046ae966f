#pragma once
/// Watertight ray/triangle intersection (Woop, Benthin and Wald 2013): rays through a shared
/// edge or vertex hit at least one of the triangles that share it.

#include <optional>

#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// Where a ray meets a triangle: distance and barycentric weights of p1 and p2
/// (the weight of p0 is 1 − b1 − b2).
struct TriangleHit {
  float t;
  float b1;
  float b2;
};

/// The hit of `ray` with triangle (p0, p1, p2) for t in (0, t_max), or nothing.
/// Never reports a hit for NaN/Inf input or a degenerate (zero-area) triangle.
std::optional<TriangleHit> intersect_triangle(const Ray& ray, float t_max, const Point3& p0,
                                              const Point3& p1, const Point3& p2);

}  // namespace mjray
