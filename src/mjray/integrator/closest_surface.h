#pragma once
/// The surface a ray sees first, with the rule for surfaces that touch.

#include <optional>

#include "mjray/accel/accelerator.h"
#include "mjray/geometry/surface_interaction.h"
#include "mjray/scene/world.h"

namespace mjray {

/// The shading data of the first surface along `ray`, or nothing. Where a transmissive
/// surface and an opaque one lie in the same place (a glass standing on a table; which of the
/// two rounding puts first changes from ray to ray), the opaque one is seen: the glass rests
/// on it, and no light passes between them. "The same place" is within a few times the hit
/// point's error bound (surface_offset) of it, measured along the ray.
std::optional<SurfaceInteraction> closest_surface(const World& world, const Accelerator& accel, const Ray& ray);

/// The frame a surface is shaded in when a ray along `direction` meets it: wo back along the
/// ray, the shading normal turned toward it.
inline ShadingFrame frame_facing(const SurfaceInteraction& si, const Vector3& direction) {
  const Vector3 wo = normalize(-direction);
  return {wo, face_forward(si.shading_normal, wo), si.geometric_normal};
}

}  // namespace mjray
