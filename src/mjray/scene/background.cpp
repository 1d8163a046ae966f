#include "mjray/scene/background.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mjray {

namespace {

/// Bilinear lookup at (u, v) ∈ [0,1]², texel centres at (i + ½)/size; u wraps around, v stops at the poles.
Color bilinear(const Image& image, const Point2& uv) {
  const int w = image.width(), h = image.height();
  const float x = uv.u * float(w) - 0.5f, y = std::clamp(uv.v * float(h) - 0.5f, 0.f, float(h - 1));
  const float x_floor = std::floor(x), y_floor = std::floor(y);
  const float fx = x - x_floor, fy = y - y_floor;
  const int x0 = ((int(x_floor) % w) + w) % w, x1 = (x0 + 1) % w;
  const int y0 = int(y_floor), y1 = std::min(y0 + 1, h - 1);
  const Color top = image.at(x0, y0) * (1 - fx) + image.at(x1, y0) * fx;
  const Color bottom = image.at(x0, y1) * (1 - fx) + image.at(x1, y1) * fx;
  return top * (1 - fy) + bottom * fy;
}

}  // namespace

Point2 equirectangular_uv(const Vector3& d) {
  constexpr float kPi = std::numbers::pi_v<float>;
  const float u = 0.5f + std::atan2(d.x, -d.z) / (2 * kPi);
  const float v = std::acos(std::clamp(d.y, -1.f, 1.f)) / kPi;
  return {u - std::floor(u), v};
}

Color Background::radiance(const Vector3& direction) const {
  if (environment) return bilinear(*environment, equirectangular_uv(normalize(direction)));
  if (zenith == horizon) return zenith;
  const float up = std::clamp(direction.y / length(direction), 0.f, 1.f);
  return horizon * (1 - up) + zenith * up;
}

}  // namespace mjray
