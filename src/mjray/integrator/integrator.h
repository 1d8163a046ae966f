#pragma once
/// The open set of light transports: anything that turns a camera ray into a colour.

#include <cstdint>

#include "mjray/core/color.h"
#include "mjray/core/ray.h"
#include "mjray/core/rng.h"

namespace mjray {

/// Rays cast, by kind; each thread keeps its own and they are summed at the end.
struct RayCounters {
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

/// For each light (the first kLights of a scene), the last opaque primitive that blocked a
/// shadow ray toward it: tested first, since neighbouring shading points are mostly shadowed
/// by the same thing. It only saves work: no result depends on it.
struct OccluderCache {
  static constexpr int kLights = 8;
  static constexpr uint32_t kNone = ~uint32_t(0);
  uint32_t prim[kLights] = {kNone, kNone, kNone, kNone, kNone, kNone, kNone, kNone};

  uint32_t* slot(size_t light) { return light < kLights ? &prim[light] : nullptr; }
};

/// What one worker thread keeps while it traces: its ray counts and caches. Cache-line
/// aligned: each thread updates its own on every ray, so neighbours in an array must not share
/// a line (false sharing would serialise the threads).
struct alignas(64) TraceState {
  RayCounters rays;
  OccluderCache occluders;
  /// The number within its pixel of the camera sample being traced: what it reads of
  /// per-sample data, such as which pass of a progressive photon map (set by the sampler).
  uint32_t camera_sample = 0;
};

/// Computes the colour seen along camera rays. Implementations are immutable after
/// construction and safe to call from many threads at once.
class Integrator {
 public:
  virtual ~Integrator() = default;
  /// The linear colour along a primary ray (unit direction); `random` supplies every sample,
  /// `state` is the calling thread's own.
  virtual Color radiance(const Ray& ray, RandomStream& random, TraceState& state) const = 0;
};

}  // namespace mjray
