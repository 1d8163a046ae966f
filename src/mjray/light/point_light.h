#pragma once
/// gr.light: a point light with quadratic falloff.

#include "mjray/core/color.h"
#include "mjray/core/vector.h"

namespace mjray {

/// A point light; its contribution at distance d is colour / (c0 + c1·d + c2·d²).
struct PointLight {
  Point3 position;
  Color colour;
  float falloff[3] = {1, 0, 0};  ///< c0, c1, c2

  /// The attenuation factor at distance d.
  float attenuation(float d) const {
    const float denominator = falloff[0] + falloff[1] * d + falloff[2] * d * d;
    return denominator > 0 ? 1 / denominator : 0;
  }
};

}  // namespace mjray
