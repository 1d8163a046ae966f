#include "mjray/io/ppm_codec.h"

#include <cctype>
#include <algorithm>
#include <cerrno>
#include <system_error>
#include <vector>

#include "mjray/core/error.h"
#include "mjray/io/image_reader.h"
#include "mjray/io/quantise.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail_read(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot read '" + path.string() + "': " + reason);
}

/// Reads one decimal header field, skipping whitespace and '#' comments before it and
/// consuming the single whitespace character after it.
bool read_field(FILE* file, long& value) {
  int c = std::getc(file);
  while (c == '#' || std::isspace(c)) {
    if (c == '#')
      while (c != '\n' && c != EOF) c = std::getc(file);
    c = std::getc(file);
  }
  if (!std::isdigit(c)) return false;
  value = 0;
  while (std::isdigit(c)) {
    value = value * 10 + (c - '0');
    if (value > 100'000'000) return false;
    c = std::getc(file);
  }
  return c != EOF && std::isspace(c);
}

}  // namespace

std::string encode_ppm(const Image& image, const EncodeOptions& options) {
  std::string out = "P6\n";
  for (const auto& [key, value] : options.metadata) {
    size_t start = 0;
    while (start < value.size()) {
      const size_t end = std::min(value.find('\n', start), value.size());
      out += "# " + key + ": " + value.substr(start, end - start) + "\n";
      start = end + 1;
    }
  }
  out += std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n255\n";
  out.reserve(out.size() + image.pixels().size() * 3);
  for (const Color& c : image.pixels()) {
    out += char(to_8bit(c.r, options.gamma));
    out += char(to_8bit(c.g, options.gamma));
    out += char(to_8bit(c.b, options.gamma));
  }
  return out;
}

ImageMetadata decode_ppm_comments(FILE* file) {
  ImageMetadata text;
  if (std::fseek(file, 2, SEEK_SET) != 0) return text;
  int c = std::getc(file);
  while (c == '#' || std::isspace(c)) {
    if (c == '#') {
      std::string line;
      for (c = std::getc(file); c != '\n' && c != EOF; c = std::getc(file)) line += char(c);
      const size_t colon = line.find(": ");
      if (line.size() > 1 && line[0] == ' ' && colon != std::string::npos) {
        const std::string key = line.substr(1, colon - 1), value = line.substr(colon + 2) + "\n";
        if (!text.empty() && text.back().first == key) text.back().second += value;
        else text.emplace_back(key, value);
      }
    }
    c = std::getc(file);
  }
  return text;
}

Image decode_ppm(const fs::path& path, FILE* file, size_t max_pixels) {
  // Parse "P6 <width> <height> <maxval>" then the raw raster.
  long width = 0, height = 0, maxval = 0;
  if (std::fseek(file, 2, SEEK_SET) != 0 || !read_field(file, width) || !read_field(file, height) ||
      !read_field(file, maxval))
    fail_read(path, "malformed PPM header");
  if (maxval != 255) fail_read(path, "PPM maxval " + std::to_string(maxval) + " is not 8-bit");
  if (width <= 0 || height <= 0) fail_read(path, "bad PPM size " + std::to_string(width) + "x" + std::to_string(height));
  check_image_size(path, uint64_t(width), uint64_t(height), max_pixels);
  const size_t needed = size_t(width) * size_t(height) * 3;
  std::error_code ec;
  const long offset = std::ftell(file);
  const auto size = fs::file_size(path, ec);
  if (!ec && offset >= 0 && size - size_t(offset) < needed)
    fail_read(path, "truncated pixel data (" + std::to_string(size - size_t(offset)) + " of " +
                        std::to_string(needed) + " bytes)");
  std::vector<uint8_t> rgb(needed);
  const size_t got = std::fread(rgb.data(), 1, needed, file);
  if (got != needed) {
    if (std::ferror(file)) fail_read(path, std::generic_category().message(errno));
    fail_read(path, "truncated pixel data (" + std::to_string(got) + " of " + std::to_string(needed) + " bytes)");
  }
  return image_from_rgb8(rgb.data(), int(width), int(height));
}

}  // namespace mjray
