#pragma once
/// Integers written most significant byte first, as PNG and zlib store them.

#include <cstdint>
#include <string>

namespace mjray {

/// Appends the four bytes of `v`, most significant first.
inline void append_big_endian(std::string& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xff);
}

}  // namespace mjray
