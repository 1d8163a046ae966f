#pragma once
/// The closed set of materials and the questions every one of them answers.
///
/// Each material is a struct in `<name>_material.h` with
///   - `LocalShading local(const SurfaceInteraction&)`: the CS 488 Phong terms at a hit (and,
///     through LocalShading::eval/sample, the physically based BRDF they map to);
///   - `LocalShading scattering(const SurfaceInteraction&)`: the non-specular reflectance that
///     transports beyond Whitted (photons, final gather) scatter by, energy-conserving;
///   - `SpecularLobes specular_lobes(const ShadingFrame&)`: the mirror, glossy and refracted
///     directions light arrives along, with their weights, and `bool specular()`: whether it
///     ever has any (photons for caustics are aimed at such objects);
///   - `Color shadow_transmittance(const ShadingFrame&)`: what a shadow ray crossing the
///     surface keeps (black: opaque), and `bool transmissive()`: whether that is ever more
///     than black (the accelerators then let shadow rays continue past it).
/// The functions below dispatch with std::visit, so a material missing one does not compile.
/// To add a material: write the struct, add it to `Material`, bind it in
/// `lua/extension_bindings.cpp`, and test it in `tests/unit/material/`.

#include <variant>

#include "mjray/material/fresnel_material.h"
#include "mjray/material/glossy_material.h"
#include "mjray/material/phong_material.h"
#include "mjray/material/reflective_material.h"
#include "mjray/material/refractive_material.h"

namespace mjray {

using Material =
    std::variant<PhongMaterial, ReflectiveMaterial, RefractiveMaterial, FresnelMaterial, GlossyMaterial>;

inline LocalShading local_shading(const Material& m, const SurfaceInteraction& si) {
  return std::visit([&](const auto& material) { return material.local(si); }, m);
}
inline LocalShading scattering(const Material& m, const SurfaceInteraction& si) {
  return std::visit([&](const auto& material) { return material.scattering(si); }, m);
}
inline SpecularLobes specular_lobes(const Material& m, const ShadingFrame& f) {
  return std::visit([&](const auto& material) { return material.specular_lobes(f); }, m);
}
inline bool specular(const Material& m) {
  return std::visit([](const auto& material) { return material.specular(); }, m);
}
inline Color shadow_transmittance(const Material& m, const ShadingFrame& f) {
  return std::visit([&](const auto& material) { return material.shadow_transmittance(f); }, m);
}

inline bool transmissive(const Material& m) {
  return std::visit([](const auto& material) { return material.transmissive(); }, m);
}

/// The Phong parameters (and texture) of any material: the struct itself or its `base`.
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
