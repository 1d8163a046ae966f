#pragma once
/// JPEG decoding through libjpeg, behind read_image.

#include <cstddef>
#include <cstdio>
#include <filesystem>

#include "mjray/core/image.h"

namespace mjray {

/// Decodes the JPEG in `file` (open for reading, positioned at its start) to 8-bit RGB
/// (greyscale expands to grey RGB; values are v/255). Throws OutputError("cannot read 'PATH':
/// REASON") for a corrupt or unsupported (e.g. CMYK) file or one of more than `max_pixels`.
Image read_jpeg(const std::filesystem::path& path, FILE* file, size_t max_pixels);

}  // namespace mjray
