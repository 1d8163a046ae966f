#pragma once
/// How a photon or gather path goes on from a surface: along a specular lobe, by the BRDF, or
/// not at all, chosen by Russian roulette.

#include <cmath>

#include "mjray/core/sampling.h"
#include "mjray/material/shading.h"

namespace mjray {

/// What a path does next. With probability each lobe's weight (and the BRDF's albedo) it
/// follows that lobe (or the BRDF), keeping its flux; otherwise it ends. Weights that add up
/// to more than 1 are scaled to 1, so that no surface gives back more light than it receives.
struct PathChoice {
  const SpecularLobe* lobe = nullptr;  ///< the lobe followed, if any
  bool brdf = false;                   ///< whether the BRDF is sampled instead
  float scale = 1;                     ///< the sum of the weights when it exceeds 1

  /// Picks with u ∈ [0, 1) among `lobes` and a BRDF of albedo `brdf_albedo` (0: lobes only).
  static PathChoice pick(const SpecularLobes& lobes, float brdf_albedo, float u) {
    float total = brdf_albedo;
    for (const SpecularLobe& lobe : lobes) total += lobe.weight;
    PathChoice choice;
    choice.scale = std::max(1.f, total);
    float rest = u * choice.scale;
    for (const SpecularLobe& lobe : lobes) {
      if (rest < lobe.weight) {
        choice.lobe = &lobe;
        return choice;
      }
      rest -= lobe.weight;
    }
    choice.brdf = rest < brdf_albedo;
    return choice;
  }
};

/// The direction a path takes along a lobe: its axis, or for a glossy lobe a direction
/// uniform over its cone (falling back to the axis below the surface, as Whitted's rays do).
inline Vector3 lobe_direction(const SpecularLobe& lobe, const ShadingFrame& frame, float u1, float u2) {
  if (lobe.samples <= 1) return lobe.direction;
  const Vector3 d = sample_cone(lobe.direction, lobe.cos_cone, u1, u2);
  return dot(d, frame.geometric_normal) * dot(frame.wo, frame.geometric_normal) > 0 ? d : lobe.direction;
}

}  // namespace mjray
