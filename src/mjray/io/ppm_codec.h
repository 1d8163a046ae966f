#pragma once
/// Binary PPM (P6): 8-bit RGB with a text header.

#include <cstdio>
#include <filesystem>
#include <string>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// The bytes of an 8-bit binary PPM of `image`; options.metadata become header comments.
std::string encode_ppm(const Image& image, const EncodeOptions& options);

/// Decodes the P6 file open in `file` (the magic already seen); throws OutputError naming
/// `path`. Values are v/255; images over `max_pixels` are refused.
Image decode_ppm(const std::filesystem::path& path, FILE* file, size_t max_pixels);

/// The "# name: line" header comments of the P6 file open in `file`, lines of one name joined
/// (each ending in a newline).
ImageMetadata decode_ppm_comments(FILE* file);

}  // namespace mjray
