#include "mjray/io/image_writer.h"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "mjray/core/error.h"
#include "mjray/io/jpeg_reader.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

/// zlib level for PNG output: renders rewrite the image often, so speed beats a few percent.
constexpr int kPngCompressionLevel = 3;
/// Largest image read_image accepts, so a corrupt header cannot demand gigabytes.
constexpr size_t kMaxReadPixels = size_t(1) << 28;

enum class ImageFormat { kPng, kPpm };

[[noreturn]] void fail_write(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot write '" + path.string() + "': " + reason);
}

[[noreturn]] void fail_read(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot read '" + path.string() + "': " + reason);
}

std::string errno_text(int err) { return std::generic_category().message(err); }

std::string lower_ascii(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

/// Interleaved 8-bit RGB, rows top to bottom, as both PNG and PPM store them.
std::vector<uint8_t> quantise(const Image& image, OutputGamma gamma) {
  std::vector<uint8_t> rgb(size_t(image.width()) * size_t(image.height()) * 3);
  size_t i = 0;
  for (const Color& c : image.pixels()) {
    rgb[i++] = to_8bit(c.r, gamma);
    rgb[i++] = to_8bit(c.g, gamma);
    rgb[i++] = to_8bit(c.b, gamma);
  }
  return rgb;
}

// --- libpng glue ----------------------------------------------------------------------------
// libpng reports errors by longjmp, which skips C++ destructors: every function that calls
// setjmp holds only plain C state, and buffers are owned by its caller.

/// What the libpng callbacks share with their caller.
struct PngIo {
  FILE* file = nullptr;
  int io_errno = 0;          ///< errno of a failed fwrite/fread; 0 when libpng itself complained
  char message[256] = {};    ///< libpng's error text
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* io = static_cast<PngIo*>(png_get_error_ptr(png));
  std::snprintf(io->message, sizeof io->message, "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

void on_png_write(png_structp png, png_bytep data, size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, length, io->file) != length) {
    io->io_errno = errno;
    png_error(png, "write failed");
  }
}

// The caller flushes and fsyncs once, after the last byte.
void on_png_flush(png_structp) {}

void on_png_read(png_structp png, png_bytep data, size_t length) {
  auto* io = static_cast<PngIo*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, io->file) != length) {
    if (std::ferror(io->file)) {
      io->io_errno = errno;
      png_error(png, "read failed");
    }
    png_error(png, "file is truncated");
  }
}

std::string png_failure(const PngIo& io) {
  if (io.io_errno != 0) return errno_text(io.io_errno);
  return std::string("libpng: ") + io.message;
}

/// Encodes interleaved 8-bit RGB as a PNG into io.file; false (io says why) on failure.
bool encode_png(PngIo& io, const uint8_t* rgb, int width, int height, OutputGamma gamma) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &io, on_png_error,
                                            on_png_warning);
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
  png_set_write_fn(png, &io, on_png_write, on_png_flush);
  png_set_compression_level(png, kPngCompressionLevel);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Tag sRGB-encoded output; linear output carries no colour chunk (viewers assume sRGB).
  if (gamma == OutputGamma::kSrgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  const size_t stride = size_t(width) * 3;
  for (int y = 0; y < height; ++y) png_write_row(png, rgb + size_t(y) * stride);
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

/// Reads the header (after the 8 signature bytes) and asks libpng for 8-bit RGB rows.
bool read_png_header(PngReader& r, png_uint_32& width, png_uint_32& height) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_set_read_fn(r.png, &r.io, on_png_read);
  png_set_sig_bytes(r.png, 8);
  png_read_info(r.png, r.info);
  png_set_expand(r.png);
  png_set_strip_16(r.png);
  png_set_strip_alpha(r.png);
  png_set_gray_to_rgb(r.png);
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  width = png_get_image_width(r.png, r.info);
  height = png_get_image_height(r.png, r.info);
  if (png_get_channels(r.png, r.info) != 3 || png_get_bit_depth(r.png, r.info) != 8)
    png_error(r.png, "unsupported pixel layout");
  return true;
}

bool read_png_rows(PngReader& r, png_bytepp rows) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_image(r.png, rows);
  png_read_end(r.png, nullptr);
  return true;
}

