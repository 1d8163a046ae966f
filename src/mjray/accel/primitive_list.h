#pragma once
/// Visibility against a short list of primitives: the few that an accelerator found to touch
/// one light's pyramid, tested for each of that light's shadow rays instead of the whole tree.

#include <cstdint>
#include <span>

#include "mjray/accel/accelerator.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// Tests every primitive of `list`, in its order. Correct only for rays that cannot touch a
/// primitive outside the list; then it answers exactly as the accelerator that made the list.
class PrimitiveList final : public Accelerator {
 public:
  PrimitiveList(const PrimitiveSet& prims, std::span<const uint32_t> list) : prims_(prims), list_(list) {}
  std::optional<Hit> intersect(const Ray& ray, Interval t_range) const override;
  bool occluded(const Ray& ray, float t_max) const override;
  bool occluded(const Ray& ray, Interval t_range, HitFilter& filter) const override;
  Bounds3 bounds() const override;
  std::string_view name() const override { return "list"; }
  size_t memory_bytes() const override { return 0; }

 private:
  const PrimitiveSet& prims_;
  std::span<const uint32_t> list_;
};

}  // namespace mjray
