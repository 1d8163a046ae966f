#include "mjray/render/render_checkpoint.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <ios>
#include <string>

#include <xxhash.h>

#include "mjray/core/byte_buffer.h"
#include "mjray/core/error.h"
#include "mjray/core/image.h"
#include "mjray/io/atomic_file.h"

namespace mjray {

namespace {

constexpr char kMagic[8] = {'M', 'J', 'R', 'S', 'T', 'A', 'T', '3'};
/// The header holds the fingerprint, a line per file the scene read: far below this.
constexpr uint64_t kMaxHeaderBytes = uint64_t(64) << 20;
/// The magic and the header's length.
constexpr size_t kPrefixBytes = sizeof kMagic + sizeof(uint64_t);
constexpr size_t kChecksumBytes = sizeof(uint64_t);

uint64_t checksum(std::string_view bytes) { return XXH3_64bits(bytes.data(), bytes.size()); }

/// What the header says: whose state it is, the image's size, and the length of each run of
/// the body, so that the body's size is known before it is read.
struct Header {
  std::string fingerprint;
  int32_t width = 0, height = 0, tile_size = 0, antialias_pass = 0;
  uint64_t tile_done = 0, supersampled = 0, pass_pixels = 0, pass_done = 0;

  uint64_t body_bytes() const {
    return tile_done + supersampled + pass_pixels * sizeof(int32_t) + pass_done +
           uint64_t(width) * uint64_t(height) * sizeof(FilmPixel);
  }
};

/// Checks and decodes a state's parts, from a file or from memory, with one message for
/// what is wrong.
class StateSource {
 public:
  explicit StateSource(std::filesystem::path origin) : origin_(std::move(origin)) {}

  [[noreturn]] void damaged(const std::string& what) const {
    throw SceneError(origin_.string() + ": the resume state file is damaged (" + what +
                     "); it is kept as it is: remove it, or render without --resume");
  }

  /// Checks the prefix (the magic and the header's length); returns the header's length.
  uint64_t header_length(std::string_view prefix, uint64_t total) const {
    if (prefix.size() < kPrefixBytes || std::memcmp(prefix.data(), kMagic, sizeof kMagic) != 0)
      throw SceneError(origin_.string() + ": not an mjray resume state file (remove it, or render without --resume)");
    uint64_t length = 0;
    std::memcpy(&length, prefix.data() + sizeof kMagic, sizeof length);
    if (length > kMaxHeaderBytes || length + kPrefixBytes + 2 * kChecksumBytes > total) damaged("its header is cut short");
    return length;
  }

  /// Checks the header's checksum and values (`bytes` ends with the checksum).
  Header header(std::string_view bytes) const {
    verify(bytes, "header");
    Header h;
    const std::string text(bytes.substr(0, bytes.size() - kChecksumBytes));
    ByteReader r(text, "the resume state's header");
    try {
      h.fingerprint = r.get_string();
      h.width = r.get<int32_t>(), h.height = r.get<int32_t>();
      h.tile_size = r.get<int32_t>(), h.antialias_pass = r.get<int32_t>();
      h.tile_done = r.get<uint64_t>(), h.supersampled = r.get<uint64_t>();
      h.pass_pixels = r.get<uint64_t>(), h.pass_done = r.get<uint64_t>();
    } catch (const TruncatedBytes&) {
      damaged("its header is cut short");
    }
    const uint64_t pixels = uint64_t(std::max(h.width, 0)) * uint64_t(std::max(h.height, 0));
    if (!r.at_end() || h.width <= 0 || h.height <= 0 || pixels > kMaxImagePixels || h.tile_size <= 0 ||
        h.antialias_pass < 0 || h.tile_done > pixels || h.supersampled > pixels || h.pass_pixels > pixels ||
        h.pass_done != h.pass_pixels)
      damaged("its header holds impossible sizes");
    return h;
  }

  /// Checks the body's checksum and decodes it with the header (`bytes` ends with the checksum).
  RenderCheckpoint body(const Header& h, std::string_view bytes) const {
    if (bytes.size() != h.body_bytes() + kChecksumBytes) damaged("its size does not match its header");
    verify(bytes, "pixels and progress");
    RenderCheckpoint c;
    c.fingerprint = h.fingerprint;
    c.tile_size = h.tile_size;
    c.antialias_pass = h.antialias_pass;
    const char* at = bytes.data();
    const auto take = [&](auto& values, uint64_t count) {
      values.resize(count);
      if (count > 0) std::memcpy(values.data(), at, count * sizeof(values[0]));
      at += count * sizeof(values[0]);
    };
    take(c.tile_done, h.tile_done);
    take(c.supersampled, h.supersampled);
    take(c.pass_pixels, h.pass_pixels);
    take(c.pass_done, h.pass_done);
    for (const int32_t p : c.pass_pixels)
      if (p < 0 || int64_t(p) >= int64_t(h.width) * h.height) damaged("a planned pixel lies outside the image");
    c.film = Film(h.width, h.height);
    std::memcpy(c.film.pixels().data(), at, c.film.pixels().size() * sizeof(FilmPixel));
    return c;
  }

