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
  /// For N boxes given axis by axis (rows: lower x, y, z, upper x, y, z), a bit per box that
  /// surely misses the pyramid: outside(Bounds3) for all of them at once, in SIMD lanes.
  template <size_t N>
  unsigned outside(const std::array<std::array<float, N>, 6>& boxes) const;
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

template <size_t N>
unsigned LightPyramid::outside(const std::array<std::array<float, N>, 6>& boxes) const {
  static_assert(N <= 32);
  // Branch-free lane loops, which the compiler turns into SIMD compares.
  std::array<int, N> out{};
  for (size_t a = 0; a < 3; ++a) {
    const float above = bounds_.hi[int(a)] + margin_, below = bounds_.lo[int(a)] - margin_;
    for (size_t i = 0; i < N; ++i) out[i] |= int(boxes[a][i] > above) | int(boxes[a + 3][i] < below);
  }
  for (const Plane& plane : planes_) {
    // The box corner deepest inside the plane, row by row.
    const auto& x = boxes[plane.n.x > 0 ? 0 : 3];
    const auto& y = boxes[plane.n.y > 0 ? 1 : 4];
    const auto& z = boxes[plane.n.z > 0 ? 2 : 5];
    const float limit = plane.d + margin_;
    for (size_t i = 0; i < N; ++i) out[i] |= int(plane.n.x * x[i] + plane.n.y * y[i] + plane.n.z * z[i] > limit);
  }
  unsigned mask = 0;
  for (size_t i = 0; i < N; ++i) mask |= unsigned(out[i]) << i;
  return mask;
}

}  // namespace mjray
