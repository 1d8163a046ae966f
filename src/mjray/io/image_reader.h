#pragma once
/// Reading images: PNG, binary PPM, JPEG and OpenEXR, for image textures, environments, tests
/// and tools.

#include <filesystem>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// How much of a file's precision read_image keeps.
struct ImageReadOptions {
  bool keep_16_bits = false;  ///< 16-bit PNG as v/65535 instead of reduced to 8 bits
};

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
