#include "mjray/io/zlib_stream.h"

#include <zlib.h>

#include <algorithm>
#include <new>
#include <vector>

#include "mjray/core/parallel_for.h"
#include "mjray/io/big_endian.h"

namespace mjray {

namespace {

/// Bytes of input per strip: large enough that priming and flushing cost nothing measurable,
/// small enough that a 512×512 image gives each of a few threads a strip.
constexpr size_t kStripBytes = size_t(128) << 10;
/// deflate's window: what a strip may refer back to.
constexpr size_t kWindowBytes = size_t(32) << 10;

/// Raw deflate blocks of `strip`, able to refer to `before`; the last strip ends the stream,
/// the others end on a byte boundary (an empty stored block), so the strips concatenate.
std::string deflate_strip(std::span<const uint8_t> before, std::span<const uint8_t> strip, int level, bool last) {
  z_stream z{};
  if (deflateInit2(&z, level, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw std::bad_alloc();
  if (!before.empty()) deflateSetDictionary(&z, before.data(), uInt(before.size()));
  std::string out(deflateBound(&z, uLong(strip.size())) + 16, '\0');
  z.next_in = const_cast<Bytef*>(strip.data());
  z.avail_in = uInt(strip.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  const int status = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
  const size_t written = out.size() - z.avail_out;
  deflateEnd(&z);
  // The output buffer holds deflateBound's worst case, so one call always completes.
  if (status != (last ? Z_STREAM_END : Z_OK)) throw std::bad_alloc();
  out.resize(written);
  return out;
}

}  // namespace

std::string zlib_stream(std::span<const uint8_t> data, int level, int threads) {
  const size_t strips = std::max<size_t>(1, (data.size() + kStripBytes - 1) / kStripBytes);
  std::vector<std::string> deflated(strips);
  std::vector<uLong> checksums(strips);
  const auto strip = [&](size_t i) { return data.subspan(i * kStripBytes, std::min(kStripBytes, data.size() - i * kStripBytes)); };
  parallel_for(int(strips), threads, [&](int index, int) {
    const auto i = size_t(index);
    const size_t begin = i * kStripBytes, primed = std::min(begin, kWindowBytes);
    deflated[i] = deflate_strip(data.subspan(begin - primed, primed), strip(i), level, i + 1 == strips);
    checksums[i] = adler32(adler32(0, nullptr, 0), strip(i).data(), uInt(strip(i).size()));
  });
  // Compute the header (deflate, 32 KiB window, level hint), the strips, and the Adler-32 of all.
  const unsigned level_hint = level <= 1 ? 0 : level <= 5 ? 1 : level == 6 ? 2 : 3;
  unsigned header = (0x78u << 8) | (level_hint << 6);
  header += (31 - header % 31) % 31;
  std::string out;
  size_t size = 6;
  for (const std::string& d : deflated) size += d.size();
  out.reserve(size);
  out += char(header >> 8);
  out += char(header & 0xff);
  uLong checksum = checksums[0];
  for (size_t i = 0; i < strips; ++i) {
    out += deflated[i];
    std::string().swap(deflated[i]);  // a large image's strips and stream need not coexist
    if (i > 0) checksum = adler32_combine(checksum, checksums[i], z_off_t(strip(i).size()));
  }
  append_big_endian(out, uint32_t(checksum));
  return out;
}

}  // namespace mjray
