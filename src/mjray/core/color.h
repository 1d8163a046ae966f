#pragma once
/// Linear RGB radiance/reflectance triple.

#include <algorithm>

namespace mjray {

/// An RGB colour in linear units; components may exceed 1 before output clamping.
struct Color {
  float r = 0, g = 0, b = 0;

  constexpr Color() = default;
  constexpr Color(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}

  constexpr Color operator+(const Color& c) const { return {r + c.r, g + c.g, b + c.b}; }
  constexpr Color operator-(const Color& c) const { return {r - c.r, g - c.g, b - c.b}; }
  /// Component-wise product (the ⊙ of the shading formulas).
  constexpr Color operator*(const Color& c) const { return {r * c.r, g * c.g, b * c.b}; }
  constexpr Color operator*(float s) const { return {r * s, g * s, b * s}; }
  constexpr Color operator/(float s) const { return {r / s, g / s, b / s}; }
  constexpr Color& operator+=(const Color& c) { return *this = *this + c; }
  constexpr bool operator==(const Color&) const = default;

  constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
  constexpr float max_component() const { return std::max({r, g, b}); }
  /// The mean of the three channels: how bright, with every channel counted alike (so that a
  /// blue-only difference counts as much as a green one).
  constexpr float average() const { return (r + g + b) * (1.f / 3); }
};

constexpr Color operator*(float s, const Color& c) { return c * s; }

}  // namespace mjray
