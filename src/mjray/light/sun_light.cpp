#include "mjray/light/sun_light.h"

namespace mjray {

LightSample SunLight::sample_li(const Point3& receiver, Point2 u) const {
  const Vector3 w = toward(u) * clearance(receiver);
  return {receiver + w, colour, length(w)};
}

}  // namespace mjray
