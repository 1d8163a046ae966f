#pragma once
/// 3-D points, vectors and normals as distinct types, so that transforms treat each correctly
/// (points translate, vectors do not, normals use the inverse transpose).

#include <algorithm>
#include <cmath>

namespace mjray {

/// A direction or displacement in 3-D.
struct Vector3 {
  float x = 0, y = 0, z = 0;

  constexpr Vector3() = default;
  constexpr Vector3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}

  constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vector3 operator+(const Vector3& v) const { return {x + v.x, y + v.y, z + v.z}; }
  constexpr Vector3 operator-(const Vector3& v) const { return {x - v.x, y - v.y, z - v.z}; }
  constexpr Vector3 operator-() const { return {-x, -y, -z}; }
  constexpr Vector3 operator*(float s) const { return {x * s, y * s, z * s}; }
  constexpr Vector3 operator/(float s) const { return {x / s, y / s, z / s}; }
  constexpr Vector3& operator+=(const Vector3& v) { return *this = *this + v; }
  constexpr bool operator==(const Vector3&) const = default;
};

constexpr Vector3 operator*(float s, const Vector3& v) { return v * s; }

/// A position in 3-D.
struct Point3 {
  float x = 0, y = 0, z = 0;

  constexpr Point3() = default;
  constexpr Point3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}

  constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Point3 operator+(const Vector3& v) const { return {x + v.x, y + v.y, z + v.z}; }
  constexpr Point3 operator-(const Vector3& v) const { return {x - v.x, y - v.y, z - v.z}; }
  constexpr Vector3 operator-(const Point3& p) const { return {x - p.x, y - p.y, z - p.z}; }
  constexpr bool operator==(const Point3&) const = default;
};

/// A surface normal: transforms by the inverse transpose of the point transform.
struct Normal3 {
  float x = 0, y = 0, z = 0;

  constexpr Normal3() = default;
  constexpr Normal3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  constexpr explicit Normal3(const Vector3& v) : x(v.x), y(v.y), z(v.z) {}
  constexpr explicit operator Vector3() const { return {x, y, z}; }

  constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Normal3 operator-() const { return {-x, -y, -z}; }
  constexpr bool operator==(const Normal3&) const = default;
};

constexpr float dot(const Vector3& a, const Vector3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr float dot(const Normal3& n, const Vector3& v) { return n.x * v.x + n.y * v.y + n.z * v.z; }
constexpr float dot(const Vector3& v, const Normal3& n) { return dot(n, v); }

constexpr Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

inline float length(const Vector3& v) { return std::sqrt(dot(v, v)); }

/// v at unit length when its squared length under- or overflows a float (tiny or huge
/// transformed normals, near-degenerate triangles); the zero vector stays zero, never NaN.
inline Vector3 normalize_rescaled(const Vector3& v) {
  const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(largest > 0)) return v * 0.f;      // zero stays zero (and NaN stays NaN)
  if (!std::isfinite(largest)) return {};  // an infinite vector has no direction
  const Vector3 w = v / largest;
  return w / std::sqrt(dot(w, w));
}

/// v at unit length; the common case costs one comparison more than v / length(v).
inline Vector3 normalize(const Vector3& v) {
  const float squared = dot(v, v);
  if (squared > 1e-30f && squared < 1e30f) [[likely]] return v / std::sqrt(squared);
  return normalize_rescaled(v);
}
inline Normal3 normalize(const Normal3& n) { return Normal3(normalize(Vector3(n))); }

/// The normal flipped, if needed, to lie in the same hemisphere as v.
constexpr Normal3 face_forward(const Normal3& n, const Vector3& v) { return dot(n, v) < 0 ? -n : n; }

constexpr float max_component(const Vector3& v) { return std::max({v.x, v.y, v.z}); }
inline Vector3 abs(const Vector3& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
inline Vector3 abs(const Point3& p) { return {std::abs(p.x), std::abs(p.y), std::abs(p.z)}; }

inline Point3 min(const Point3& a, const Point3& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Point3 max(const Point3& a, const Point3& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

inline bool is_finite(const Vector3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool is_finite(const Point3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/// A texture coordinate pair.
struct Point2 {
  float u = 0, v = 0;
  constexpr bool operator==(const Point2&) const = default;
};

}  // namespace mjray
