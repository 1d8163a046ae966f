#pragma once
/// How much of a light's samples reaches one shading point: its shadow rays, and everything
/// that makes them cheap without changing an answer (the search, once for all of an area
/// light's samples, of what they can hit; the primitive that blocked the last one).

#include <cstddef>
#include <optional>

#include "mjray/accel/accelerator.h"
#include "mjray/accel/region_search.h"
#include "mjray/core/color.h"
#include "mjray/geometry/surface_interaction.h"
#include "mjray/integrator/integrator.h"
#include "mjray/integrator/shadow_scope.h"
#include "mjray/light/light.h"
#include "mjray/scene/world.h"

namespace mjray {

/// What answers shadow rays: the accelerator, and its region search where it has one.
struct ShadowQueries {
  const Accelerator& accel;
  const RegionSearch* regions = nullptr;
};

/// One light's visibility from one shading point, asked once per sample of the light.
class LightVisibility {
 public:
  /// For the samples of `light`, the `light_index`-th of `world`, seen from `si`. With
  /// `many_samples`, what their rays can hit is searched for once (when a sample first needs
  /// a ray). `through_glass`: shadow rays pass transmissive surfaces keeping the share they let
  /// through (off when a caustic photon map brings that light: glass then shadows like any
  /// object). Everything given must outlive the object.
  LightVisibility(const World& world, const ShadowQueries& queries, const SurfaceInteraction& si, const Light& light,
                  size_t light_index, bool many_samples, bool through_glass, TraceState& state)
      : world_(world), queries_(queries), si_(si), light_(light), light_index_(light_index),
        many_samples_(many_samples), through_glass_(through_glass), state_(state) {}
  LightVisibility(const LightVisibility&) = delete;
  LightVisibility& operator=(const LightVisibility&) = delete;

  /// The share of the light leaving `light_point` that arrives at the shading point: white
  /// when nothing is in the way, black when something opaque is, and through glass what the
  /// glass lets pass. Counts the shadow ray when it traces one.
  Color transmittance(const Point3& light_point);

 private:
  const ShadowScope& scope();

  const World& world_;
  const ShadowQueries& queries_;
  const SurfaceInteraction& si_;
  const Light& light_;
  size_t light_index_;
  bool many_samples_;
  bool through_glass_;
  TraceState& state_;
  std::optional<ShadowScope> scope_;
};

}  // namespace mjray