// --- file plumbing --------------------------------------------------------------------------

struct FileCloser {
  void operator()(FILE* file) const { std::fclose(file); }
};
using FilePtr = std::unique_ptr<FILE, FileCloser>;

/// The temporary sibling of an output file: removed unless committed over the target.
class TempFile {
 public:
  explicit TempFile(fs::path path) : path_(std::move(path)) {
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
      open_errno_ = errno;
      return;
    }
    file_ = ::fdopen(fd, "wb");
    if (file_ == nullptr) {
      open_errno_ = errno;
      ::close(fd);
      discard();
    }
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (file_ != nullptr) std::fclose(file_);
    if (!committed_ && open_errno_ == 0) discard();
  }

  FILE* file() const { return file_; }
  int open_errno() const { return open_errno_; }

  /// Flushes, fsyncs, closes and renames over `target`; returns the reason on failure.
  std::string commit(const fs::path& target) {
    const std::string name = "'" + path_.filename().string() + "'";
    if (std::fflush(file_) != 0) return "writing " + name + " failed: " + errno_text(errno);
    if (::fsync(::fileno(file_)) != 0) return "syncing " + name + " failed: " + errno_text(errno);
    FILE* file = file_;
    file_ = nullptr;
    if (std::fclose(file) != 0) return "closing " + name + " failed: " + errno_text(errno);
    if (std::rename(path_.c_str(), target.c_str()) != 0)
      return "cannot replace it with " + name + ": " + errno_text(errno);
    committed_ = true;
    sync_folder();
    return {};
  }

 private:
  void discard() {
    std::error_code ignored;
    fs::remove(path_, ignored);
  }

  // Makes the rename durable. Best effort: the new file is already in place, and some
  // filesystems refuse fsync on folders.
  void sync_folder() const {
    const fs::path folder = path_.has_parent_path() ? path_.parent_path() : fs::path(".");
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)::fsync(fd);
    ::close(fd);
  }

  fs::path path_;
  FILE* file_ = nullptr;
  int open_errno_ = 0;
  bool committed_ = false;
};

std::string create_failure(const fs::path& tmp, int err) {
  const fs::path folder = tmp.has_parent_path() ? tmp.parent_path() : fs::path(".");
  std::error_code ec;
  if (err == ENOENT && !fs::exists(folder, ec))
    return "folder '" + folder.string() + "' does not exist";
  return "cannot create temporary file '" + tmp.filename().string() + "': " + errno_text(err);
}

/// Reads one decimal header field of a PPM, skipping whitespace and '#' comments before it and
/// consuming the single whitespace character after it.
bool read_ppm_field(FILE* file, long& value) {
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

Image image_from_rgb(const uint8_t* rgb, int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = rgb + (size_t(y) * size_t(width) + size_t(x)) * 3;
      image.at(x, y) = Color(float(p[0]) / 255.0f, float(p[1]) / 255.0f, float(p[2]) / 255.0f);
    }
  }
  return image;
}

Image read_ppm(const fs::path& path, FILE* file) {
  // Parse "P6 <width> <height> <maxval>" then the raw raster.
  long width = 0, height = 0, maxval = 0;
  if (std::fseek(file, 2, SEEK_SET) != 0 || !read_ppm_field(file, width) ||
      !read_ppm_field(file, height) || !read_ppm_field(file, maxval))
    fail_read(path, "malformed PPM header");
  if (maxval != 255) fail_read(path, "PPM maxval " + std::to_string(maxval) + " is not 8-bit");
  if (width <= 0 || height <= 0 || size_t(width) * size_t(height) > kMaxReadPixels)
    fail_read(path, "bad PPM size " + std::to_string(width) + "x" + std::to_string(height));
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
    if (std::ferror(file)) fail_read(path, errno_text(errno));
    fail_read(path, "truncated pixel data (" + std::to_string(got) + " of " +
                        std::to_string(needed) + " bytes)");
  }
  return image_from_rgb(rgb.data(), int(width), int(height));
}

