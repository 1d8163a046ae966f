#pragma once
/// The open set of light transports: anything that turns a camera ray into a colour.

#include <cstdint>

#include "mjray/core/color.h"
#include "mjray/core/ray.h"
#include "mjray/core/rng.h"

namespace mjray {

/// Rays cast, by kind; each thread keeps its own and they are summed at the end.
/// Cache-line aligned: each worker thread updates its own on every ray, so neighbours in an
/// array must not share a line (false sharing would serialise the threads).
struct alignas(64) RayCounters {
  uint64_t primary = 0;
  uint64_t secondary = 0;
  uint64_t shadow = 0;

  RayCounters& operator+=(const RayCounters& o) {
    primary += o.primary;
    secondary += o.secondary;
    shadow += o.shadow;
    return *this;
  }
  uint64_t total() const { return primary + secondary + shadow; }
};

/// Computes the colour seen along camera rays. Implementations are immutable after
/// construction and safe to call from many threads at once.
class Integrator {
 public:
  virtual ~Integrator() = default;
  /// The linear colour along a primary ray (unit direction); `random` supplies every sample.
  virtual Color radiance(const Ray& ray, RandomStream& random, RayCounters& counters) const = 0;
};

}  // namespace mjray
