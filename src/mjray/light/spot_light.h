#pragma once
/// gr.spotlight: a point light that shines into a cone, its edge softened over a penumbra
/// (POV-Ray's spotlight radius and falloff; Cycles' spot size and blend).

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "mjray/core/sampling.h"
#include "mjray/light/light_sample.h"

namespace mjray {

/// A point light whose intensity toward a direction at angle θ from its axis is colour for
/// θ ≤ cone, 0 for θ ≥ cone + penumbra, and a smoothstep between; with gr.light's falloff.
struct SpotLight {
  Point3 position;
  Vector3 direction{0, 0, -1};  ///< unit: the cone's axis
  Color colour;
  float falloff[3] = {1, 0, 0};
  float cone = 0.5f;   ///< radians: the half-angle of the fully lit cone
  float penumbra = 0;  ///< radians beyond `cone` over which the light fades to nothing

  float attenuation(float d) const { return falloff_attenuation(falloff, d); }
  /// The fraction of `colour` sent along the unit direction `w` (from the light).
  float profile(const Vector3& w) const;

  /// A spot light needs one sample, as a point light.
  int samples_per_axis(int /*requested*/) const { return 1; }
  /// The light arriving at `receiver` (u is unused). Out of line, as the sun's: the loops
  /// over light samples inline the point and area lights' instead.
  LightSample sample_li(const Point3& receiver, Point2 u) const;
  std::array<Point3, 4> sample_region(const Point3& /*receiver*/) const {
    return {position, position, position, position};
  }

  /// Photons: from the position, only into the outer cone, each carrying profile × intensity.
  EmissionPoint emission_point(Point2 /*u*/) const { return {position, colour}; }
  float emission_profile(const Vector3& w) const { return profile(w); }
  /// 1 − cos θ as 2 sin²(θ/2), exact for the narrowest cones.
  EmissionCone emission_cone() const {
    const float half = std::sin(std::min(cone + penumbra, std::numbers::pi_v<float>) / 2);
    return {direction, 2 * half * half};
  }
  /// A photon's flux after `d` along its first flight: the falloff in place of 1 / d².
  float photon_falloff(float d) const { return d * d * attenuation(d); }
  /// The flux into the outer cone at full intensity (an upper bound, for choosing lights).
  Color power() const { return colour * (2 * std::numbers::pi_v<float> * emission_cone().one_minus_cos); }
};

}  // namespace mjray
