#include "mjray/integrator/reflection_bound.h"

#include <algorithm>
#include <cmath>

namespace mjray {

namespace {

/// Whether every sample's intensity is finite (so that zero times it is zero): a finite
/// colour and a falloff 1 / (c0 + c1·d + c2·d²) that cannot divide by zero (the sun has none).
bool intensity_is_finite(const Light& light) {
  return std::visit(
      [](const auto& l) {
        const Color& c = l.colour;
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) return false;
        if constexpr (requires { l.falloff; })
          return l.falloff[0] > 0 && l.falloff[1] >= 0 && l.falloff[2] >= 0 &&
                 std::isfinite(l.falloff[0] + l.falloff[1] + l.falloff[2]);
        return true;
      },
      light);
}

}  // namespace

bool highlight_may_reach(const LocalShading& local, const ShadingFrame& frame, const Point3& point, const Light& light) {
  if (!intensity_is_finite(light)) return true;
  if (local.ks.is_black()) return false;
  const Color& ks = local.ks;
  if (!(local.shininess > 0) || !std::isfinite(ks.r) || !std::isfinite(ks.g) || !std::isfinite(ks.b)) return true;
  // r·v = l·m for the mirror m of v about n: every direction l toward the light must make
  // r·v so small that its power rounds to zero. The directions lie within the cone around
  // the region's centre that holds its circumscribed sphere.
  const std::array<Point3, 4> region = sample_region(light, point);
  double centre[3] = {0, 0, 0};
  for (const Point3& q : region)
    for (int a = 0; a < 3; ++a) centre[a] += double(q[a]) / 4;
  double radius2 = 0, axis[3], distance2 = 0;
  for (const Point3& q : region) {
    double r2 = 0;
    for (int a = 0; a < 3; ++a) r2 += (double(q[a]) - centre[a]) * (double(q[a]) - centre[a]);
    radius2 = std::max(radius2, r2);
  }
  for (int a = 0; a < 3; ++a) {
    axis[a] = centre[a] - double(point[a]);
    distance2 += axis[a] * axis[a];
  }
  if (!(distance2 > 4 * radius2) || !(distance2 > 0)) return true;  // too close for a narrow cone
  const double distance = std::sqrt(distance2);
  const double n_dot_v = double(dot(frame.n, frame.wo));
  double mirror[3], mirror_length2 = 0, along_axis = 0;
  for (int a = 0; a < 3; ++a) {
    mirror[a] = 2 * n_dot_v * double(frame.n[a]) - double(frame.wo[a]);
    mirror_length2 += mirror[a] * mirror[a];
    along_axis += mirror[a] * axis[a];
  }
  const double mirror_length = std::sqrt(mirror_length2);
  if (!(mirror_length > 0)) return true;
  // The cone's half-angle, widened by a milliradian for the rounding of the float directions
  // and dot products.
  constexpr double kMargin = 1e-3;
  const double sin_half = std::sqrt(radius2 / distance2), cos_half = std::sqrt(1 - radius2 / distance2);
  const double cos_wide = cos_half * std::cos(kMargin) - sin_half * std::sin(kMargin);
  const double sin_wide = sin_half * std::cos(kMargin) + cos_half * std::sin(kMargin);
  const double cos_to_mirror = std::clamp(along_axis / (mirror_length * distance), -1.0, 1.0);
  if (cos_to_mirror >= cos_wide) return true;  // the mirror direction lies in the cone
  const double sin_to_mirror = std::sqrt(1 - cos_to_mirror * cos_to_mirror);
  // The largest l·m, plus room for the float r·v's rounding error: |m| times the cosine of
  // the angle between m and the cone's rim.
  const double largest = mirror_length * (cos_to_mirror * cos_wide + sin_to_mirror * sin_wide) + 1e-5;
  // Unless r·v ≤ 0 everywhere, or largest^shininess < 2^-200, far under the smallest float
  // (2^-149), where the power rounds to zero.
  return !(largest <= 0 || double(local.shininess) * std::log2(largest) < -200);
}

}  // namespace mjray