Image read_png(const fs::path& path, FILE* file) {
  PngReader r;
  r.io.file = file;
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r.io, on_png_error, on_png_warning);
  if (r.png != nullptr) r.info = png_create_info_struct(r.png);
  if (r.png == nullptr || r.info == nullptr) fail_read(path, "out of memory");
  png_uint_32 width = 0, height = 0;
  if (!read_png_header(r, width, height)) fail_read(path, png_failure(r.io));
  if (size_t(width) * size_t(height) > kMaxReadPixels)
    fail_read(path, "image too large (" + std::to_string(width) + "x" + std::to_string(height) +
                        ")");
  // Compute the least data such an image needs: one bit per pixel and a filter byte per row,
  // deflated at most 1032:1. A smaller file is truncated, and must not cost gigabytes first.
  std::error_code ec;
  const auto file_size = fs::file_size(path, ec);
  const size_t least_raw = size_t(height) + size_t(width) * size_t(height) / 8;
  if (!ec && least_raw / 1032 > file_size + 1024)
    fail_read(path, "file is truncated (" + std::to_string(file_size) + " bytes cannot hold a " +
                        std::to_string(width) + "x" + std::to_string(height) + " image)");
  const size_t stride = size_t(width) * 3;
  std::vector<uint8_t> rgb(stride * height);
  std::vector<png_bytep> rows(height);
  for (size_t y = 0; y < height; ++y) rows[y] = rgb.data() + y * stride;
  if (!read_png_rows(r, rows.data())) fail_read(path, png_failure(r.io));
  return image_from_rgb(rgb.data(), int(width), int(height));
}

}  // namespace

uint8_t to_8bit(float linear, OutputGamma gamma) {
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  float v = linear;
  if (gamma == OutputGamma::kSrgb)
    v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::min(255.0f, std::floor(v * 255.0f + 0.5f)));
}

void write_image(const Image& image, const fs::path& path, OutputGamma gamma) {
  // Choose the format before touching the disk.
  const std::string extension = path.extension().string();
  const std::string lowered = lower_ascii(extension);
  ImageFormat format;
  if (lowered == ".png") {
    format = ImageFormat::kPng;
  } else if (lowered == ".ppm") {
    format = ImageFormat::kPpm;
  } else {
    fail_write(path, "unsupported image format '" + extension + "' (use .png or .ppm)");
  }
  if (image.width() <= 0 || image.height() <= 0)
    fail_write(path, "image has no pixels (" + std::to_string(image.width()) + "x" +
                         std::to_string(image.height()) + ")");
  const std::vector<uint8_t> rgb = quantise(image, gamma);

  // Encode into the temporary sibling, then move it over the target.
  fs::path tmp_path = path;
  tmp_path += ".tmp-" + std::to_string(::getpid());
  TempFile tmp(tmp_path);
  if (tmp.file() == nullptr) fail_write(path, create_failure(tmp_path, tmp.open_errno()));
  if (format == ImageFormat::kPpm) {
    const std::string header = "P6\n" + std::to_string(image.width()) + " " +
                               std::to_string(image.height()) + "\n255\n";
    if (std::fwrite(header.data(), 1, header.size(), tmp.file()) != header.size() ||
        std::fwrite(rgb.data(), 1, rgb.size(), tmp.file()) != rgb.size())
      fail_write(path, errno_text(errno));
  } else {
    PngIo io;
    io.file = tmp.file();
    if (!encode_png(io, rgb.data(), image.width(), image.height(), gamma))
      fail_write(path, png_failure(io));
  }
  if (const std::string reason = tmp.commit(path); !reason.empty()) fail_write(path, reason);
}

Image read_image(const fs::path& path) {
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) fail_read(path, errno_text(errno));
  unsigned char magic[8] = {};
  const size_t got = std::fread(magic, 1, sizeof magic, file.get());
  if (got == sizeof magic && png_sig_cmp(magic, 0, sizeof magic) == 0)
    return read_png(path, file.get());
  if (got >= 2 && magic[0] == 'P' && magic[1] == '6') return read_ppm(path, file.get());
  if (got >= 3 && magic[0] == 0xFF && magic[1] == 0xD8 && magic[2] == 0xFF) {
    if (std::fseek(file.get(), 0, SEEK_SET) != 0) fail_read(path, errno_text(errno));
    return read_jpeg(path, file.get(), kMaxReadPixels);
  }
  fail_read(path, "not a PNG, JPEG or binary (P6) PPM file");
}

}  // namespace mjray
