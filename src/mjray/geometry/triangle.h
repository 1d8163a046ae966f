#pragma once
/// Watertight ray/triangle intersection (Woop, Benthin and Wald 2013): rays through a shared
/// edge or vertex hit at least one of the triangles that share it.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>

#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

namespace triangle_error {
// γ(n) = n·u / (1 − n·u), u = 2⁻²⁴, for the error bound of t.
inline constexpr float kU = 0.5f * 1.1920928955078125e-7f;
inline constexpr float gamma2 = (2 * kU) / (1 - 2 * kU);
inline constexpr float gamma3 = (3 * kU) / (1 - 3 * kU);
inline constexpr float gamma5 = (5 * kU) / (1 - 5 * kU);
}  // namespace triangle_error

/// Where a ray meets a triangle: distance and barycentric weights of p1 and p2
/// (the weight of p0 is 1 − b1 − b2).
struct TriangleHit {
  float t;
  float b1;
  float b2;
};

/// The per-ray part of the watertight test (axis permutation and shear), computed once per
/// ray so that accelerators can test many triangles against it.
struct WatertightRay {
  int kx = 0, ky = 1, kz = 2;          ///< permutation that makes the largest |direction| z
  float sx = 0, sy = 0, sz = 0;        ///< shear that maps the direction to +z
  std::array<float, 3> origin{};       ///< world-space origin, unpermuted
  bool valid = false;                  ///< false for a zero or NaN dominant direction

  WatertightRay() = default;
  explicit WatertightRay(const Ray& ray) {
    const Vector3 ad = abs(ray.direction);
    kz = (ad.x > ad.y) ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    valid = ad[kz] > 0;
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    const auto d = std::bit_cast<std::array<float, 3>>(ray.direction);
    sx = -d[kx] / d[kz];
    sy = -d[ky] / d[kz];
    sz = 1.f / d[kz];
    origin = std::bit_cast<std::array<float, 3>>(ray.origin);
  }
};

/// Whether the scaled distance t·det of a hit lies in (t_range.min, t_range.max], decided before
/// dividing: the watertight test's range check, shared with accelerators' SIMD leaf tests.
[[gnu::always_inline]] inline bool scaled_distance_in_range(float t_scaled, float det, Interval t_range) {
  if (det < 0 && (t_scaled >= t_range.min * det || t_scaled < t_range.max * det)) return false;
  if (det > 0 && (t_scaled <= t_range.min * det || t_scaled > t_range.max * det)) return false;
  return true;
}

/// Whether a hit's t exceeds the bound on its rounding error (pbrt-v4), so that it cannot lie at
/// or behind the origin: a ray leaving a surface then never re-hits it, however large the
/// triangle is against its offset. The arguments are the largest magnitudes of the sheared
/// corners' z, x and y, and of the edge functions. (In double: a tiny direction component makes
/// these products overflow a float.) The shear's error scales with the unscaled z; t's with the
/// scaled one.
[[gnu::always_inline]] inline bool clears_rounding_error(float t, float det, float sz, float max_z_f, float max_xt_f,
                                                         float max_yt_f, float max_e_f) {
  using namespace triangle_error;
  const double max_z = max_z_f, max_xt = max_xt_f, max_yt = max_yt_f, max_e = max_e_f;
  const double max_zt = max_z * double(std::abs(sz));
  const double delta_z = gamma3 * max_zt;
  const double delta_x = gamma5 * (max_xt + max_z);
  const double delta_y = gamma5 * (max_yt + max_z);
  const double delta_e = 2 * (gamma2 * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
  const double delta_t = 3 * (gamma3 * max_e * max_zt + delta_e * max_zt + delta_z * max_e) / std::abs(double(det));
  return double(t) > delta_t;
}

/// The hit of the prepared ray with triangle (p0, p1, p2) for t in (t_range.min, t_range.max]
/// (a hit exactly at max counts), or nothing.
/// Inline so that accelerators' leaf loops share exactly this arithmetic (and so the same
/// barycentrics) with `intersect_triangle` below.
[[gnu::always_inline]] inline std::optional<TriangleHit> intersect_triangle(const WatertightRay& ray, Interval t_range,
                                                     const std::array<float, 3>& p0,
                                                     const std::array<float, 3>& p1,
                                                     const std::array<float, 3>& p2) {
  if (!ray.valid) return std::nullopt;
  const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
  const auto& o = ray.origin;

  // Compute vertices relative to the ray origin in the permuted frame, sheared so that the
  // ray runs along +z.
  const float az = p0[kz] - o[kz], bz = p1[kz] - o[kz], cz = p2[kz] - o[kz];
  const float ax = (p0[kx] - o[kx]) + ray.sx * az, ay = (p0[ky] - o[ky]) + ray.sy * az;
  const float bx = (p1[kx] - o[kx]) + ray.sx * bz, by = (p1[ky] - o[ky]) + ray.sy * bz;
  const float cx = (p2[kx] - o[kx]) + ray.sx * cz, cy = (p2[ky] - o[ky]) + ray.sy * cz;

  // Compute edge functions; fall back to double when one is exactly zero so that
  // edges shared by two triangles are decided consistently.
  float e0 = bx * cy - by * cx;
  float e1 = cx * ay - cy * ax;
  float e2 = ax * by - ay * bx;
  if (e0 == 0 || e1 == 0 || e2 == 0) [[unlikely]] {
    e0 = float(double(bx) * cy - double(by) * cx);
    e1 = float(double(cx) * ay - double(cy) * ax);
    e2 = float(double(ax) * by - double(ay) * bx);
  }
  if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return std::nullopt;
  const float det = e0 + e1 + e2;
  if (!(det != 0) || !std::isfinite(det)) return std::nullopt;

  // Compute the scaled distance and reject hits outside the range before dividing.
  const float t_scaled = e0 * (az * ray.sz) + e1 * (bz * ray.sz) + e2 * (cz * ray.sz);
  if (!scaled_distance_in_range(t_scaled, det, t_range)) return std::nullopt;

  const float inv_det = 1 / det;
  const float t = t_scaled * inv_det;
  if (!(t > t_range.min) || !std::isfinite(t)) return std::nullopt;
  if (!clears_rounding_error(t, det, ray.sz, std::max({std::abs(az), std::abs(bz), std::abs(cz)}),
                             std::max({std::abs(ax), std::abs(bx), std::abs(cx)}),
                             std::max({std::abs(ay), std::abs(by), std::abs(cy)}),
                             std::max({std::abs(e0), std::abs(e1), std::abs(e2)})))
    return std::nullopt;
  return TriangleHit{t, e1 * inv_det, e2 * inv_det};
}

/// The hit of `ray` with triangle (p0, p1, p2) for t in (t_range.min, t_range.max], or nothing.
/// Never reports a hit for NaN/Inf input or a degenerate (zero-area) triangle.
std::optional<TriangleHit> intersect_triangle(const Ray& ray, Interval t_range, const Point3& p0,
                                              const Point3& p1, const Point3& p2);

}  // namespace mjray
