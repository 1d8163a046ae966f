#pragma once
/// gr.refractedmaterial and gr.reflectrefractmaterial: Snell refraction, optionally blended
/// with mirror reflection.

#include "mjray/material/dielectric.h"
#include "mjray/material/phong_material.h"

namespace mjray {

/// Kr that does not depend on the angle.
struct ConstantReflectance {
  float kr;
  float operator()(float /*cos_i*/, float /*eta_i*/, float /*eta_t*/) const { return kr; }
};

/// colour = Phong + Kr · reflected + (1 − Kr) · refracted; gr.refractedmaterial has Kr = 0.
/// Under total internal reflection the refracted share is reflected instead. Shadow rays keep
/// 1 − Kr at each crossing.
struct RefractiveMaterial {
  PhongMaterial base;
  float reflectivity = 0;  ///< Kr
  float eta_outside = 1;   ///< η_i: index of the medium around the object
  float eta_inside = 1.5f; ///< η_t: index of the object

  LocalShading local(const SurfaceInteraction& si) const { return base.local(si); }
  LocalShading scattering(const SurfaceInteraction& si) const { return base.diffuse_scattering(si); }
  SpecularLobes specular_lobes(const ShadingFrame& f) const {
    return dielectric_lobes(f, eta_outside, eta_inside, ConstantReflectance{reflectivity});
  }
  Color shadow_transmittance(const ShadingFrame& f) const {
    const float t = dielectric_transmittance(f, eta_outside, eta_inside, ConstantReflectance{reflectivity});
    return {t, t, t};
  }
  bool specular() const { return true; }
  bool transmissive() const { return true; }
};

}  // namespace mjray
