#pragma once
/// gr.checkerboardtexture: a solid (3-D) checkerboard of cubic cells.

#include "mjray/core/color.h"
#include "mjray/core/vector.h"

namespace mjray {

/// Cubic cells of edge `scale` (object units) aligned with the object frame's axes: a point
/// p reads colour1 where ⌊x/s + ε⌋ + ⌊y/s + ε⌋ + ⌊z/s + ε⌋ is even, colour2 where it is odd
/// (s = scale, ε = kEdgeBias). So a cell spans [k·s − ε·s, (k+1)·s − ε·s) on each axis: a face
/// lying on a cell boundary (a floor at y = 0), whose hit points scatter by rounding on both
/// sides of it, reads the cell on its + side everywhere instead of flickering between two.
struct CheckerboardTexture {
  /// Fraction of a cell by which the cell boundaries sit below the multiples of the scale.
  static constexpr double kEdgeBias = 1e-4;

  Color colour1;
  Color colour2;
  float scale = 1;  ///< cell edge length in object units, > 0

  /// The colour at an object-space point (the uv is unused).
  Color evaluate(const Point3& object_point, const Point2& uv = {}) const;
};

}  // namespace mjray
