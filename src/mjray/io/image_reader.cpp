#include "mjray/io/image_reader.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <memory>
#include <system_error>

#include "mjray/core/error.h"
#include "mjray/io/jpeg_reader.h"
#include "mjray/io/png_codec.h"
#include "mjray/io/ppm_codec.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

/// Largest image read_image accepts, so a corrupt header cannot demand gigabytes.
constexpr size_t kMaxReadPixels = size_t(1) << 28;

struct FileCloser {
  void operator()(FILE* file) const { std::fclose(file); }
};

[[noreturn]] void fail_read(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot read '" + path.string() + "': " + reason);
}

}  // namespace

Image read_image(const fs::path& path) {
  std::unique_ptr<FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail_read(path, std::generic_category().message(errno));
  unsigned char magic[8] = {};
  const size_t got = std::fread(magic, 1, sizeof magic, file.get());
  if (got == sizeof magic && png_sig_cmp(magic, 0, sizeof magic) == 0) return decode_png(path, file.get(), kMaxReadPixels);
  if (got >= 2 && magic[0] == 'P' && magic[1] == '6') return decode_ppm(path, file.get(), kMaxReadPixels);
  if (got >= 3 && magic[0] == 0xFF && magic[1] == 0xD8 && magic[2] == 0xFF) {
    if (std::fseek(file.get(), 0, SEEK_SET) != 0) fail_read(path, std::generic_category().message(errno));
    return read_jpeg(path, file.get(), kMaxReadPixels);
  }
  fail_read(path, "not a PNG, JPEG or binary (P6) PPM file");
}

ImageMetadata read_image_metadata(const fs::path& path) {
  std::unique_ptr<FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail_read(path, std::generic_category().message(errno));
  unsigned char magic[8] = {};
  const size_t got = std::fread(magic, 1, sizeof magic, file.get());
  if (got == sizeof magic && png_sig_cmp(magic, 0, sizeof magic) == 0) return decode_png_text(path, file.get());
  if (got >= 2 && magic[0] == 'P' && magic[1] == '6') return decode_ppm_comments(file.get());
  return {};
}

}  // namespace mjray
