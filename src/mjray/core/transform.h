#pragma once
/// Affine transforms with their inverses, named by the frames they map between
/// (e.g. `world_from_object`).

#include <array>

#include "mjray/core/bounds.h"
#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// A 4×4 row-major matrix.
struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{};

  static Matrix4 identity();
  Matrix4 operator*(const Matrix4& b) const;
  Matrix4 transposed() const;
  bool operator==(const Matrix4&) const = default;
};

/// An invertible affine transform and its inverse, kept together so that normals and
/// inverse mappings never need a matrix inversion at render time.
class Transform {
 public:
  Transform() : m_(Matrix4::identity()), inverse_(Matrix4::identity()) {}
  Transform(const Matrix4& m, const Matrix4& inverse) : m_(m), inverse_(inverse) {}

  static Transform translate(const Vector3& delta);
  static Transform scale(float sx, float sy, float sz);
  /// Right-handed rotation by `degrees` about axis 0 (x), 1 (y) or 2 (z).
  static Transform rotate(int axis, float degrees);

  const Matrix4& matrix() const { return m_; }
  const Matrix4& inverse_matrix() const { return inverse_; }
  Transform inverse() const { return {inverse_, m_}; }
  Transform operator*(const Transform& b) const { return {m_ * b.m_, b.inverse_ * inverse_}; }
  bool is_identity() const { return m_ == Matrix4::identity(); }

  Point3 operator()(const Point3& p) const;
  Vector3 operator()(const Vector3& v) const;
  /// Normals map by the inverse transpose; the result is not normalised.
  Normal3 operator()(const Normal3& n) const;
  Ray operator()(const Ray& r) const { return {(*this)(r.origin), (*this)(r.direction)}; }
  /// The box around the 8 transformed corners (Arvo's bound, exact for affine maps).
  Bounds3 operator()(const Bounds3& b) const;

 private:
  Matrix4 m_;
  Matrix4 inverse_;
};

}  // namespace mjray
