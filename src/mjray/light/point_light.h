#pragma once
/// gr.light: a point light with quadratic falloff.

#include <array>

#include "mjray/core/sampling.h"
#include "mjray/light/light_sample.h"

namespace mjray {

/// A point light emitting equally in every direction; its contribution at distance d is
/// colour / (c0 + c1·d + c2·d²).
struct PointLight {
  Point3 position;
  Color colour;
  float falloff[3] = {1, 0, 0};  ///< c0, c1, c2

  /// The attenuation factor at distance d.
  float attenuation(float d) const { return falloff_attenuation(falloff, d); }

  /// A point light needs one sample, whatever the area-light sampling asks for.
  int samples_per_axis(int /*requested*/) const { return 1; }
  /// The light arriving at `receiver` (u is unused: there is one point to sample).
  LightSample sample_li(const Point3& receiver, Point2 /*u*/) const {
    const float d = length(position - receiver);
    return {position, colour * attenuation(d), d};
  }
  /// The light's position and intensity (u is unused).
  EmissionPoint emission_point(Point2 /*u*/) const { return {position, colour}; }
  /// Where its samples lie: the position (four times, for the parallelogram shape of lights).
  std::array<Point3, 4> sample_region(const Point3& /*receiver*/) const { return {position, position, position, position}; }
  /// Photons leave it equally in every direction.
  float emission_profile(const Vector3& /*w*/) const { return 1; }
  EmissionCone emission_cone() const { return {}; }
  /// A photon's flux after `d` along its first flight: the falloff in place of 1 / d².
  float photon_falloff(float d) const { return d * d * attenuation(d); }
  /// Total flux, 4π · colour (before falloff).
  Color power() const { return isotropic_power(colour); }
};

}  // namespace mjray
