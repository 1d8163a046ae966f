#pragma once
/// Lens points for the samples of one pass over a pixel: the first n points of a (0,2)-sequence
/// (with n a power of two, one point in every elementary interval of area 1/n: every 1/n-wide
/// column, row, and every box of that area between), scrambled by random digit flips and handed
/// to the samples in a random order. Both are keyed by the seed, the pixel and the pass, so the
/// points are the same for any thread, tile order or process, cover the lens evenly (depth of
/// field converges faster than with independent points), and do not follow the pixel's grid.

#include <cstdint>

namespace mjray {

/// A point on the unit square, which the camera maps to its lens.
struct LensPoint {
  float u = 0, v = 0;
};

class LensPoints {
 public:
  /// The points of a pass of `count` samples of pixel `pixel`, the pass named by `pass` (a
  /// number no other pass over that pixel uses).
  LensPoints(uint64_t seed, uint64_t pixel, uint64_t pass, uint32_t count);
  /// The point of the pass's sample k (k < count).
  LensPoint at(uint32_t k) const;

 private:
  uint32_t count_;
  uint32_t order_;          // the permutation's key
  uint32_t flip_u_, flip_v_;  // the digit flips of each coordinate
};

/// Point i of the (0,2)-sequence: (radical inverse of i in base 2, Sobol's second coordinate),
/// as 32-bit fractions.
uint32_t van_der_corput_bits(uint32_t i);
uint32_t sobol_second_bits(uint32_t i);

/// Element i of a pseudo-random permutation of [0, n) chosen by `key` (Kensler, "Correlated
/// Multi-Jittered Sampling", 2013): a bijection for every key, cheap to evaluate at any i.
uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t key);

}  // namespace mjray
