#pragma once
/// Lights a surface reflects none of, found before any of their samples is drawn.

#include "mjray/light/light.h"
#include "mjray/material/shading.h"

namespace mjray {

/// Whether a surface with no diffuse part, its highlight ks·max(0, r·v)^shininess as
/// `local` gives it, at `point` seen along `frame`, reflects exactly zero of every sample of
/// `light`: the highlight rounds to zero for every direction toward the light's sample region
/// (a glass's narrow highlight, for all lights but those near its mirror direction). A
/// conservative bound, with room for rounding: a light it does not rule out is merely sampled.
bool highlight_misses(const LocalShading& local, const ShadingFrame& frame, const Point3& point, const Light& light);

/// Whether the Phong terms `local` at `point`, seen along `frame`, reflect exactly zero of
/// every sample of `light`: no diffuse part, and a highlight that misses the light. The
/// samples' sum is then zero, bit for bit, whatever their shadow rays would find. Inline, so
/// that the common surface (one with a diffuse part) pays only the test of kd.
inline bool reflects_none_of(const LocalShading& local, const ShadingFrame& frame, const Point3& point,
                             const Light& light) {
  return local.kd.is_black() && highlight_misses(local, frame, point, light);
}

}  // namespace mjray
