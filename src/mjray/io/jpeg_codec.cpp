#include "mjray/io/jpeg_codec.h"

#include <csetjmp>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

// jpeglib.h needs FILE and size_t declared first.
#include <jpeglib.h>
#include <jerror.h>

#include "mjray/core/error.h"
#include "mjray/io/image_reader.h"
#include "mjray/io/quantise.h"

namespace mjray {

namespace {

// libjpeg reports errors by longjmp, which skips C++ destructors: every function that calls
// setjmp holds only plain C state, and buffers are owned by its caller (as for libpng).

/// libjpeg's error manager extended with where to jump and what it said.
struct JpegError {
  jpeg_error_mgr manager;  // first, so that libjpeg's pointer to it is a pointer to this
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void on_jpeg_error(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->message);
  std::longjmp(error->jump, 1);
}

// Corrupt-data warnings still decode an image; keep them off the user's terminal.
void on_jpeg_message(j_common_ptr) {}

/// Most memory libjpeg may take for whole-image buffers (progressive files): a few hundred
/// bytes of file can declare a 65535 x 65535 image.
constexpr long kMaxJpegWorkingMemory = 512L << 20;

/// Data that ends before the image does (at the end of the file or at the next marker) is an
/// error, not a grey image: otherwise a few hundred bytes with a large declared size decode
/// to gigabytes of filler.
void on_jpeg_emit(j_common_ptr info, int level) {
  const int code = info->err->msg_code;
  if (level < 0 && (code == JWRN_JPEG_EOF || code == JWRN_HIT_MARKER)) on_jpeg_error(info);
  if (level < 0) ++info->err->num_warnings;
}

/// A libjpeg decompression session; destroyed by its owner, outside any setjmp frame.
struct JpegReader {
  jpeg_decompress_struct info{};
  JpegError error{};
  bool created = false;

  ~JpegReader() {
    if (created) jpeg_destroy_decompress(&info);
  }
};

/// Creates the session and reads the header (keeping the COM markers when asked), asking for
/// RGB output.
bool read_jpeg_header(JpegReader& r, FILE* file, bool keep_comments = false) {
  r.info.err = jpeg_std_error(&r.error.manager);
  r.error.manager.error_exit = on_jpeg_error;
  r.error.manager.output_message = on_jpeg_message;
  r.error.manager.emit_message = on_jpeg_emit;
  if (setjmp(r.error.jump)) return false;
  jpeg_create_decompress(&r.info);
  r.created = true;
  r.info.mem->max_memory_to_use = kMaxJpegWorkingMemory;
  jpeg_stdio_src(&r.info, file);
  if (keep_comments) jpeg_save_markers(&r.info, JPEG_COM, 0xFFFF);
  jpeg_read_header(&r.info, TRUE);
  r.info.out_color_space = JCS_RGB;
  return true;
}

/// Decodes every scanline into `rgb`, which the caller sized from the header's dimensions.
bool read_jpeg_rows(JpegReader& r, unsigned char* rgb, size_t width, size_t height) {
  if (setjmp(r.error.jump)) return false;
  jpeg_start_decompress(&r.info);
  if (r.info.output_components != 3 || r.info.output_width != width || r.info.output_height != height) {
    std::snprintf(r.error.message, sizeof r.error.message, "unsupported pixel layout");
    return false;
  }
  while (r.info.output_scanline < r.info.output_height) {
    JSAMPROW row = rgb + size_t(r.info.output_scanline) * width * 3;
    jpeg_read_scanlines(&r.info, &row, 1);
  }
  jpeg_finish_decompress(&r.info);
  return true;
}

/// A libjpeg compression session into memory; destroyed by its owner, outside any setjmp frame.
struct JpegWriter {
  jpeg_compress_struct info{};
  JpegError error{};
  bool created = false;
  unsigned char* bytes = nullptr;  // malloc'd by libjpeg
  unsigned long size = 0;

