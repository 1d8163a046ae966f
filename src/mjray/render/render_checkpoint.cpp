#include "mjray/render/render_checkpoint.h"

#include <cstring>
#include <fstream>
#include <ios>
#include <string>

#include "mjray/core/byte_buffer.h"
#include "mjray/core/error.h"
#include "mjray/io/atomic_file.h"

namespace mjray {

namespace {

constexpr char kMagic[8] = {'M', 'J', 'R', 'S', 'T', 'A', 'T', '2'};

}  // namespace

std::string encode_checkpoint(const RenderCheckpoint& c) {
  ByteWriter out;
  out.put_bytes(kMagic, sizeof kMagic).put_string(c.fingerprint);
  out.put(int32_t(c.film.width())).put(int32_t(c.film.height())).put(int32_t(c.tile_size)).put(int32_t(c.antialias_pass));
  out.put_vector(c.tile_done).put_vector(c.supersampled).put_vector(c.pass_pixels).put_vector(c.pass_done);
  out.put_bytes(c.film.pixels().data(), c.film.pixels().size() * sizeof(FilmPixel));
  return out.take();
}

void write_checkpoint(const RenderCheckpoint& c, const std::filesystem::path& path) {
  try {
    write_file_atomically(path, encode_checkpoint(c));
  } catch (const OutputError& e) {
    throw OutputError(std::string("the resume state: ") + e.what());
  }
}

RenderCheckpoint read_checkpoint(const std::filesystem::path& path) {
  const auto unreadable = [&] {
    return SceneError(path.string() + ": cannot read the resume state file (remove it, or render without --resume)");
  };
  std::string data;
  try {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw unreadable();
    data.assign(std::istreambuf_iterator<char>(in), {});
    if (in.bad()) throw unreadable();
  } catch (const std::ios_base::failure&) {
    // A read error (a folder of that name opens, then fails to read) throws from the stream
    // buffer in libstdc++, where other libraries set badbit.
    throw unreadable();
  }
  return decode_checkpoint(data, path);
}

RenderCheckpoint decode_checkpoint(const std::string& data, const std::filesystem::path& path) {
  const auto corrupt = [&] { return SceneError(path.string() + ": the resume state file is corrupt"); };
  ByteReader r(data, "the resume state file");
  RenderCheckpoint c;
  try {
    char magic[sizeof kMagic];
    r.get_bytes(magic, sizeof magic);
    if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw SceneError(path.string() + ": not an mjray resume state file");
    c.fingerprint = r.get_string();
    const auto width = r.get<int32_t>(), height = r.get<int32_t>();
    c.tile_size = r.get<int32_t>();
    c.antialias_pass = r.get<int32_t>();
    if (width <= 0 || height <= 0 || width > 65536 || height > 65536 || c.tile_size <= 0 || c.antialias_pass < 0)
      throw corrupt();
    c.tile_done = r.get_vector<uint8_t>();
    c.supersampled = r.get_vector<uint8_t>();
    c.pass_pixels = r.get_vector<int32_t>();
    c.pass_done = r.get_vector<uint8_t>();
    if (c.pass_done.size() != c.pass_pixels.size()) throw corrupt();
    for (const int32_t p : c.pass_pixels)
      if (p < 0 || int64_t(p) >= int64_t(width) * height) throw corrupt();
    c.film = Film(width, height);
    r.get_bytes(c.film.pixels().data(), c.film.pixels().size() * sizeof(FilmPixel));
  } catch (const TruncatedBytes& e) {
    throw SceneError(path.string() + ": " + e.what());
  }
  if (!r.at_end()) throw corrupt();
  return c;
}

}  // namespace mjray
