#pragma once
/// How much light a shadow ray keeps on its way from a surface to a light.

#include <cstdint>
#include <optional>

#include "mjray/accel/accelerator.h"
#include "mjray/core/color.h"
#include "mjray/scene/world.h"

namespace mjray {

/// What a shadow ray kept, and the opaque primitive that blocked it, if one did.
struct ShadowResult {
  Color kept;
  std::optional<uint32_t> blocker;
};

/// Black at the first opaque primitive between 0 and t_max; otherwise the product, in order
/// along the ray, of each transmissive surface's shadow_transmittance at the ray's angle
/// there (shadow rays do not bend). White when nothing is in the way. The order is fixed (by
/// t, then primitive id), so every accelerator gives the same bits.
ShadowResult shadow_ray_transmittance(const World& world, const Accelerator& accel, const Ray& ray, float t_max);

}  // namespace mjray
