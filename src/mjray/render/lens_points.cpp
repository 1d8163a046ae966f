#include "mjray/render/lens_points.h"

#include "mjray/core/rng.h"

namespace mjray {

uint32_t van_der_corput_bits(uint32_t i) {
  // Reverse the bits.
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
  return i;
}

uint32_t sobol_second_bits(uint32_t i) {
  // Sobol's second generator matrix: the columns 1, 11, 101, 1111, ... (Pascal's triangle mod 2).
  uint32_t result = 0;
  for (uint32_t column = 1u << 31; i != 0; i >>= 1, column ^= column >> 1)
    if (i & 1) result ^= column;
  return result;
}

uint32_t permutation_element(uint32_t i, uint32_t n, uint32_t key) {
  // Hash i within the smallest power-of-two range over n, again until it falls below n
  // (cycle-walking keeps it a bijection of [0, n)).
  uint32_t mask = n - 1;
  mask |= mask >> 1;
  mask |= mask >> 2;
  mask |= mask >> 4;
  mask |= mask >> 8;
  mask |= mask >> 16;
  do {
    i ^= key;
    i *= 0xe170893du;
    i ^= key >> 16;
    i ^= (i & mask) >> 4;
    i ^= key >> 8;
    i *= 0x0929eb3fu;
    i ^= key >> 23;
    i ^= (i & mask) >> 1;
    i *= 1 | key >> 27;
    i *= 0x6935fa69u;
    i ^= (i & mask) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & mask) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & mask) >> 2;
    i *= 0xc860a3dfu;
    i &= mask;
    i ^= i >> 5;
  } while (i >= n);
  return (i + key) % n;
}

LensPoints::LensPoints(uint64_t seed, uint64_t pixel, uint64_t pass, uint32_t count) : count_(count) {
  const uint64_t a = mix64(mix64(mix64(seed ^ 0x6c656e73ULL) ^ pixel) ^ mix64(pass + 0x9e3779b97f4a7c15ULL));
  const uint64_t b = mix64(a);
  order_ = uint32_t(a);
  flip_u_ = uint32_t(a >> 32);
  flip_v_ = uint32_t(b);
}

LensPoint LensPoints::at(uint32_t k) const {
  const uint32_t i = permutation_element(k, count_, order_);
  // The top 24 bits, which a float holds exactly: the point stays below 1.
  return {float((van_der_corput_bits(i) ^ flip_u_) >> 8) * 0x1p-24f, float((sobol_second_bits(i) ^ flip_v_) >> 8) * 0x1p-24f};
}

}  // namespace mjray
