#pragma once
/// Warping uniform random numbers into directions and points.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mjray/core/vector.h"

namespace mjray {

/// Two unit vectors that complete the unit `axis` to a right-handed orthonormal frame
/// (Duff et al. 2017: no branch on a near-parallel helper vector).
struct Basis {
  Vector3 tangent, bitangent;
};
inline Basis orthonormal_basis(const Vector3& axis) {
  const float sign = std::copysign(1.f, axis.z);
  const float a = -1 / (sign + axis.z), b = axis.x * axis.y * a;
  return {{1 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x}, {b, sign + axis.y * axis.y * a, -axis.y}};
}

/// A unit vector within acos(cos_max) of the unit `axis`, uniform over the cone's solid angle,
/// from two uniform numbers in [0, 1).
inline Vector3 sample_cone(const Vector3& axis, float cos_max, float u1, float u2) {
  const float cos_theta = 1 - u1 * (1 - cos_max);
  const float sin_theta = std::sqrt(std::max(0.f, 1 - cos_theta * cos_theta));
  const float phi = 2 * std::numbers::pi_v<float> * u2;
  const Basis frame = orthonormal_basis(axis);
  return normalize(frame.tangent * (sin_theta * std::cos(phi)) + frame.bitangent * (sin_theta * std::sin(phi)) +
                   axis * cos_theta);
}

/// A unit vector on the hemisphere around the unit `axis` with density cos θ / π.
inline Vector3 sample_cosine_hemisphere(const Vector3& axis, float u1, float u2) {
  const float r = std::sqrt(u1), phi = 2 * std::numbers::pi_v<float> * u2;
  const float cos_theta = std::sqrt(std::max(0.f, 1 - u1));
  const Basis frame = orthonormal_basis(axis);
  return normalize(frame.tangent * (r * std::cos(phi)) + frame.bitangent * (r * std::sin(phi)) + axis * cos_theta);
}

/// A unit vector uniform over the sphere (density 1 / 4π).
inline Vector3 sample_uniform_sphere(float u1, float u2) {
  const float z = 1 - 2 * u1;
  const float r = std::sqrt(std::max(0.f, 1 - z * z)), phi = 2 * std::numbers::pi_v<float> * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

/// A point uniform over the unit disk from two uniform numbers in [0, 1), by Shirley and Chiu's
/// concentric map (area-preserving; neighbouring (u1, u2) stay neighbours on the disk).
inline Point2 sample_concentric_disk(float u1, float u2) {
  const float a = 2 * u1 - 1, b = 2 * u2 - 1;
  if (a == 0 && b == 0) return {0, 0};
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4;
  if (std::abs(a) > std::abs(b)) return {a * std::cos(kQuarterPi * (b / a)), a * std::sin(kQuarterPi * (b / a))};
  const float angle = 2 * kQuarterPi - kQuarterPi * (a / b);
  return {b * std::cos(angle), b * std::sin(angle)};
}

}  // namespace mjray
