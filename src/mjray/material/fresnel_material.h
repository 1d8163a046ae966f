#pragma once
/// gr.fresneldiectricmaterial: glass whose reflect/refract weights come from the Fresnel
/// equations at each hit.

#include "mjray/material/dielectric.h"
#include "mjray/material/phong_material.h"

namespace mjray {

/// colour = Phong + F · reflected + (1 − F) · refracted, F the unpolarised Fresnel reflectance.
/// Shadow rays keep 1 − F(θ) at each crossing, θ their angle there.
struct FresnelMaterial {
  PhongMaterial base;
  float eta_outside = 1;
  float eta_inside = 1.5f;

  LocalShading local(const SurfaceInteraction& si) const { return base.local(si); }
  LocalShading scattering(const SurfaceInteraction& si) const { return base.diffuse_scattering(si); }
  SpecularLobes specular_lobes(const ShadingFrame& f) const {
    return dielectric_lobes(f, eta_outside, eta_inside, fresnel_dielectric);
  }
  Color shadow_transmittance(const ShadingFrame& f) const {
    const float t = dielectric_transmittance(f, eta_outside, eta_inside, fresnel_dielectric);
    return {t, t, t};
  }
  bool specular() const { return true; }
  bool transmissive() const { return true; }
};

}  // namespace mjray
