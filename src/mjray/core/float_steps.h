#pragma once
/// Stepping to the neighbouring float, for bounds that must not round back.

#include <bit>
#include <cstdint>
#include <limits>

namespace mjray {

/// The next float above (up) or below a finite v, without a library call.
constexpr float next_float(float v, bool up) {
  if (v == 0) return up ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits += (v > 0) == up ? 1u : ~0u;  // one step away from or toward zero
  return std::bit_cast<float>(bits);
}

}  // namespace mjray
