#pragma once
/// Reading images: PNG, binary PPM and JPEG, for image textures, tests and tools.

#include <filesystem>

#include "mjray/core/image.h"

namespace mjray {

/// Reads a PNG (any colour type; 16-bit reduced to 8, alpha dropped), an 8-bit binary PPM or a
/// JPEG, format chosen by the file's magic bytes; throws OutputError("cannot read 'PATH':
/// REASON") on failure. Values are v/255 (no gamma decoding).
Image read_image(const std::filesystem::path& path);

}  // namespace mjray