 private:
  /// The last 8 bytes of `bytes` are the checksum of the others.
  void verify(std::string_view bytes, const char* part) const {
    uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + bytes.size() - kChecksumBytes, kChecksumBytes);
    if (checksum(bytes.substr(0, bytes.size() - kChecksumBytes)) != stored)
      damaged(std::string("the checksum of its ") + part + " does not match");
  }

  std::filesystem::path origin_;
};

/// Reads exactly `n` bytes from `in` into `out`; false when the file ends first.
bool read_exactly(std::ifstream& in, std::string& out, uint64_t n) {
  out.resize(n);
  in.read(out.data(), std::streamsize(n));
  return uint64_t(in.gcount()) == n;
}

}  // namespace

std::string encode_checkpoint(const RenderCheckpoint& c) {
  ByteWriter header;
  header.put_string(c.fingerprint);
  header.put(int32_t(c.film.width())).put(int32_t(c.film.height())).put(int32_t(c.tile_size)).put(int32_t(c.antialias_pass));
  header.put(uint64_t(c.tile_done.size())).put(uint64_t(c.supersampled.size()));
  header.put(uint64_t(c.pass_pixels.size())).put(uint64_t(c.pass_done.size()));
  const std::string head = header.take();
  ByteWriter body;
  body.put_bytes(c.tile_done.data(), c.tile_done.size()).put_bytes(c.supersampled.data(), c.supersampled.size());
  body.put_bytes(c.pass_pixels.data(), c.pass_pixels.size() * sizeof(int32_t));
  body.put_bytes(c.pass_done.data(), c.pass_done.size());
  body.put_bytes(c.film.pixels().data(), c.film.pixels().size() * sizeof(FilmPixel));
  const std::string rest = body.take();
  ByteWriter out;
  out.put_bytes(kMagic, sizeof kMagic).put(uint64_t(head.size()));
  out.put_bytes(head.data(), head.size()).put(checksum(head));
  out.put_bytes(rest.data(), rest.size()).put(checksum(rest));
  return out.take();
}

void write_checkpoint(const RenderCheckpoint& c, const std::filesystem::path& path) {
  try {
    write_file_atomically(path, encode_checkpoint(c));
  } catch (const OutputError& e) {
    throw OutputError(std::string("the resume state: ") + e.what());
  }
}

RenderCheckpoint decode_checkpoint(const std::string& bytes, const std::filesystem::path& origin) {
  const StateSource source(origin);
  const std::string_view all(bytes);
  const uint64_t length = source.header_length(all, all.size());
  const Header header = source.header(all.substr(kPrefixBytes, length + kChecksumBytes));
  return source.body(header, all.substr(kPrefixBytes + length + kChecksumBytes));
}

RenderCheckpoint read_checkpoint(const std::filesystem::path& path, const FingerprintCheck& check) {
  const StateSource source(path);
  const auto unreadable = [&] {
    return SceneError(path.string() + ": cannot read the resume state file (remove it, or render without --resume)");
  };
  try {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    const uint64_t total = std::filesystem::file_size(path, ec);
    if (!in || ec) throw unreadable();
    // Compute: the header first, checked before anything the size of the image is touched.
    std::string prefix, head, body;
    if (!read_exactly(in, prefix, std::min<uint64_t>(total, kPrefixBytes))) throw unreadable();
    const uint64_t length = source.header_length(prefix, total);
    if (!read_exactly(in, head, length + kChecksumBytes)) throw unreadable();
    const Header header = source.header(head);
    if (total != kPrefixBytes + length + kChecksumBytes + header.body_bytes() + kChecksumBytes)
      source.damaged("its size, " + std::to_string(total) + " bytes, does not match its header");
    if (check) check(header.fingerprint);
    if (!read_exactly(in, body, header.body_bytes() + kChecksumBytes)) throw unreadable();
    return source.body(header, body);
  } catch (const std::ios_base::failure&) {
    // A read error (a folder of that name opens, then fails to read) throws from the stream
    // buffer in libstdc++, where other libraries set badbit.
    throw unreadable();
  }
}

bool is_checkpoint_file(const std::filesystem::path& path) {
  std::error_code ec;
  const uint64_t total = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  std::string prefix, head;
  if (!in || ec || !read_exactly(in, prefix, std::min<uint64_t>(total, kPrefixBytes))) return false;
  try {
    const StateSource source(path);
    const uint64_t length = source.header_length(prefix, total);
    if (!read_exactly(in, head, length + kChecksumBytes)) return false;
    source.header(head);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace mjray
