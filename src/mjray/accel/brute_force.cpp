#include "mjray/accel/brute_force.h"

namespace mjray {

std::optional<Hit> BruteForce::intersect(const Ray& ray, Interval t_range) const {
  std::optional<Hit> nearest;
  const uint32_t n = prims_.size();
  for (uint32_t prim = 0; prim < n; ++prim) {
    // At equal t the lower primitive id, tested first, stays.
    if (auto hit = prims_.intersect(prim, ray, t_range); hit && !(nearest && hit->t >= nearest->t)) {
      t_range.max = hit->t;
      nearest = hit;
    }
  }
  return nearest;
}

bool BruteForce::occluded(const Ray& ray, float t_max) const {
  const uint32_t n = prims_.size();
  for (uint32_t prim = 0; prim < n; ++prim)
    if (prims_.intersect(prim, ray, {0, t_max})) return true;
  return false;
}

bool BruteForce::occluded(const Ray& ray, Interval t_range, HitFilter& filter) const {
  const uint32_t n = prims_.size();
  for (uint32_t prim = 0; prim < n; ++prim)
    if (const auto hit = prims_.intersect(prim, ray, t_range))
      if (!prims_.filtered(prim, filter.sees_opaque) || filter.blocks(*hit)) return true;
  return false;
}

}  // namespace mjray
