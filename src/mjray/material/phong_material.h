#pragma once
/// The CS 488 Phong material: diffuse and specular colours and a specular exponent.

#include "mjray/core/color.h"

namespace mjray {

/// gr.material(kd, ks, shininess): the local shading model shared by every material.
struct PhongMaterial {
  Color kd;               ///< diffuse reflectance, also scales the ambient light
  Color ks;               ///< specular reflectance
  float shininess = 0;    ///< Phong exponent of max(0, r·v)
};

}  // namespace mjray
