#include "mjray/accel/brute_force.h"

namespace mjray {

std::optional<Hit> BruteForce::intersect(const Ray& ray, float t_max) const {
  std::optional<Hit> nearest;
  const uint32_t n = world_.primitive_count();
  for (uint32_t prim = 0; prim < n; ++prim) {
    if (auto hit = world_.intersect_primitive(prim, ray, t_max)) {
      t_max = hit->t;
      nearest = hit;
    }
  }
  return nearest;
}

bool BruteForce::occluded(const Ray& ray, float t_max) const {
  const uint32_t n = world_.primitive_count();
  for (uint32_t prim = 0; prim < n; ++prim)
    if (world_.intersect_primitive(prim, ray, t_max)) return true;
  return false;
}

}  // namespace mjray
