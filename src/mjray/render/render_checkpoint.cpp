#include "mjray/render/render_checkpoint.h"

#include <cstring>
#include <fstream>
#include <string>

#include "mjray/core/error.h"
#include "mjray/io/atomic_file.h"

namespace mjray {

namespace {

constexpr char kMagic[8] = {'M', 'J', 'R', 'S', 'T', 'A', 'T', '2'};

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
void put_vector(std::string& out, const std::vector<T>& values) {
  put(out, uint64_t(values.size()));
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

/// Reads from a byte buffer, failing cleanly at the end instead of reading past it.
class Reader {
 public:
  Reader(const std::string& data, const std::filesystem::path& path) : data_(data), path_(path) {}
  template <class T>
  T get() {
    T value;
    bytes(&value, sizeof value);
    return value;
  }
  template <class T>
  std::vector<T> get_vector() {
    const auto count = get<uint64_t>();
    if (count > (data_.size() - offset_) / sizeof(T)) corrupt();
    std::vector<T> values(count);
    bytes(values.data(), count * sizeof(T));
    return values;
  }
  void bytes(void* out, size_t n) {
    if (n > data_.size() - offset_) throw SceneError(path_.string() + ": the resume state file is truncated");
    if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not see
    std::memcpy(out, data_.data() + offset_, n);
    offset_ += n;
  }
  bool at_end() const { return offset_ == data_.size(); }
  [[noreturn]] void corrupt() const { throw SceneError(path_.string() + ": the resume state file is corrupt"); }

 private:
  const std::string& data_;
  const std::filesystem::path& path_;
  size_t offset_ = 0;
};

}  // namespace

std::string encode_checkpoint(const RenderCheckpoint& c) {
  std::string out(kMagic, sizeof kMagic);
  put(out, uint64_t(c.fingerprint.size()));
  out += c.fingerprint;
  put(out, int32_t(c.film.width()));
  put(out, int32_t(c.film.height()));
  put(out, int32_t(c.tile_size));
  put(out, int32_t(c.antialias_pass));
  put_vector(out, c.tile_done);
  put_vector(out, c.supersampled);
  put_vector(out, c.pass_pixels);
  put_vector(out, c.pass_done);
  out.append(reinterpret_cast<const char*>(c.film.pixels().data()), c.film.pixels().size() * sizeof(FilmPixel));
  return out;
}

void write_checkpoint(const RenderCheckpoint& c, const std::filesystem::path& path) {
  try {
    write_file_atomically(path, encode_checkpoint(c));
  } catch (const OutputError& e) {
    throw OutputError(std::string("the resume state: ") + e.what());
  }
}

RenderCheckpoint read_checkpoint(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path.string() + ": cannot open the resume state file (render without --resume)");
  return decode_checkpoint(std::string((std::istreambuf_iterator<char>(in)), {}), path);
}

RenderCheckpoint decode_checkpoint(const std::string& data, const std::filesystem::path& path) {
  Reader r(data, path);
  char magic[sizeof kMagic];
  r.bytes(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw SceneError(path.string() + ": not an mjray resume state file");
  RenderCheckpoint c;
  const std::vector<char> fingerprint = r.get_vector<char>();
  c.fingerprint.assign(fingerprint.begin(), fingerprint.end());
  const auto width = r.get<int32_t>(), height = r.get<int32_t>();
  c.tile_size = r.get<int32_t>();
  c.antialias_pass = r.get<int32_t>();
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536 || c.tile_size <= 0 || c.antialias_pass < 0)
    r.corrupt();
  c.tile_done = r.get_vector<uint8_t>();
  c.supersampled = r.get_vector<uint8_t>();
  c.pass_pixels = r.get_vector<int32_t>();
  c.pass_done = r.get_vector<uint8_t>();
  if (c.pass_done.size() != c.pass_pixels.size()) r.corrupt();
  for (const int32_t p : c.pass_pixels)
    if (p < 0 || int64_t(p) >= int64_t(width) * height) r.corrupt();
  c.film = Film(width, height);
  r.bytes(c.film.pixels().data(), c.film.pixels().size() * sizeof(FilmPixel));
  if (!r.at_end()) r.corrupt();
  return c;
}

}  // namespace mjray
