#pragma once
/// The CS 488 Phong material: diffuse and specular colours and a specular exponent.

#include <memory>

#include "mjray/core/color.h"
#include "mjray/geometry/surface_interaction.h"
#include "mjray/material/shading.h"
#include "mjray/texture/texture.h"

namespace mjray {

/// gr.material(kd, ks, shininess): the local shading model shared by every material. Opaque,
/// with no specular lobes.
struct PhongMaterial {
  Color kd;               ///< diffuse reflectance, also scales the ambient light
  Color ks;               ///< specular reflectance
  float shininess = 0;    ///< Phong exponent of max(0, r·v)
  /// material:set_material_texture: when set, replaces kd at each hit (ambient and diffuse).
  std::shared_ptr<const Texture> texture = nullptr;
  /// Which point a solid texture reads (set_material_texture's optional 'world' | 'object').
  TextureSpace texture_space = TextureSpace::kWorld;

  /// The diffuse reflectance at a hit: the texture's colour there, or kd.
  Color kd_at(const SurfaceInteraction& si) const {
    if (!texture) return kd;
    return evaluate(*texture, texture_space == TextureSpace::kWorld ? si.point : si.object_point, si.uv);
  }

  LocalShading local(const SurfaceInteraction& si) const { return {kd_at(si), ks, shininess}; }
  /// Light beyond Whitted scatters by the whole Phong model: ks is a glossy lobe here.
  LocalShading scattering(const SurfaceInteraction& si) const { return local(si).energy_conserving(); }
  SpecularLobes specular_lobes(const ShadingFrame&) const { return {}; }
  bool specular() const { return false; }
  /// The scattering of a material with specular lobes: kd alone. Its ks is the highlight of
  /// the lights that those lobes would show, and the lobes reflect everything else.
  LocalShading diffuse_scattering(const SurfaceInteraction& si) const {
    return LocalShading{kd_at(si), {}, 1}.energy_conserving();
  }
  Color shadow_transmittance(const ShadingFrame&) const { return {}; }
  bool transmissive() const { return false; }
};

}  // namespace mjray
