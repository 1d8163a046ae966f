#pragma once
/// Lights a surface reflects none of, found before any of their samples is drawn.

#include "mjray/light/light.h"
#include "mjray/material/shading.h"

namespace mjray {

/// Whether the Phong terms `local` at `point`, seen along `frame`, reflect exactly zero of
/// every sample of `light`: no diffuse part, and the highlight ks·max(0, r·v)^shininess
/// rounds to zero for every direction toward the light's sample region (a glass's narrow
/// highlight, for all lights but those near its mirror direction). The samples' sum is then
/// zero, bit for bit, whatever their shadow rays would find; a conservative bound, with room
/// for rounding, so a light it does not rule out is merely sampled as usual.
bool reflects_none_of(const LocalShading& local, const ShadingFrame& frame, const Point3& point, const Light& light);

}  // namespace mjray
