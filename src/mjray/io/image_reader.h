#pragma once
/// Reading images: PNG, binary PPM, JPEG and OpenEXR, for image textures, environments, tests
/// and tools.

#include <cstdint>
#include <filesystem>
#include <string>

#include "mjray/core/error.h"
#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// Largest image read_image accepts unless told less, so that a corrupt header cannot demand
/// gigabytes.
inline constexpr size_t kMaxReadPixels = size_t(1) << 28;

/// How much of a file's precision read_image keeps, and how large an image it may read.
struct ImageReadOptions {
  bool keep_16_bits = false;  ///< 16-bit PNG as v/65535 instead of reduced to 8 bits
  size_t max_pixels = kMaxReadPixels;
};

/// Thrown by read_image for a file that declares more pixels than it may read (before any of
/// them is decoded).
struct ImageTooLarge : OutputError {
  ImageTooLarge(const std::filesystem::path& path, uint64_t image_width, uint64_t image_height)
      : OutputError("cannot read '" + path.string() + "': image too large (" + std::to_string(image_width) + "x" +
                    std::to_string(image_height) + ")"),
        width(image_width), height(image_height) {}
  uint64_t width, height;
};

/// Throws ImageTooLarge when a width × height image has more than `max_pixels` pixels; what
/// every decoder calls once it knows the size.
inline void check_image_size(const std::filesystem::path& path, uint64_t width, uint64_t height, size_t max_pixels) {
  if (width * height > max_pixels) throw ImageTooLarge(path, width, height);
}

/// Reads a PNG (any colour type; 16-bit reduced to 8 unless asked, alpha dropped), an 8-bit
/// binary PPM, a JPEG or an OpenEXR file, format chosen by the file's magic bytes; throws
/// OutputError("cannot read 'PATH': REASON") on failure. Integer values are v/255 (v/65535)
/// with no gamma decoding; EXR values are linear, as stored.
Image read_image(const std::filesystem::path& path, const ImageReadOptions& options = {});

/// Whether the file is an OpenEXR file, whose values are linear (no sRGB decoding applies).
bool holds_linear_values(const std::filesystem::path& path);

/// The text a PNG, PPM, JPEG or EXR keeps (EncodeOptions::metadata as written); none for
/// other files. Throws OutputError when the file cannot be read.
ImageMetadata read_image_metadata(const std::filesystem::path& path);

}  // namespace mjray
