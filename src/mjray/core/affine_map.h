#pragma once
/// A 3×4 affine map, small enough to store beside each shape and apply inline on the ray path.

#include <array>

#include "mjray/core/ray.h"
#include "mjray/core/transform.h"
#include "mjray/core/vector.h"

namespace mjray {

/// The top three rows of an affine matrix. The arithmetic is that of Transform (double
/// products summed left to right, then rounded to float), so both give the same floats.
/// The rows are stored by column in four-lane vectors (the fourth lane unused): one input
/// coordinate's products for all three outputs are one SIMD multiply, with the same
/// operations in the same order as one row at a time (shape tests map every ray they see).
struct AffineMap {
  using Lanes = double __attribute__((vector_size(4 * sizeof(double))));
  std::array<Lanes, 4> column{Lanes{1, 0, 0, 0}, Lanes{0, 1, 0, 0}, Lanes{0, 0, 1, 0}, Lanes{0, 0, 0, 0}};

  AffineMap() = default;
  explicit AffineMap(const Matrix4& matrix) {
    for (size_t j = 0; j < 4; ++j) column[j] = Lanes{matrix.m[0][j], matrix.m[1][j], matrix.m[2][j], 0};
  }

  Point3 operator()(const Point3& p) const {
    const Lanes out = column[0] * double(p.x) + column[1] * double(p.y) + column[2] * double(p.z) + column[3];
    return {float(out[0]), float(out[1]), float(out[2])};
  }
  Vector3 operator()(const Vector3& v) const {
    const Lanes out = column[0] * double(v.x) + column[1] * double(v.y) + column[2] * double(v.z);
    return {float(out[0]), float(out[1]), float(out[2])};
  }
  Ray operator()(const Ray& r) const { return {(*this)(r.origin), (*this)(r.direction)}; }
  /// A normal of the map's source frame carried back by the transpose: for the map
  /// object_from_world this takes object-space normals to world space.
  Normal3 transpose_apply(const Normal3& n) const {
    const double x = n.x, y = n.y, z = n.z;
    const auto dot = [&](const Lanes& c) { return float(c[0] * x + c[1] * y + c[2] * z); };
    return {dot(column[0]), dot(column[1]), dot(column[2])};
  }
};

}  // namespace mjray
