#pragma once
/// gr.glossyreflectivematerial: blurred reflection from several perturbed mirror rays.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mjray/material/optics.h"
#include "mjray/material/phong_material.h"

namespace mjray {

/// colour = Phong + reflectivity · (mean of `samples` rays spread uniformly over the solid
/// angle of a cone around the mirror direction). The cone narrows as the reflectivity grows:
/// half-angle = (1 − reflectivity) · 45°, so reflectivity 1 is a perfect mirror. Opaque.
struct GlossyMaterial {
  PhongMaterial base;
  float reflectivity = 0;
  int samples = 1;

  /// Cosine of the cone's half-angle.
  float cos_cone_angle() const {
    return std::cos((1 - std::clamp(reflectivity, 0.f, 1.f)) * std::numbers::pi_v<float> / 4);
  }

  LocalShading local(const SurfaceInteraction& si) const { return base.local(si); }
  LocalShading scattering(const SurfaceInteraction& si) const { return base.diffuse_scattering(si); }
  SpecularLobes specular_lobes(const ShadingFrame& f) const {
    SpecularLobes lobes;
    lobes.add({reflect(f.wo, f.n), reflectivity, LobeKind::kReflection, cos_cone_angle(), samples});
    return lobes;
  }
  Color shadow_transmittance(const ShadingFrame&) const { return {}; }
  bool specular() const { return reflectivity > 0; }
  bool transmissive() const { return false; }
};

}  // namespace mjray
