// The counter-based random stream: draw i of a stream is mix64(key ^ mix64(i)), for every i,
// those whose index hash comes from the precomputed table and those past it.

#include "mjray/core/rng.h"

#include <array>
#include <cstdint>

#include <gtest/gtest.h>

namespace mjray {
namespace {

/// Draw `index` of the stream with key `key`, by the formula alone.
float formula_draw(uint64_t key, uint64_t index) { return float(mix64(key ^ mix64(index)) >> 40) * 0x1p-24f; }

TEST(RandomStream, EveryDrawIsTheHashOfTheKeyAndItsIndexBeforeAndPastTheTable) {
  for (const auto& [seed, pixel, sample] : {std::array<uint64_t, 3>{0, 0, 0}, {7, 123456, 3}, {~uint64_t(0), 5, 1 << 20}}) {
    const uint64_t key = mix64(mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ pixel) ^ (sample * 0xd1b54a32d192ed03ULL));
    RandomStream random(seed, pixel, sample);
    for (uint64_t i = 1; i <= 3 * DrawIndexHashes::kCount; ++i) ASSERT_EQ(random.uniform(), formula_draw(key, i)) << i;
  }
}

TEST(RandomStream, TheTableHoldsTheIndexHashes) {
  for (uint64_t i = 0; i < DrawIndexHashes::kCount; ++i) EXPECT_EQ(kDrawIndexHashes.of[i], mix64(i)) << i;
}

TEST(RandomStream, SkippingDrawsGoesOnAsIfTheyHadBeenDrawn) {
  for (const uint64_t skipped : {uint64_t(0), uint64_t(1), uint64_t(32), uint64_t(DrawIndexHashes::kCount + 3)}) {
    RandomStream drawn(3, 41, 2), skipping(3, 41, 2);
    drawn.uniform(), skipping.uniform();
    for (uint64_t i = 0; i < skipped; ++i) drawn.uniform();
    skipping.skip(skipped);
    for (int i = 0; i < 8; ++i) ASSERT_EQ(skipping.uniform(), drawn.uniform()) << skipped << ", " << i;
  }
}

}  // namespace
}  // namespace mjray
