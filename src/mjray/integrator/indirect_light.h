#pragma once
/// Light that reaches a surface other than straight from a light or along its specular lobes:
/// caustics and interreflection, which Whitted's recursion leaves out.

#include "mjray/core/color.h"
#include "mjray/core/rng.h"
#include "mjray/geometry/surface_interaction.h"
#include "mjray/integrator/integrator.h"
#include "mjray/material/shading.h"

namespace mjray {

/// What WhittedIntegrator adds at every surface it shades, when a job asks for it (photon
/// maps). Immutable after construction and safe to call from many threads at once.
class IndirectLight {
 public:
  virtual ~IndirectLight() = default;
  /// The light leaving `si` toward frame.wo; `local` is the material's local shading there
  /// and `weight` the share this surface has in its pixel (fewer samples where it is small).
  /// `state` is the tracing thread's (its counters, and the camera sample's number).
  virtual Color radiance(const SurfaceInteraction& si, const ShadingFrame& frame, const LocalShading& local,
                         float weight, RandomStream& random, TraceState& state) const = 0;
};

}  // namespace mjray
