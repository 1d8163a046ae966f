#pragma once
/// Mirror reflection, Snell refraction and the unpolarised Fresnel reflectance.

#include <algorithm>
#include <cmath>
#include <optional>

#include "mjray/core/vector.h"

namespace mjray {

/// The mirror image of `wo` (pointing away from the surface) about the normal n.
inline Vector3 reflect(const Vector3& wo, const Normal3& n) {
  return Vector3(n) * (2 * dot(wo, n)) - wo;
}

/// The transmitted direction for `wo` (unit, pointing away, same side as unit n) entering the
/// side opposite n, with eta = η_incident / η_transmitted; nothing under total internal reflection.
inline std::optional<Vector3> refract(const Vector3& wo, const Normal3& n, float eta) {
  const float cos_i = dot(wo, n);
  const float sin2_t = eta * eta * std::max(0.f, 1 - cos_i * cos_i);
  if (sin2_t >= 1) return std::nullopt;
  const float cos_t = std::sqrt(1 - sin2_t);
  return -wo * eta + Vector3(n) * (eta * cos_i - cos_t);
}

/// Fraction of unpolarised light reflected at a dielectric boundary, for the cosine of the
/// incident angle and the indices on the incident and transmitted sides: the mean of r∥² and
/// r⊥²; 1 beyond the critical angle.
inline float fresnel_dielectric(float cos_i, float eta_i, float eta_t) {
  cos_i = std::clamp(cos_i, 0.f, 1.f);
  const float sin_t = eta_i / eta_t * std::sqrt(std::max(0.f, 1 - cos_i * cos_i));
  if (sin_t >= 1) return 1;
  const float cos_t = std::sqrt(std::max(0.f, 1 - sin_t * sin_t));
  const float r_parallel = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  const float r_perpendicular = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

}  // namespace mjray