  ~JpegWriter() {
    if (created) jpeg_destroy_compress(&info);
    std::free(bytes);
  }
};

/// What one encode needs, prepared outside the setjmp frame.
struct JpegEncodeJob {
  const unsigned char* rgb;  ///< interleaved 8-bit rows, top first
  int width, height, quality;
  const std::vector<std::string>* comments;
};

bool write_jpeg(JpegWriter& w, const JpegEncodeJob& job) {
  w.info.err = jpeg_std_error(&w.error.manager);
  w.error.manager.error_exit = on_jpeg_error;
  w.error.manager.output_message = on_jpeg_message;
  if (setjmp(w.error.jump)) return false;
  jpeg_create_compress(&w.info);
  w.created = true;
  jpeg_mem_dest(&w.info, &w.bytes, &w.size);
  w.info.image_width = JDIMENSION(job.width);
  w.info.image_height = JDIMENSION(job.height);
  w.info.input_components = 3;
  w.info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&w.info);
  jpeg_set_quality(&w.info, job.quality, TRUE);
  // Full-resolution colour: renders have sharp coloured edges that 4:2:0 smears.
  for (int c = 0; c < w.info.num_components; ++c) w.info.comp_info[c].h_samp_factor = w.info.comp_info[c].v_samp_factor = 1;
  jpeg_start_compress(&w.info, TRUE);
  for (const std::string& comment : *job.comments)
    jpeg_write_marker(&w.info, JPEG_COM, reinterpret_cast<const JOCTET*>(comment.data()), unsigned(comment.size()));
  while (w.info.next_scanline < w.info.image_height) {
    JSAMPROW row = const_cast<unsigned char*>(job.rgb) + size_t(w.info.next_scanline) * size_t(job.width) * 3;
    jpeg_write_scanlines(&w.info, &row, 1);
  }
  jpeg_finish_compress(&w.info);
  return true;
}

/// Most bytes of one COM marker (its length field counts itself).
constexpr size_t kMaxCommentBytes = 65533;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& reason) {
  throw OutputError("cannot read '" + path.string() + "': " + reason);
}

}  // namespace

Image read_jpeg(const std::filesystem::path& path, FILE* file, size_t max_pixels) {
  JpegReader r;
  if (!read_jpeg_header(r, file)) fail(path, std::string("libjpeg: ") + r.error.message);
  const size_t width = r.info.image_width, height = r.info.image_height;
  if (width == 0 || height == 0) fail(path, "bad JPEG size " + std::to_string(width) + "x" + std::to_string(height));
  check_image_size(path, width, height, max_pixels);
  // Left uninitialised: only rows the decoder reaches are touched, so a truncated file with a
  // large declared size fails before it costs memory.
  const std::unique_ptr<unsigned char[]> rgb(new unsigned char[width * height * 3]);
  if (!read_jpeg_rows(r, rgb.get(), width, height)) fail(path, std::string("libjpeg: ") + r.error.message);
  Image image{int(width), int(height)};
  for (size_t i = 0; i < width * height; ++i)
    image.at(int(i % width), int(i / width)) =
        Color(float(rgb[3 * i]) / 255.0f, float(rgb[3 * i + 1]) / 255.0f, float(rgb[3 * i + 2]) / 255.0f);
  return image;
}

std::string encode_jpeg(const Image& image, const EncodeOptions& options) {
  if (options.jpeg_quality < 1 || options.jpeg_quality > 100)
    throw OutputError("JPEG quality must be from 1 to 100, not " + std::to_string(options.jpeg_quality));
  std::vector<unsigned char> rgb;
  rgb.reserve(image.pixels().size() * 3);
  for (const Color& c : image.pixels())
    for (const float v : {c.r, c.g, c.b}) rgb.push_back(to_8bit(v, options.gamma));
  // Each pair as "name\nvalue", in pieces that fit a marker; read_jpeg_comments joins them.
  std::vector<std::string> comments;
  for (const auto& [key, value] : options.metadata) {
    const size_t room = kMaxCommentBytes - key.size() - 1;
    size_t start = 0;
    do {
      comments.push_back(key + "\n" + value.substr(start, room));
      start += room;
    } while (start < value.size());
  }
  JpegWriter w;
  if (!write_jpeg(w, {rgb.data(), image.width(), image.height(), options.jpeg_quality, &comments}))
    throw OutputError(std::string("libjpeg: ") + w.error.message);
  return std::string(reinterpret_cast<const char*>(w.bytes), w.size);
}

ImageMetadata read_jpeg_comments(const std::filesystem::path& path, FILE* file) {
  JpegReader r;
  if (!read_jpeg_header(r, file, true)) fail(path, std::string("libjpeg: ") + r.error.message);
  ImageMetadata text;
  for (jpeg_saved_marker_ptr m = r.info.marker_list; m != nullptr; m = m->next) {
    const std::string comment(reinterpret_cast<const char*>(m->data), m->data_length);
    const size_t newline = comment.find('\n');
    if (m->marker != JPEG_COM || newline == std::string::npos) continue;
    const std::string key = comment.substr(0, newline), value = comment.substr(newline + 1);
    if (!text.empty() && text.back().first == key) text.back().second += value;
    else text.emplace_back(key, value);
  }
  return text;
}

}  // namespace mjray
