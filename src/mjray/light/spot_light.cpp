#include "mjray/light/spot_light.h"

namespace mjray {

float SpotLight::profile(const Vector3& w) const {
  // The angle from the axis, accurate for the narrowest cones (acos is not, near 1).
  const float theta = std::atan2(length(cross(w, direction)), dot(w, direction));
  if (theta <= cone) return 1;
  if (!(penumbra > 0) || theta >= cone + penumbra) return 0;
  // A smoothstep in the angle across the penumbra.
  const float t = std::clamp((cone + penumbra - theta) / penumbra, 0.f, 1.f);
  return t * t * (3 - 2 * t);
}

LightSample SpotLight::sample_li(const Point3& receiver, Point2 /*u*/) const {
  const float d = length(receiver - position);
  const float shown = d > 0 ? profile((receiver - position) / d) : 0;
  return {position, colour * (attenuation(d) * shown), d};
}

}  // namespace mjray
