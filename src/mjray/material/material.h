#pragma once
/// The closed set of materials.
///
/// To add a material: write `<name>_material.h` with a struct that has a `PhongMaterial base`
/// for the local shading, add it to `Material` below, teach the integrator's
/// `secondary_light` about it, and bind it in `lua/gr_bindings.cpp`.

#include <variant>

#include "mjray/material/fresnel_material.h"
#include "mjray/material/glossy_material.h"
#include "mjray/material/phong_material.h"
#include "mjray/material/reflective_material.h"
#include "mjray/material/refractive_material.h"

namespace mjray {

using Material =
    std::variant<PhongMaterial, ReflectiveMaterial, RefractiveMaterial, FresnelMaterial, GlossyMaterial>;

/// The local (Phong) shading parameters of any material.
inline const PhongMaterial& phong_of(const Material& m) {
  return std::visit([](const auto& alternative) -> const PhongMaterial& {
    if constexpr (std::is_same_v<std::decay_t<decltype(alternative)>, PhongMaterial>) {
      return alternative;
    } else {
      return alternative.base;
    }
  }, m);
}

/// The grey material of geometry that has none (kd 0.5, ks 0).
inline Material default_material() { return PhongMaterial{{0.5f, 0.5f, 0.5f}, {0, 0, 0}, 1}; }

}  // namespace mjray

