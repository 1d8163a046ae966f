#include "mjray/render/render_checkpoint.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include <unistd.h>

#include "mjray/core/error.h"

namespace mjray {

namespace {

constexpr char kMagic[8] = {'M', 'J', 'R', 'S', 'T', 'A', 'T', '1'};

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
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
  void bytes(void* out, size_t n) {
    if (n > data_.size() - offset_) throw SceneError(path_.string() + ": the resume state file is truncated");
    std::memcpy(out, data_.data() + offset_, n);
    offset_ += n;
  }
  bool at_end() const { return offset_ == data_.size(); }

 private:
  const std::string& data_;
  const std::filesystem::path& path_;
  size_t offset_ = 0;
};

}  // namespace

void write_checkpoint(const RenderCheckpoint& c, const std::filesystem::path& path) {
  std::string out(kMagic, sizeof kMagic);
  put(out, c.fingerprint);
  put(out, int32_t(c.image.width()));
  put(out, int32_t(c.image.height()));
  put(out, int32_t(c.tile_size));
  put(out, int32_t(c.antialias_pass));
  put(out, uint64_t(c.tile_done.size()));
  out.append(reinterpret_cast<const char*>(c.tile_done.data()), c.tile_done.size());
  put(out, uint64_t(c.supersampled.size()));
  out.append(reinterpret_cast<const char*>(c.supersampled.data()), c.supersampled.size());
  out.append(reinterpret_cast<const char*>(c.image.pixels().data()), c.image.pixels().size() * sizeof(Color));

  const std::string temporary = path.string() + ".tmp-" + std::to_string(::getpid());
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) throw OutputError("cannot write the resume state '" + path.string() + "': " + std::strerror(errno));
  const bool written = std::fwrite(out.data(), 1, out.size(), file) == out.size();
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw OutputError("cannot write the resume state '" + path.string() + "'");
  }
}

RenderCheckpoint read_checkpoint(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path.string() + ": cannot open the resume state file (render without --resume)");
  const std::string data((std::istreambuf_iterator<char>(in)), {});
  Reader r(data, path);
  char magic[sizeof kMagic];
  r.bytes(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) throw SceneError(path.string() + ": not an mjray resume state file");
  RenderCheckpoint c;
  c.fingerprint = r.get<uint64_t>();
  const auto width = r.get<int32_t>(), height = r.get<int32_t>();
  c.tile_size = r.get<int32_t>();
  c.antialias_pass = r.get<int32_t>();
  if (width <= 0 || height <= 0 || width > 65536 || height > 65536 || c.tile_size <= 0 || c.antialias_pass < 0)
    throw SceneError(path.string() + ": the resume state file is corrupt");
  for (std::vector<uint8_t>* flags : {&c.tile_done, &c.supersampled}) {
    const auto count = r.get<uint64_t>();
    if (count > data.size()) throw SceneError(path.string() + ": the resume state file is corrupt");
    flags->resize(count);
    r.bytes(flags->data(), count);
  }
  c.image = Image(width, height);
  r.bytes(c.image.data(), c.image.pixels().size() * sizeof(Color));
  if (!r.at_end()) throw SceneError(path.string() + ": the resume state file is corrupt");
  return c;
}

}  // namespace mjray
