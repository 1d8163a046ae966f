// The strip-parallel zlib stream: zlib itself inflates it back to the input, whatever its
// size against the strips, and its bytes do not depend on the number of threads.

#include "mjray/io/zlib_stream.h"

#include <zlib.h>

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace mjray {
namespace {

/// `size` bytes mixing runs, a repeating pattern and noise, so deflate uses all its means.
std::vector<uint8_t> sample_data(size_t size) {
  std::vector<uint8_t> data(size);
  uint32_t state = 12345;
  for (size_t i = 0; i < size; ++i) {
    state = state * 1664525u + 1013904223u;
    const size_t part = (i / 5000) % 3;
    data[i] = part == 0 ? uint8_t(i / 700) : part == 1 ? uint8_t("mjray strips"[i % 12]) : uint8_t(state >> 24);
  }
  return data;
}

std::vector<uint8_t> inflated(const std::string& stream, size_t expected_size) {
  std::vector<uint8_t> out(expected_size + 1);
  uLongf size = uLongf(out.size());
  const int status = uncompress(out.data(), &size, reinterpret_cast<const Bytef*>(stream.data()), uLong(stream.size()));
  EXPECT_EQ(status, Z_OK);
  out.resize(size);
  return out;
}

TEST(ZlibStream, InflatesToTheInputAtEverySizeAroundTheStrips) {
  constexpr size_t kStrip = size_t(128) << 10;
  for (const size_t size : {size_t(0), size_t(1), size_t(1000), kStrip - 1, kStrip, kStrip + 1, 3 * kStrip + 77,
                            size_t(2) << 20}) {
    const auto data = sample_data(size);
    for (const int level : {1, 3, 9}) {
      const std::string stream = zlib_stream(data, level, 4);
      EXPECT_EQ(inflated(stream, size), data) << size << " bytes at level " << level;
      // The header says deflate with a 32 KiB window and checks itself.
      ASSERT_GE(stream.size(), 6u);
      EXPECT_EQ(uint8_t(stream[0]), 0x78);
      EXPECT_EQ(((uint8_t(stream[0]) << 8) | uint8_t(stream[1])) % 31, 0);
    }
  }
}

TEST(ZlibStream, BytesDoNotDependOnTheThreadCount) {
  const auto data = sample_data(size_t(1) << 20);
  const std::string one = zlib_stream(data, 3, 1);
  for (const int threads : {2, 3, 8, 64}) EXPECT_EQ(zlib_stream(data, 3, threads), one) << threads;
}

TEST(ZlibStream, StripsPrimedWithTheWindowBeforeThemCompressAboutAsWellAsOneStream) {
  // A pattern longer than a strip's window repeats: each strip finds it in the window before it.
  const auto data = sample_data(size_t(1) << 20);
  const std::string ours = zlib_stream(data, 3, 4);
  uLongf size = compressBound(uLong(data.size()));
  std::vector<Bytef> whole(size);
  ASSERT_EQ(compress2(whole.data(), &size, data.data(), uLong(data.size()), 3), Z_OK);
  EXPECT_LT(double(ours.size()), 1.01 * double(size)) << ours.size() << " against " << size;
}

}  // namespace
}  // namespace mjray
