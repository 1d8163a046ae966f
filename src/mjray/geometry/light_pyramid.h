#pragma once
/// The solid that every shadow ray from one point to one flat light lies in: the pyramid of
/// the point and the light's four corners. If no primitive can touch it, every one of those
/// rays reaches the light, and none needs tracing.

#include <array>
#include <optional>

#include "mjray/core/bounds.h"
#include "mjray/core/vector.h"

namespace mjray {

/// A convex pyramid with its apex at a ray origin and a parallelogram base, as its five
/// bounding planes (outward normals) and its box. Tests are conservative: "outside" is said
/// only when sure, with a margin for float rounding.
class LightPyramid {
 public:
  /// The pyramid of `apex` and the parallelogram `base` (corners in order around it); nothing
  /// when it is degenerate (the apex in the base's plane, or a base of no area).
  static std::optional<LightPyramid> make(const Point3& apex, const std::array<Point3, 4>& base);

  const Bounds3& bounds() const { return bounds_; }
  /// Whether the box surely misses the pyramid.
  bool outside(const Bounds3& box) const;
  /// Whether the triangle surely misses the pyramid.
  bool outside(const Point3& p0, const Point3& p1, const Point3& p2) const;

 private:
  struct Plane {
    Vector3 n;
    float d;  ///< points x with dot(n, x) > d are outside
  };
  std::array<Plane, 5> planes_{};
  std::array<Point3, 5> vertices_{};
  Bounds3 bounds_;
  float margin_ = 0;  ///< slack in distance units (float rounding of the plane tests)
};

}  // namespace mjray
