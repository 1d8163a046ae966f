#pragma once
/// A ray with a parametric range, the unit of every visibility query.

#include <limits>

#include "mjray/core/vector.h"

namespace mjray {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// origin + t·direction for t in (0, t_max); the direction need not be unit length
/// (object-space rays keep the world-space t).
struct Ray {
  Point3 origin;
  Vector3 direction;

  constexpr Point3 at(float t) const { return origin + direction * t; }
};

/// The open range (min, max) of ray parameters a query accepts.
struct Interval {
  float min = 0;
  float max = kInfinity;

  constexpr bool contains(float t) const { return t > min && t < max; }
};

}  // namespace mjray
