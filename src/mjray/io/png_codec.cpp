#include "mjray/io/png_codec.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <system_error>
#include <vector>

#include "mjray/core/error.h"
#include "mjray/io/quantise.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

/// zlib level for PNG output: renders rewrite the image often, so speed beats a few percent.
constexpr int kCompressionLevel = 3;

/// Every row filtered by its left neighbour: on the corpus's renders this is a third faster
/// than libpng's per-row choice among all five filters, and the files are 3 % smaller.
constexpr int kRowFilter = PNG_FILTER_SUB;

// libpng reports errors by longjmp, which skips C++ destructors: every function that calls
// setjmp holds only plain C state, and buffers are owned by its caller.

/// What the libpng callbacks share with their caller.
struct PngIo {
  FILE* file = nullptr;        ///< reading
  std::string* out = nullptr;  ///< writing
  int io_errno = 0;            ///< errno of a failed fread; 0 when libpng itself complained
  char message[256] = {};      ///< libpng's error text
};

void on_error(png_structp png, png_const_charp message) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  std::snprintf(io->message, sizeof io->message, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void on_write(png_structp png, png_bytep data, size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  io->out->append(reinterpret_cast<const char*>(data), length);
}

void on_flush(png_structp) {}

void on_read(png_structp png, png_bytep data, size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, io->file) != length) {
    if (std::ferror(io->file)) {
      io->io_errno = errno;
      png_error(png, "read failed");
    }
    png_error(png, "file is truncated");
  }
}

std::string failure(const PngIo& io) {
  if (io.io_errno != 0) return std::generic_category().message(io.io_errno);
  return std::string("libpng: ") + io.message;
}

/// What one encode needs, prepared outside the setjmp frame.
struct EncodeJob {
  const uint8_t* rows;  ///< big-endian samples, rows top to bottom
  int width, height, bit_depth;
  bool srgb;
  std::vector<png_text> text;
};

bool encode(PngIo& io, const EncodeJob& job) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &io, on_error, on_warning);
  if (png == nullptr) {
    std::snprintf(io.message, sizeof io.message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(io.message, sizeof io.message, "out of memory");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, &io, on_write, on_flush);
  png_set_compression_level(png, kCompressionLevel);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, kRowFilter);
  png_set_IHDR(png, info, png_uint_32(job.width), png_uint_32(job.height), job.bit_depth, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Tag sRGB-encoded output; linear output carries no colour chunk (viewers assume sRGB).
  if (job.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (!job.text.empty()) png_set_text(png, info, job.text.data(), int(job.text.size()));
  png_write_info(png, info);
  const size_t stride = size_t(job.width) * 3 * size_t(job.bit_depth / 8);
  for (int y = 0; y < job.height; ++y) png_write_row(png, job.rows + size_t(y) * stride);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

/// A libpng read session; destroyed by its owner, outside any setjmp frame.
struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngIo io;

  ~PngReader() {
    if (png != nullptr) png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr);
  }
};

/// Reads the header (after the 8 signature bytes) and asks libpng for RGB rows of 8 bits, or
/// of 16 (big-endian) for a 16-bit file when `keep_16`; `bit_depth` says which.
bool read_header(PngReader& r, png_uint_32& width, png_uint_32& height, bool keep_16, int& bit_depth) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_set_read_fn(r.png, &r.io, on_read);
  png_set_sig_bytes(r.png, 8);
  png_read_info(r.png, r.info);
  png_set_expand(r.png);
  if (!keep_16) png_set_strip_16(r.png);
  png_set_strip_alpha(r.png);
  png_set_gray_to_rgb(r.png);
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  width = png_get_image_width(r.png, r.info);
  height = png_get_image_height(r.png, r.info);
  bit_depth = png_get_bit_depth(r.png, r.info);
  if (png_get_channels(r.png, r.info) != 3 || (bit_depth != 8 && bit_depth != 16))
    png_error(r.png, "unsupported pixel layout");
  return true;
}

bool read_rows(PngReader& r, png_bytepp rows) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_image(r.png, rows);
  png_read_end(r.png, nullptr);
  return true;
}

[[noreturn]] void fail_read(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot read '" + path.string() + "': " + reason);
}

}  // namespace

