#pragma once
/// gr.arealight: a parallelogram light, sampled with jittered shadow rays for soft shadows.

#include "mjray/core/color.h"
#include "mjray/core/vector.h"

namespace mjray {

/// The parallelogram corner + s·edge1 + t·edge2, s, t in [0,1], emitting `colour` in total
/// with the falloff of a point light at each sample point.
struct AreaLight {
  Point3 corner;
  Vector3 edge1;  ///< corner1 − corner
  Vector3 edge2;  ///< corner2 − corner
  Color colour;
  float falloff[3] = {1, 0, 0};

  /// The point at parameters (s, t).
  Point3 point_at(float s, float t) const { return corner + edge1 * s + edge2 * t; }
  float attenuation(float d) const {
    const float denominator = falloff[0] + falloff[1] * d + falloff[2] * d * d;
    return denominator > 0 ? 1 / denominator : 0;
  }
};

}  // namespace mjray
