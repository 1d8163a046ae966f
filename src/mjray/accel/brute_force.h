#pragma once
/// The oracle: every ray tests every primitive.

#include "mjray/accel/accelerator.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// Tests every primitive in order; kept as the reference the other accelerators must match.
class BruteForce final : public Accelerator {
 public:
  explicit BruteForce(const PrimitiveSet& prims) : prims_(prims), bounds_(prims.bounds()) {}
  std::optional<Hit> intersect(const Ray& ray, Interval t_range) const override;
  bool occluded(const Ray& ray, float t_max) const override;
  bool occluded(const Ray& ray, Interval t_range, HitFilter& filter) const override;
  Bounds3 bounds() const override { return bounds_; }
  std::string_view name() const override { return "none"; }
  size_t memory_bytes() const override { return 0; }

 private:
  const PrimitiveSet& prims_;
  Bounds3 bounds_;
};

}  // namespace mjray
