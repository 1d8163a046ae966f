#pragma once
/// The one narrow seam between visibility queries and the structures that answer them.

#include <cstddef>
#include <optional>
#include <string_view>

#include "mjray/core/bounds.h"
#include "mjray/core/ray.h"
#include "mjray/geometry/hit.h"

namespace mjray {

/// Decides, for a hit of a filtered occlusion query, whether the ray is blocked there
/// (Embree's occlusion-filter shape). It sees the hits on transmissive primitives
/// (PrimitiveSet::transmissive), and on every primitive when `sees_opaque`; other hits block
/// at once. Hits come in no particular order, exact (as intersect() computes them), and a
/// primitive may be reported more than once.
class HitFilter {
 public:
  explicit HitFilter(bool sees_opaque_hits = false, bool ignores_transmissive_hits = false)
      : sees_opaque(sees_opaque_hits), ignores_transmissive(ignores_transmissive_hits) {}
  virtual ~HitFilter() = default;
  /// True stops the query: the ray counts as occluded.
  virtual bool blocks(const Hit& hit) = 0;

  const bool sees_opaque;
  /// A filter that says nothing of transmissive hits (blocks false for them, and they do not
  /// change its state) may set this: an accelerator may then skip transmissive primitives
  /// without testing them. It may still show them.
  const bool ignores_transmissive;
};

/// A spatial index over a PrimitiveSet. Implementations: none (brute force), grid, bvh,
/// embree. All are thread-safe for queries and never allocate or throw on the ray path.
class Accelerator {
 public:
  virtual ~Accelerator() = default;
  /// The nearest hit with t in the open range `t_range`, or nothing.
  virtual std::optional<Hit> intersect(const Ray& ray, Interval t_range) const = 0;
  /// Whether anything is hit with t in (0, t_max) (shadow rays; any hit will do).
  virtual bool occluded(const Ray& ray, float t_max) const = 0;
  /// Whether something blocks the ray for t in `t_range`: a primitive the filter does not see,
  /// or one whose hit it says blocks. Without a blocker, every primitive the filter sees that
  /// the ray crosses has been shown to it.
  virtual bool occluded(const Ray& ray, Interval t_range, HitFilter& filter) const = 0;
  /// Bounds of all primitives.
  virtual Bounds3 bounds() const = 0;
  /// The name users pass to --accel.
  virtual std::string_view name() const = 0;
  /// Bytes used by the structure itself (not the World).
  virtual size_t memory_bytes() const = 0;
};

}  // namespace mjray
