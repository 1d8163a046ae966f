#pragma once
/// Which primitives may stand in a region of space: what an accelerator can say once for all of
/// an area light's shadow rays from one point, so that each ray tests a few primitives or none.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "mjray/geometry/light_pyramid.h"

namespace mjray {

/// Implemented by the accelerators that can answer it cheaply (the BVH).
class RegionSearch {
 public:
  virtual ~RegionSearch() = default;
  /// The primitives other than `ignore` that may touch `region`, written to the front of
  /// `out`: every shadow ray inside the region can hit only these (and `ignore`). None found
  /// means every such ray reaches its light. Nothing when there are more than out.size(), or
  /// when the search would cost more than it saves: the rays are then traced as usual.
  virtual std::optional<size_t> region_primitives(const LightPyramid& region, uint32_t ignore,
                                                  std::span<uint32_t> out) const = 0;
};

}  // namespace mjray
