#include "mjray/render/subdivided_pixel.h"

#include <algorithm>

#include "mjray/core/error.h"

namespace mjray {

SubdivisionLattice SubdivisionLattice::finest_for(int n) {
  MJRAY_CHECK(n >= 1);
  int levels = 0;
  while ((1 << levels) < n) ++levels;
  return {levels};
}

bool corners_differ(const Color& a, const Color& b, const Color& c, const Color& d, float threshold) {
  const auto spread = [&](float Color::*channel) {
    const auto [lo, hi] = std::minmax({a.*channel, b.*channel, c.*channel, d.*channel});
    return hi - lo;
  };
  return spread(&Color::r) > threshold || spread(&Color::g) > threshold || spread(&Color::b) > threshold;
}

Color subdivided_estimate(int i, int j, int size, float threshold,
                          const std::function<const Color&(int, int)>& corner) {
  // Copied: the references corner() returns may not outlive the next call.
  const Color a = corner(i, j), b = corner(i + size, j), c = corner(i, j + size), d = corner(i + size, j + size);
  if (size == 1 || !corners_differ(a, b, c, d, threshold)) return (a + b + c + d) / 4.f;
  const int half = size / 2;
  const auto quarter = [&](int qi, int qj) { return subdivided_estimate(qi, qj, half, threshold, corner); };
  return (quarter(i, j) + quarter(i + half, j) + quarter(i, j + half) + quarter(i + half, j + half)) / 4.f;
}

}  // namespace mjray
