#pragma once
/// gr.arealight: a parallelogram light, sampled with jittered shadow rays for soft shadows.

#include <array>

#include "mjray/core/sampling.h"
#include "mjray/light/light_sample.h"

namespace mjray {

/// The parallelogram corner + s·edge1 + t·edge2, s, t in [0,1]: as the original, a
/// parallelogram of point emitters that together emit `colour` (each sample point lights the
/// receiver like a point light there, with the same falloff).
struct AreaLight {
  Point3 corner;
  Vector3 edge1;  ///< corner1 − corner
  Vector3 edge2;  ///< corner2 − corner
  Color colour;
  float falloff[3] = {1, 0, 0};

  /// The point at parameters (s, t).
  Point3 point_at(float s, float t) const { return corner + edge1 * s + edge2 * t; }
  float attenuation(float d) const { return falloff_attenuation(falloff, d); }

  /// -s N: an N×N jittered grid over the parallelogram.
  int samples_per_axis(int requested) const { return requested; }
  /// The light from the point at parameters u = (s, t) arriving at `receiver`.
  LightSample sample_li(const Point3& receiver, Point2 u) const {
    const Point3 p = point_at(u.u, u.v);
    const float d = length(p - receiver);
    return {p, colour * attenuation(d), d};
  }
  /// The point at parameters u, uniform over the parallelogram, with the whole light's
  /// intensity (the mean over the points is the light).
  EmissionPoint emission_point(Point2 u) const { return {point_at(u.u, u.v), colour}; }
  /// The parallelogram its samples lie in, corners in order around it.
  std::array<Point3, 4> sample_region(const Point3& /*receiver*/) const { return {corner, corner + edge1, corner + edge1 + edge2, corner + edge2}; }
  /// Photons leave it equally in every direction.
  float emission_profile(const Vector3& /*w*/) const { return 1; }
  EmissionCone emission_cone() const { return {}; }
  /// A photon's flux after `d` along its first flight: the falloff in place of 1 / d².
  float photon_falloff(float d) const { return d * d * attenuation(d); }
  /// Total flux, 4π · colour (before falloff).
  Color power() const { return isotropic_power(colour); }
};

}  // namespace mjray
