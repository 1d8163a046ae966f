#pragma once
/// The result of a visibility query: just enough to find the surface again.

#include <cstdint>

namespace mjray {

/// The nearest intersection: distance along the ray, primitive id in the World, and the
/// barycentric weights (b1, b2) of a triangle's second and third vertices (0 for other shapes).
struct Hit {
  float t;
  uint32_t prim;
  float u = 0;
  float v = 0;
};

}  // namespace mjray
