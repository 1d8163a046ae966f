#pragma once
/// gr.reflectivematerial: Phong plus a mirror reflection weighted by the reflectivity.

#include "mjray/material/phong_material.h"

namespace mjray {

/// colour = Phong + reflectivity · (light from the mirror direction).
struct ReflectiveMaterial {
  PhongMaterial base;
  float reflectivity = 0;  ///< Kr in [0, 1]
};

}  // namespace mjray
