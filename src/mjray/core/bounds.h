#pragma once
/// Axis-aligned bounding boxes.

#include <algorithm>

#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// An axis-aligned box [lo, hi]; the default box is empty (lo > hi) and absorbs any union.
struct Bounds3 {
  Point3 lo{kInfinity, kInfinity, kInfinity};
  Point3 hi{-kInfinity, -kInfinity, -kInfinity};

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void expand(const Point3& p) { lo = min(lo, p); hi = max(hi, p); }
  void expand(const Bounds3& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
  Vector3 diagonal() const { return hi - lo; }
  Point3 centre() const { return lo + diagonal() * 0.5f; }
  Point3 corner(int i) const {
    return {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
  }
  float surface_area() const {
    if (empty()) return 0;
    const Vector3 d = diagonal();
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

}  // namespace mjray
