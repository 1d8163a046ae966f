#pragma once
/// gr.fresneldiectricmaterial: glass whose reflect/refract weights come from the Fresnel
/// equations at each hit.

#include "mjray/material/phong_material.h"

namespace mjray {

/// colour = Phong + F · reflected + (1 − F) · refracted, F the unpolarised Fresnel reflectance.
struct FresnelMaterial {
  PhongMaterial base;
  float eta_outside = 1;
  float eta_inside = 1.5f;
};

}  // namespace mjray
