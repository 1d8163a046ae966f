#pragma once
/// Which lights a surface may reflect, decided before any of their samples is drawn: a surface
/// without a diffuse part reflects only what its highlight reaches.

#include "mjray/light/light.h"
#include "mjray/material/shading.h"

namespace mjray {

/// Whether the highlight ks·max(0, r·v)^shininess that `local` gives at `point`, seen along
/// `frame`, may be more than zero for some sample of `light`. False only where it rounds to
/// zero for every direction toward the light's sample region (a glass's narrow highlight, for
/// every light but those near its mirror direction); a conservative bound, with room for
/// rounding: a light it does not rule out is merely sampled.
bool highlight_may_reach(const LocalShading& local, const ShadingFrame& frame, const Point3& point, const Light& light);

/// Whether the Phong terms `local` at `point`, seen along `frame`, may reflect some of
/// `light`: a diffuse part, or a highlight that may reach it. When not, the samples' sum is
/// zero, bit for bit, whatever their shadow rays would find. Inline, so that the common surface
/// (one with a diffuse part) pays only the test of kd.
inline bool may_reflect(const LocalShading& local, const ShadingFrame& frame, const Point3& point, const Light& light) {
  return !local.kd.is_black() || highlight_may_reach(local, frame, point, light);
}

}  // namespace mjray
