#pragma once
/// Counter-based random numbers: every value is a pure function of (seed, pixel, sample,
/// dimension), so images do not depend on threads, tile order or process count.

#include <cstdint>

namespace mjray {

/// A 64-bit finaliser with full avalanche (SplitMix64's), the core of every draw.
constexpr uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

/// mix64 of the first draw indices, the half of every draw that is the same in all streams.
struct DrawIndexHashes {
  static constexpr uint64_t kCount = 512;
  uint64_t of[kCount];
  constexpr DrawIndexHashes() : of() {
    for (uint64_t i = 0; i < kCount; ++i) of[i] = mix64(i);
  }
};
inline constexpr DrawIndexHashes kDrawIndexHashes;

/// The random stream of one sample of one pixel; draw i is hash(key, i).
class RandomStream {
 public:
  constexpr RandomStream(uint64_t seed, uint64_t pixel, uint64_t sample)
      : key_(mix64(mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ pixel) ^ (sample * 0xd1b54a32d192ed03ULL))) {}

  /// A stream for a sub-task (e.g. one glossy ray) that does not disturb this stream's order.
  constexpr RandomStream fork(uint64_t tag) const { return RandomStream(key_, tag); }

  /// Passes over the next `draws` values unread: the stream goes on as if they had been drawn.
  constexpr void skip(uint64_t draws) { counter_ += draws; }

  /// The next uniform value in [0, 1).
  constexpr float uniform() {
    ++counter_;
    const uint64_t index_hash = counter_ < DrawIndexHashes::kCount ? kDrawIndexHashes.of[counter_] : mix64(counter_);
    const uint64_t bits = mix64(key_ ^ index_hash);
    return float(bits >> 40) * 0x1p-24f;  // 24 random bits: exactly representable, < 1
  }

 private:
  constexpr RandomStream(uint64_t parent_key, uint64_t tag) : key_(mix64(parent_key ^ mix64(tag + 0x632be59bd9b4e019ULL))) {}

  uint64_t key_;
  uint64_t counter_ = 0;
};

}  // namespace mjray
