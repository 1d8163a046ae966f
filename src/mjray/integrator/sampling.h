#pragma once
/// Warping uniform random numbers into directions.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mjray/core/vector.h"

namespace mjray {

/// A unit vector within acos(cos_max) of the unit `axis`, uniform over the cone's solid angle,
/// from two uniform numbers in [0, 1).
inline Vector3 sample_cone(const Vector3& axis, float cos_max, float u1, float u2) {
  const float cos_theta = 1 - u1 * (1 - cos_max);
  const float sin_theta = std::sqrt(std::max(0.f, 1 - cos_theta * cos_theta));
  const float phi = 2 * std::numbers::pi_v<float> * u2;
  // Compute an orthonormal frame around the axis (Duff et al. 2017).
  const float sign = std::copysign(1.f, axis.z);
  const float a = -1 / (sign + axis.z), b = axis.x * axis.y * a;
  const Vector3 t1(1 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
  const Vector3 t2(b, sign + axis.y * axis.y * a, -axis.y);
  return normalize(t1 * (sin_theta * std::cos(phi)) + t2 * (sin_theta * std::sin(phi)) + axis * cos_theta);
}

}  // namespace mjray
