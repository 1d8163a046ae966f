#include "mjray/texture/perlin_texture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mjray/texture/perlin_noise.h"

namespace mjray {

double PerlinTexture::weight(const Point3& p) const {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  const double x = double(p.x) * scale, y = double(p.y) * scale, z = double(p.z) * scale;
  double t = 0;
  switch (pattern) {
    case PerlinPattern::kLinear:
    case PerlinPattern::kCosine:
      t = 0.5 + 0.5 * perlin_fractal(x, y, z, kFractalOctaves);
      break;
    case PerlinPattern::kMarble:
      t = 1 - std::abs(std::sin(std::numbers::pi * (x + kMarbleTurbulence * perlin_turbulence(x, y, z, kTurbulenceOctaves))));
      break;
    case PerlinPattern::kWavy:
      t = 0.5 + 0.5 * std::sin(kTwoPi * (x + noise_multiplier * perlin_noise(x, y, z)));
      break;
    case PerlinPattern::kWoodGrain:
      t = kWoodRings * perlin_noise(x, y, z);
      t -= std::floor(t);
      break;
  }
  // NaN (from a non-finite point) reads as colour1.
  return std::isnan(t) ? 0 : std::clamp(t, 0.0, 1.0);
}

Color PerlinTexture::evaluate(const Point3& p, const Point2&) const {
  double w = weight(p);
  if (pattern != PerlinPattern::kLinear) w = (1 - std::cos(std::numbers::pi * w)) / 2;
  const auto f = float(w);
  return colour1 * (1 - f) + colour2 * f;
}

}  // namespace mjray
