#pragma once
/// What lights answer: a point to send a shadow ray to with the light arriving from it, and
/// an emitted ray for transports that start at lights.

#include <numbers>

#include "mjray/core/color.h"
#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// One sample of the light reaching a receiver: where it comes from and its intensity there
/// (colour × falloff at the receiver's distance), before shadowing and shading.
struct LightSample {
  Point3 position;
  Color intensity;
  float distance;  ///< |position − receiver|, as the falloff used it
};

/// A point light leaves a light from, and the radiant intensity of the whole light there, the
/// same in every direction: photons drawn from it carry intensity × solid angle / count.
struct EmissionPoint {
  Point3 position;
  Color intensity;
};

/// The directions a light sends photons into from a point: within acos(1 − one_minus_cos)
/// of `axis` (2: every direction).
struct EmissionCone {
  Vector3 axis{0, 0, 1};
  float one_minus_cos = 2;
};

/// The falloff 1 / (c0 + c1·d + c2·d²) at distance d; 0 where the denominator is not positive.
inline float falloff_attenuation(const float (&falloff)[3], float d) {
  const float denominator = falloff[0] + falloff[1] * d + falloff[2] * d * d;
  return denominator > 0 ? 1 / denominator : 0;
}

/// The flux of an isotropic emitter of intensity `colour`: 4π · colour.
inline Color isotropic_power(const Color& colour) { return colour * (4 * std::numbers::pi_v<float>); }

}  // namespace mjray
