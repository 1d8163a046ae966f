#pragma once
/// A 3×4 affine map, small enough to store beside each shape and apply inline on the ray path.

#include <array>

#include "mjray/core/ray.h"
#include "mjray/core/transform.h"
#include "mjray/core/vector.h"

namespace mjray {

/// The top three rows of an affine matrix. The arithmetic is that of Transform (double
/// products summed left to right, then rounded to float), so both give the same floats.
struct AffineMap {
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  AffineMap() = default;
  explicit AffineMap(const Matrix4& matrix) {
    for (size_t i = 0; i < 3; ++i) m[i] = matrix.m[i];
  }

  Point3 operator()(const Point3& p) const {
    const double x = p.x, y = p.y, z = p.z;
    return {float(m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3]),
            float(m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3]),
            float(m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3])};
  }
  Vector3 operator()(const Vector3& v) const {
    const double x = v.x, y = v.y, z = v.z;
    return {float(m[0][0] * x + m[0][1] * y + m[0][2] * z),
            float(m[1][0] * x + m[1][1] * y + m[1][2] * z),
            float(m[2][0] * x + m[2][1] * y + m[2][2] * z)};
  }
  Ray operator()(const Ray& r) const { return {(*this)(r.origin), (*this)(r.direction)}; }
  /// A normal of the map's source frame carried back by the transpose: for the map
  /// object_from_world this takes object-space normals to world space.
  Normal3 transpose_apply(const Normal3& n) const {
    const double x = n.x, y = n.y, z = n.z;
    return {float(m[0][0] * x + m[1][0] * y + m[2][0] * z),
            float(m[0][1] * x + m[1][1] * y + m[2][1] * z),
            float(m[0][2] * x + m[1][2] * y + m[2][2] * z)};
  }
};

}  // namespace mjray
