#pragma once
/// Reading images: PNG, binary PPM and JPEG, for image textures, tests and tools.

#include <filesystem>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// Reads a PNG (any colour type; 16-bit reduced to 8, alpha dropped), an 8-bit binary PPM or a
/// JPEG, format chosen by the file's magic bytes; throws OutputError("cannot read 'PATH':
/// REASON") on failure. Values are v/255 (no gamma decoding).
Image read_image(const std::filesystem::path& path);

/// The text a PNG or PPM keeps (EncodeOptions::metadata as written); none for other files.
/// Throws OutputError when the file cannot be read.
ImageMetadata read_image_metadata(const std::filesystem::path& path);

}  // namespace mjray
