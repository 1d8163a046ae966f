#pragma once
/// A 3×4 affine map, small enough to store beside each shape and apply inline on the ray path.

#include <array>
#include <cstring>

#include "mjray/core/ray.h"
#include "mjray/core/transform.h"
#include "mjray/core/vector.h"

namespace mjray {

/// The top three rows of an affine matrix. The arithmetic is that of Transform (double
/// products summed left to right, then rounded to float), so both give the same floats.
/// The rows are stored by column in four lanes (the fourth unused): one input
/// coordinate's products for all three outputs are one SIMD multiply, with the same
/// operations in the same order as one row at a time (shape tests map every ray they see).
struct AffineMap {
  using Row4 = std::array<double, 4>;
  std::array<Row4, 4> column{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 0}}};

  AffineMap() = default;
  explicit AffineMap(const Matrix4& matrix) {
    for (size_t j = 0; j < 4; ++j) column[j] = {matrix.m[0][j], matrix.m[1][j], matrix.m[2][j], 0};
  }

  Point3 operator()(const Point3& p) const {
    Lanes c0, c1, c2, c3;
    load_columns(c0, c1, c2);
    std::memcpy(&c3, column[3].data(), sizeof c3);  // the offsets: points only
    const Lanes out = c0 * double(p.x) + c1 * double(p.y) + c2 * double(p.z) + c3;
    return {float(out[0]), float(out[1]), float(out[2])};
  }
  Vector3 operator()(const Vector3& v) const {
    Lanes c0, c1, c2;
    load_columns(c0, c1, c2);
    const Lanes out = c0 * double(v.x) + c1 * double(v.y) + c2 * double(v.z);
    return {float(out[0]), float(out[1]), float(out[2])};
  }
  Ray operator()(const Ray& r) const { return {(*this)(r.origin), (*this)(r.direction)}; }
  /// A normal of the map's source frame carried back by the transpose: for the map
  /// object_from_world this takes object-space normals to world space.
  Normal3 transpose_apply(const Normal3& n) const {
    const double x = n.x, y = n.y, z = n.z;
    const auto dot = [&](const Row4& c) { return float(c[0] * x + c[1] * y + c[2] * z); };
    return {dot(column[0]), dot(column[1]), dot(column[2])};
  }

 private:
  // A vector type only in locals: its alignment and how it is passed depend on the
  // instruction set a file is compiled for, so neither the stored layout nor a signature
  // may hold one (the loads are unaligned).
  using Lanes = double __attribute__((vector_size(4 * sizeof(double))));

  void load_columns(Lanes& c0, Lanes& c1, Lanes& c2) const {
    std::memcpy(&c0, column[0].data(), sizeof c0);
    std::memcpy(&c1, column[1].data(), sizeof c1);
    std::memcpy(&c2, column[2].data(), sizeof c2);
  }
};

}  // namespace mjray
