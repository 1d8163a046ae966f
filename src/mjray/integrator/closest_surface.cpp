#include "mjray/integrator/closest_surface.h"

#include <algorithm>
#include <cmath>

#include "mjray/geometry/spawn_ray.h"

namespace mjray {

namespace {

/// Sees every hit and keeps the nearest opaque one (ties: the lower primitive id).
class NearestOpaque final : public HitFilter {
 public:
  explicit NearestOpaque(const PrimitiveSet& prims) : HitFilter(true, true), prims_(prims) {}
  bool blocks(const Hit& hit) override {
    if (!prims_.transmissive(hit.prim) &&
        (!nearest || hit.t < nearest->t || (hit.t == nearest->t && hit.prim < nearest->prim)))
      nearest = hit;
    return false;
  }
  std::optional<Hit> nearest;

 private:
  const PrimitiveSet& prims_;
};

}  // namespace

std::optional<SurfaceInteraction> closest_surface(const World& world, const Accelerator& accel, const Ray& ray) {
  const auto hit = accel.intersect(ray, {});
  if (!hit) return std::nullopt;
  const SurfaceInteraction si = world.interaction(ray, *hit);
  if (!world.primitives.transmissive(hit->prim)) return si;
  // Compute the window along the ray that the spawn offset spans at this hit.
  const float speed = length(ray.direction);
  const float cosine = std::max(std::abs(dot(ray.direction, si.geometric_normal)) / speed, 1e-3f);
  // The other surface's hit has its own rounding, which grows with the coordinates the ray
  // was traced in: its origin's as much as the hit point's.
  const float magnitude = max_component(abs(si.point)) + max_component(abs(ray.origin));
  const float reach = 4 * surface_offset(si) + gamma_bound(16) * magnitude;
  const float half_window = reach / (cosine * speed);
  const Interval window{std::max(0.f, hit->t - half_window), hit->t + half_window};
  NearestOpaque touching(world.primitives);
  accel.occluded(ray, window, touching);
  return touching.nearest ? world.interaction(ray, *touching.nearest) : si;
}

}  // namespace mjray
