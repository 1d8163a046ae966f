#pragma once
/// gr.refractedmaterial and gr.reflectrefractmaterial: Snell refraction, optionally blended
/// with mirror reflection.

#include "mjray/material/phong_material.h"

namespace mjray {

/// colour = Phong + Kr · reflected + (1 − Kr) · refracted; gr.refractedmaterial has Kr = 0.
/// Under total internal reflection the refracted share is reflected instead.
struct RefractiveMaterial {
  PhongMaterial base;
  float reflectivity = 0;  ///< Kr
  float eta_outside = 1;   ///< η_i: index of the medium around the object
  float eta_inside = 1.5f; ///< η_t: index of the object
};

}  // namespace mjray
