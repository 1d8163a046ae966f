#pragma once
/// PNG through libpng: 8- or 16-bit RGB out, any PNG in.

#include <cstdio>
#include <filesystem>
#include <string>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// The bytes of a PNG of `image`: RGB with options.bit_depth (8 or 16) bits per channel,
/// tagged sRGB when encoded so, with options.metadata as text chunks. Throws OutputError.
std::string encode_png(const Image& image, const EncodeOptions& options);

/// Decodes the PNG open in `file` (after its 8 signature bytes): any colour type, alpha
/// dropped; values v/255, or v/65535 for a 16-bit file with `keep_16` (else reduced to 8 bits).
/// Throws OutputError naming `path`.
Image decode_png(const std::filesystem::path& path, FILE* file, size_t max_pixels, bool keep_16 = false);

/// The text chunks before the pixels of the PNG open in `file` (after its signature), as
/// encode_png writes options.metadata. Throws OutputError naming `path`.
ImageMetadata decode_png_text(const std::filesystem::path& path, FILE* file);

}  // namespace mjray
