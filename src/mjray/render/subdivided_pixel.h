#pragma once
/// Adaptive supersampling by subdivision (Whitted 1980; POV-Ray's +AM2): a pixel is sampled at
/// its four corners, and a square whose corners differ by more than a threshold is split into
/// four, down to a finest lattice. Neighbouring squares share their corners, so a pixel where
/// nothing changes costs one sample (the corner it shares with three others) and an edge is
/// refined only along its length.

#include <functional>

#include "mjray/core/color.h"

namespace mjray {

/// The lattice of a subdivided pixel: cells() × cells() cells, cells() = 2^levels.
struct SubdivisionLattice {
  int levels = 0;
  int cells() const { return 1 << levels; }
  /// The fewest levels whose cells are at most 1/n pixel wide (-a n): 1 → 0, 2 → 1, 3..4 → 2.
  static SubdivisionLattice finest_for(int n);
};

/// Whether some channel of the four colours spans more than `threshold`.
bool corners_differ(const Color& a, const Color& b, const Color& c, const Color& d, float threshold);

/// The estimate of the square with top-left lattice point (i, j) and `size` cells per side (a
/// power of two): the mean of its four corners if they do not differ or `size` is 1, else the
/// mean of its four quarters' estimates. `corner(i, j)` gives the colour at a lattice point;
/// the caller keeps the points already sampled.
Color subdivided_estimate(int i, int j, int size, float threshold, const std::function<const Color&(int, int)>& corner);

}  // namespace mjray
