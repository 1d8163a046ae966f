#pragma once
/// gr.checkerboardtexture: a solid (3-D) checkerboard of cubic cells.

#include "mjray/core/color.h"
#include "mjray/core/vector.h"

namespace mjray {

/// Cubic cells of edge 1/scale aligned with the axes of the texture's space: as for every
/// texture the point is multiplied by the scale (a smaller scale, larger cells), and p reads
/// colour1 where ⌊s·x + ε⌋ + ⌊s·y + ε⌋ + ⌊s·z + ε⌋ is even, colour2 where it is odd
/// (s = scale, ε = kEdgeBias). So a cell spans [(k − ε)/s, (k + 1 − ε)/s) on each axis: a face
/// lying on a cell boundary (a floor at y = 0), whose hit points scatter by rounding on both
/// sides of it, reads the cell on its + side everywhere instead of flickering between two.
struct CheckerboardTexture {
  /// Fraction of a cell by which the cell boundaries sit below the multiples of the scale.
  static constexpr double kEdgeBias = 1e-4;

  Color colour1;
  Color colour2;
  float scale = 1;  ///< cells per unit length, > 0 (the cell edge is 1/scale)

  /// The colour at an object-space point (the uv is unused).
  Color evaluate(const Point3& object_point, const Point2& uv = {}) const;
};

}  // namespace mjray
