#pragma once
/// What photon maps hold: photons where they landed, and irradiance computed at some of them.

#include <cmath>
#include <cstdint>

#include "mjray/core/color.h"
#include "mjray/core/vector.h"

namespace mjray {

/// A unit normal in three bytes (each component × 127): enough to tell whether two surface
/// points face the same way.
struct PackedNormal {
  int8_t x = 0, y = 0, z = 127;

  static PackedNormal pack(const Normal3& n) {
    return {int8_t(std::lround(n.x * 127)), int8_t(std::lround(n.y * 127)), int8_t(std::lround(n.z * 127))};
  }
  Normal3 unit() const { return normalize(Normal3(float(x), float(y), float(z))); }
  /// The cosine between this normal and unit n (to about 1%).
  float dot(const Normal3& n) const { return (float(x) * n.x + float(y) * n.y + float(z) * n.z) * (1.f / 127); }
};

/// A photon stored where it met a diffuse surface: the flux it carries there, in the lights'
/// units (a CS 488 light of colour I and falloff 1 gives the surface I per unit area at normal
/// incidence), and the surface's normal on the side it arrived from.
struct Photon {
  Point3 position;
  Color power;
  PackedNormal normal;
};

/// The irradiance estimated at one photon's place, for final gathering.
struct IrradianceSample {
  Point3 position;
  Color irradiance;
  PackedNormal normal;
};

}  // namespace mjray
