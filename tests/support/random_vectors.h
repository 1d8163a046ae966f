#pragma once
/// Random vectors for tests that sample geometry.

#include <random>

#include "mjray/core/vector.h"

namespace mjray::test {

/// A direction uniform on the unit sphere (a normalised Gaussian triple, redrawn when tiny).
inline Vector3 random_unit_vector(std::mt19937& rng) {
  std::normal_distribution<float> normal;
  for (;;) {
    const Vector3 v{normal(rng), normal(rng), normal(rng)};
    if (length(v) > 1e-3f) return normalize(v);
  }
}

}  // namespace mjray::test
