#pragma once
/// gr.sunlight: light from a distant disc (the sun): parallel rays without falloff, soft
/// shadows from a disc of the sun's angular size.

#include <array>
#include <cmath>
#include <numbers>

#include "mjray/core/sampling.h"
#include "mjray/light/light_sample.h"

namespace mjray {

/// A light at infinity: a surface facing it receives `colour` (as a point light of no falloff
/// one unit away), whatever its position. Its disc spans `half_angle` about its direction;
/// samples are uniform over the disc's tangent plane (the same as over its solid angle to
/// well under 1 % below 10°).
struct SunLight {
  Vector3 direction{0, -1, 0};  ///< unit: the way its light travels
  Color colour;
  float half_angle = 0;  ///< radians: half the sun's angular diameter
  /// A ball around the scene, set by fit_to_scene: where shadow rays start beyond, and what
  /// its photons cover.
  Point3 scene_centre;
  float scene_radius = 0;

  void fit_to_scene(const Point3& centre, float radius) { scene_centre = centre, scene_radius = radius; }
  /// The direction toward the sun's disc at u ∈ [0,1)², not unit length: its tangent-plane
  /// point (a unit step toward the sun plus the offset on the plane).
  Vector3 toward(Point2 u) const {
    const Vector3 axis = -direction;
    if (!(half_angle > 0)) return axis;
    const Point2 d = sample_concentric_disk(u.u, u.v);
    const Basis b = orthonormal_basis(axis);
    const float r = std::tan(half_angle);
    return axis + b.tangent * (r * d.u) + b.bitangent * (r * d.v);
  }
  /// The radius of a disc across its light whose lines from every point of the sun's disc
  /// still cover a ball of radius r: r / cos of its half-angle.
  float covering_radius(float r) const { return r / std::cos(half_angle); }
  /// How far back toward the sun a shadow ray from `receiver` must go to clear the scene.
  float clearance(const Point3& receiver) const { return length(receiver - scene_centre) + 2 * scene_radius + 1; }

  int samples_per_axis(int requested) const { return half_angle > 0 ? requested : 1; }
  /// Light from the point of the disc at u, placed beyond the scene (out of line: see SpotLight).
  LightSample sample_li(const Point3& receiver, Point2 u) const;
  /// The square around the disc's points, as seen from `receiver`.
  std::array<Point3, 4> sample_region(const Point3& receiver) const {
    const Vector3 axis = -direction;
    const Basis b = orthonormal_basis(axis);
    const float r = half_angle > 0 ? std::tan(half_angle) : 0, far = clearance(receiver);
    const auto corner = [&](float s, float t) {
      return receiver + (axis + b.tangent * (r * s) + b.bitangent * (r * t)) * far;
    };
    return {corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)};
  }
  /// A photon's flux does not fall off.
  float photon_falloff(float /*d*/) const { return 1; }
  /// The flux through the scene's cross-section.
  Color power() const { return colour * (std::numbers::pi_v<float> * scene_radius * scene_radius); }
};

}  // namespace mjray
