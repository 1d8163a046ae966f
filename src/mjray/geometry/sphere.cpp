#include "mjray/geometry/sphere.h"

#include <cmath>
#include <numbers>

namespace mjray {

std::optional<float> intersect_unit_sphere(const Ray& r, Interval t_range) {
  // Solve |o + t·d|² = 1 in double, with the stable form of the quadratic roots.
  const double ox = r.origin.x, oy = r.origin.y, oz = r.origin.z;
  const double dx = r.direction.x, dy = r.direction.y, dz = r.direction.z;
  const double a = dx * dx + dy * dy + dz * dz;
  const double half_b = ox * dx + oy * dy + oz * dz;
  // c = |o|² − 1 computed as |o − (o·d̂)d̂|² − 1 + (o·d̂)² avoids cancellation far away.
  const double proj = half_b / a;
  const double px = ox - proj * dx, py = oy - proj * dy, pz = oz - proj * dz;
  const double perp2 = px * px + py * py + pz * pz;
  const double disc = a * (1.0 - perp2);  // = half_b² − a·c
  if (!(disc >= 0)) return std::nullopt;  // also rejects NaN
  const double c = (ox * ox + oy * oy + oz * oz) - 1.0;
  const double root = std::sqrt(disc);
  const double q = half_b < 0 ? -half_b + root : -half_b - root;
  double t0 = q != 0 ? c / q : 0.0;
  double t1 = q / a;
  if (t0 > t1) std::swap(t0, t1);
  const double t_min = t_range.min;
  const double t = t0 > t_min ? t0 : t1;
  if (!(t > t_min) || !(t < t_range.max)) return std::nullopt;
  return float(t);
}

Point2 unit_sphere_uv(const Point3& p) {
  // φ grows eastward as seen from outside (from +x toward −z), θ from the north pole, so an
  // image wraps upright and unmirrored: v = 1 at the top (images have v = 0 at the bottom).
  double phi = std::atan2(-double(p.z), double(p.x));
  if (phi < 0) phi += 2 * std::numbers::pi;
  const double theta = std::acos(std::clamp(double(p.y), -1.0, 1.0));
  return {float(phi / (2 * std::numbers::pi)), float(1 - theta / std::numbers::pi)};
}

}  // namespace mjray