std::string encode_png(const Image& image, const EncodeOptions& options) {
  if (options.bit_depth != 8 && options.bit_depth != 16)
    throw OutputError("PNG stores 8 or 16 bits per channel, not " + std::to_string(options.bit_depth));
  // Compute the samples: bytes for 8 bits, big-endian pairs for 16.
  const std::vector<Color>& pixels = image.pixels();
  const size_t bytes_per_sample = size_t(options.bit_depth / 8);
  std::vector<uint8_t> samples(pixels.size() * 3 * bytes_per_sample);
  uint8_t* next = samples.data();
  if (options.bit_depth == 8) {
    for (const Color& c : pixels) {
      *next++ = to_8bit(c.r, options.gamma);
      *next++ = to_8bit(c.g, options.gamma);
      *next++ = to_8bit(c.b, options.gamma);
    }
  } else {
    for (const Color& c : pixels)
      for (const float v : {c.r, c.g, c.b}) {
        const uint16_t q = to_16bit(v, options.gamma);
        *next++ = uint8_t(q >> 8);
        *next++ = uint8_t(q & 0xff);
      }
  }
  EncodeJob job{samples.data(), image.width(), image.height(), options.bit_depth,
                options.gamma == OutputGamma::kSrgb, {}};
  for (const auto& [key, value] : options.metadata) {
    png_text t{};
    t.compression = PNG_TEXT_COMPRESSION_NONE;
    t.key = const_cast<char*>(key.c_str());
    t.text = const_cast<char*>(value.c_str());
    t.text_length = value.size();
    job.text.push_back(t);
  }
  std::string out;
  PngIo io;
  io.out = &out;
  if (!encode(io, job)) throw OutputError(failure(io));
  return out;
}

Image decode_png(const fs::path& path, FILE* file, size_t max_pixels, bool keep_16) {
  PngReader r;
  r.io.file = file;
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.io, on_error, on_warning);
  if (r.png != nullptr) r.info = png_create_info_struct(r.png);
  if (r.png == nullptr || r.info == nullptr) fail_read(path, "out of memory");
  png_uint_32 width = 0, height = 0;
  int bit_depth = 8;
  if (!read_header(r, width, height, keep_16, bit_depth)) fail_read(path, failure(r.io));
  if (size_t(width) * size_t(height) > max_pixels)
    fail_read(path, "image too large (" + std::to_string(width) + "x" + std::to_string(height) + ")");
  // Compute the least data such an image needs: one bit per pixel and a filter byte per row,
  // deflated at most 1032:1. A smaller file is truncated, and must not cost gigabytes first.
  std::error_code ec;
  const auto file_size = fs::file_size(path, ec);
  const size_t least_raw = size_t(height) + size_t(width) * size_t(height) / 8;
  if (!ec && least_raw / 1032 > file_size + 1024)
    fail_read(path, "file is truncated (" + std::to_string(file_size) + " bytes cannot hold a " +
                        std::to_string(width) + "x" + std::to_string(height) + " image)");
  const size_t stride = size_t(width) * 3 * size_t(bit_depth / 8);
  std::vector<uint8_t> rgb(stride * height);
  std::vector<png_bytep> rows(height);
  for (size_t y = 0; y < height; ++y) rows[y] = rgb.data() + y * stride;
  if (!read_rows(r, rows.data())) fail_read(path, failure(r.io));
  if (bit_depth == 8) return image_from_rgb8(rgb.data(), int(width), int(height));
  Image image{int(width), int(height)};
  const auto sample = [&](size_t i) { return float((unsigned(rgb[2 * i]) << 8) | rgb[2 * i + 1]) / 65535.0f; };
  for (size_t i = 0; i < size_t(width) * height; ++i) image.data()[i] = Color(sample(3 * i), sample(3 * i + 1), sample(3 * i + 2));
  return image;
}

namespace {

bool read_text(PngReader& r, ImageMetadata& text) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_set_read_fn(r.png, &r.io, on_read);
  png_set_sig_bytes(r.png, 8);
  png_read_info(r.png, r.info);
  png_textp chunks = nullptr;
  const int count = png_get_text(r.png, r.info, &chunks, nullptr);
  for (int i = 0; i < count; ++i) text.emplace_back(chunks[i].key, std::string(chunks[i].text, chunks[i].text_length));
  return true;
}

}  // namespace

ImageMetadata decode_png_text(const fs::path& path, FILE* file) {
  PngReader r;
  r.io.file = file;
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.io, on_error, on_warning);
  if (r.png != nullptr) r.info = png_create_info_struct(r.png);
  if (r.png == nullptr || r.info == nullptr) fail_read(path, "out of memory");
  ImageMetadata text;
  if (!read_text(r, text)) fail_read(path, failure(r.io));
  return text;
}

}  // namespace mjray
