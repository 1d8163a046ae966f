#include "mjray/io/image_codec.h"

#include <cctype>

#include "mjray/core/error.h"
#include "mjray/io/atomic_file.h"
#include "mjray/io/exr_codec.h"
#include "mjray/io/jpeg_codec.h"
#include "mjray/io/png_codec.h"
#include "mjray/io/ppm_codec.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

std::string only_8bit(const EncodeOptions& o) {
  return o.bit_depth == 8 ? std::string() : "PPM stores 8 bits per channel, not " + std::to_string(o.bit_depth);
}
std::string png_depths(const EncodeOptions& o) {
  return o.bit_depth == 8 || o.bit_depth == 16 ? std::string()
                                               : "PNG stores 8 or 16 bits per channel, not " + std::to_string(o.bit_depth);
}
std::string jpeg_options(const EncodeOptions& o) {
  if (o.bit_depth != 8) return "JPEG stores 8 bits per channel, not " + std::to_string(o.bit_depth);
  if (o.jpeg_quality < 1 || o.jpeg_quality > 100) return "JPEG quality must be from 1 to 100, not " + std::to_string(o.jpeg_quality);
  return "";
}
std::string exr_options(const EncodeOptions& o) {
  return o.bit_depth == 8 ? std::string() : "EXR stores half floats; a bit depth of " + std::to_string(o.bit_depth) + " is for PNG";
}

constexpr ImageCodec kCodecs[] = {
    {"PNG", {".png", ""}, png_depths, encode_png},
    {"PPM", {".ppm", ""}, only_8bit, encode_ppm},
    {"JPEG", {".jpg", ".jpeg"}, jpeg_options, encode_jpeg},
    {"OpenEXR", {".exr", ""}, exr_options, encode_exr},
};

[[noreturn]] void fail_write(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot write '" + path.string() + "': " + reason);
}

std::string lower_ascii(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::string writable_extensions() {
  std::string list;
  for (const ImageCodec& codec : kCodecs)
    for (const std::string_view extension : codec.extensions)
      if (!extension.empty()) list += (list.empty() ? "" : ", ") + std::string(extension);
  return list;
}

const ImageCodec& codec_for(const fs::path& path) {
  const std::string extension = lower_ascii(path.extension().string());
  for (const ImageCodec& codec : kCodecs)
    for (const std::string_view known : codec.extensions)
      if (!known.empty() && extension == known) return codec;
  fail_write(path, "unsupported image format '" + path.extension().string() + "' (mjray writes " +
                       writable_extensions() + ")");
}

void check_image_output_format(const fs::path& path, const EncodeOptions& options) {
  const ImageCodec& codec = codec_for(path);
  if (const std::string reason = codec.unsupported(options); !reason.empty()) fail_write(path, reason);
}

void write_image(const Image& image, const fs::path& path, const EncodeOptions& options) {
  // Choose the format before touching the disk.
  const ImageCodec& codec = codec_for(path);
  if (image.width() <= 0 || image.height() <= 0)
    fail_write(path, "image has no pixels (" + std::to_string(image.width()) + "x" + std::to_string(image.height()) + ")");
  std::string bytes;
  try {
    bytes = codec.encode(image, options);
  } catch (const OutputError& e) {
    fail_write(path, e.what());
  }
  write_file_atomically(path, bytes);
}

}  // namespace mjray
