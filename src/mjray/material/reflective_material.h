#pragma once
/// gr.reflectivematerial: Phong plus a mirror reflection weighted by the reflectivity.

#include "mjray/material/optics.h"
#include "mjray/material/phong_material.h"

namespace mjray {

/// colour = Phong + reflectivity · (light from the mirror direction). Opaque.
struct ReflectiveMaterial {
  PhongMaterial base;
  float reflectivity = 0;  ///< Kr in [0, 1]

  LocalShading local(const SurfaceInteraction& si) const { return base.local(si); }
  LocalShading scattering(const SurfaceInteraction& si) const { return base.diffuse_scattering(si); }
  SpecularLobes specular_lobes(const ShadingFrame& f) const {
    SpecularLobes lobes;
    lobes.add({reflect(f.wo, f.n), reflectivity, LobeKind::kReflection});
    return lobes;
  }
  Color shadow_transmittance(const ShadingFrame&) const { return {}; }
  bool specular() const { return reflectivity > 0; }
  bool transmissive() const { return false; }
};

}  // namespace mjray
