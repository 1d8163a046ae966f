#include "mjray/accel/primitive_list.h"

#include "mjray/core/float_steps.h"

namespace mjray {

std::optional<Hit> PrimitiveList::intersect(const Ray& ray, Interval t_range) const {
  std::optional<Hit> nearest;
  for (const uint32_t prim : list_) {
    // At equal t the lower primitive id wins, whatever the list's order.
    const float reach = nearest ? next_float(nearest->t, true) : t_range.max;
    const auto hit = prims_.intersect(prim, ray, {t_range.min, reach});
    if (hit && (!nearest || hit->t < nearest->t || (hit->t == nearest->t && prim < nearest->prim))) nearest = hit;
  }
  return nearest;
}

bool PrimitiveList::occluded(const Ray& ray, float t_max) const {
  for (const uint32_t prim : list_)
    if (prims_.intersect(prim, ray, {0, t_max})) return true;
  return false;
}

bool PrimitiveList::occluded(const Ray& ray, Interval t_range, HitFilter& filter) const {
  for (const uint32_t prim : list_)
    if (const auto hit = prims_.intersect(prim, ray, t_range))
      if (!prims_.filtered(prim, filter.sees_opaque) || filter.blocks(*hit)) return true;
  return false;
}

Bounds3 PrimitiveList::bounds() const {
  Bounds3 b;
  for (const uint32_t prim : list_) b.expand(prims_.primitive_bounds(prim));
  return b;
}

}  // namespace mjray
