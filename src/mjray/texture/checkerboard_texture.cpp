#include "mjray/texture/checkerboard_texture.h"

#include <cmath>

namespace mjray {

Color CheckerboardTexture::evaluate(const Point3& p, const Point2&) const {
  // Sum the three cell indices in double: float cell indices lose parity beyond 2^24.
  const double s = scale;
  const double sum = std::floor(p.x * s + kEdgeBias) + std::floor(p.y * s + kEdgeBias) +
                     std::floor(p.z * s + kEdgeBias);
  if (!std::isfinite(sum)) return colour1;
  return std::fmod(sum, 2.0) == 0 ? colour1 : colour2;
}

}  // namespace mjray
