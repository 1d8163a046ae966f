#include "mjray/io/image_reader.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <memory>
#include <system_error>

#include "mjray/core/error.h"
#include "mjray/io/exr_codec.h"
#include "mjray/io/jpeg_codec.h"
#include "mjray/io/png_codec.h"
#include "mjray/io/ppm_codec.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

struct FileCloser {
  void operator()(FILE* file) const { std::fclose(file); }
};

[[noreturn]] void fail_read(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot read '" + path.string() + "': " + reason);
}

/// The file, open at its start, and its first bytes.
struct OpenedImage {
  std::unique_ptr<FILE, FileCloser> file;
  unsigned char magic[8] = {};
  size_t got = 0;

  bool is_png() const { return got == sizeof magic && png_sig_cmp(magic, 0, sizeof magic) == 0; }
  bool is_ppm() const { return got >= 2 && magic[0] == 'P' && magic[1] == '6'; }
  bool is_jpeg() const { return got >= 3 && magic[0] == 0xFF && magic[1] == 0xD8 && magic[2] == 0xFF; }
  bool is_exr() const { return has_exr_magic(magic, got); }
};

OpenedImage open_image(const fs::path& path) {
  OpenedImage opened{std::unique_ptr<FILE, FileCloser>(std::fopen(path.c_str(), "rb"))};
  if (!opened.file) fail_read(path, std::generic_category().message(errno));
  opened.got = std::fread(opened.magic, 1, sizeof opened.magic, opened.file.get());
  return opened;
}

void rewind(const fs::path& path, FILE* file) {
  if (std::fseek(file, 0, SEEK_SET) != 0) fail_read(path, std::generic_category().message(errno));
}

}  // namespace

Image read_image(const fs::path& path, const ImageReadOptions& options) {
  OpenedImage opened = open_image(path);
  FILE* file = opened.file.get();
  const size_t most = std::min(options.max_pixels, kMaxReadPixels);
  if (opened.is_png()) return decode_png(path, file, most, options.keep_16_bits);
  if (opened.is_ppm()) return decode_ppm(path, file, most);
  if (opened.is_jpeg()) {
    rewind(path, file);
    return read_jpeg(path, file, most);
  }
  if (opened.is_exr()) return decode_exr(path, most);
  fail_read(path, "not a PNG, JPEG, OpenEXR or binary (P6) PPM file");
}

bool holds_linear_values(const fs::path& path) { return open_image(path).is_exr(); }

ImageMetadata read_image_metadata(const fs::path& path) {
  OpenedImage opened = open_image(path);
  FILE* file = opened.file.get();
  if (opened.is_png()) return decode_png_text(path, file);
  if (opened.is_ppm()) return decode_ppm_comments(file);
  if (opened.is_jpeg()) {
    rewind(path, file);
    return read_jpeg_comments(path, file);
  }
  if (opened.is_exr()) return decode_exr_metadata(path);
  return {};
}

}  // namespace mjray
