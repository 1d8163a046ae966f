#include "mjray/integrator/shadow_transmittance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "mjray/geometry/shape.h"

namespace mjray {

namespace {

/// Collects the transmissive crossings of one shadow ray; more than kCapacity block it.
/// Accelerators report a shape's first crossing only, so the way out of a sphere or a box is
/// found here.
class TransmissiveHits final : public HitFilter {
 public:
  static constexpr int kCapacity = 64;

  TransmissiveHits(const PrimitiveSet& prims, const Ray& ray, float t_max)
      : HitFilter(true), prims_(prims), ray_(ray), t_max_(t_max) {}

  /// The opaque primitive that blocked the ray, if one did.
  std::optional<uint32_t> blocker;

  bool blocks(const Hit& hit) override {
    if (!prims_.transmissive(hit.prim)) {
      blocker = hit.prim;
      return true;
    }
    const int most = prims_.is_triangle(hit.prim) ? 1 : kMaxShapeCrossings;
    std::optional<Hit> crossing = hit;
    for (int crossed = 0; crossing;) {
      if (count_ == kCapacity) return true;
      hits_[size_t(count_++)] = *crossing;
      if (++crossed == most) break;
      // Past the float t just found: the shape's own root, rounded down to it, may lie above.
      crossing = prims_.intersect(hit.prim, ray_, {std::nextafter(crossing->t, kInfinity), t_max_});
    }
    return false;
  }

  /// The hits in order along the ray, each primitive once.
  std::span<const Hit> in_order() {
    std::sort(hits_, hits_ + count_,
              [](const Hit& a, const Hit& b) { return a.t < b.t || (a.t == b.t && a.prim < b.prim); });
    const auto end = std::unique(hits_, hits_ + count_,
                                 [](const Hit& a, const Hit& b) { return a.prim == b.prim && a.t == b.t; });
    return {hits_, size_t(end - hits_)};
  }

 private:
  const PrimitiveSet& prims_;
  const Ray& ray_;
  float t_max_;
  // Left uninitialised: a shadow ray mostly crosses nothing, and 64 hits are a kilobyte.
  union Storage {
    Storage() {}
    Hit hits[kCapacity];
  } storage_;
  Hit* hits_ = storage_.hits;
  int count_ = 0;
};

}  // namespace

ShadowResult shadow_ray_transmittance(const World& world, const Accelerator& accel, const Ray& ray, float t_max) {
  TransmissiveHits hits(world.primitives, ray, t_max);
  if (accel.occluded(ray, {0, t_max}, hits)) return {{}, hits.blocker};
  Color kept{1, 1, 1};
  const Vector3 wo = normalize(-ray.direction);
  for (const Hit& hit : hits.in_order()) {
    const SurfaceInteraction si = world.crossing(ray, hit);
    const ShadingFrame frame{wo, face_forward(si.shading_normal, wo), si.geometric_normal};
    kept = kept * shadow_transmittance(world.materials[si.material], frame);
    if (kept.is_black()) break;
  }
  return {kept, std::nullopt};
}

}  // namespace mjray
