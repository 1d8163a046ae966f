#pragma once
/// JPEG through libjpeg: 8-bit RGB out (a quality option, metadata as comments), any
/// baseline or progressive RGB or greyscale JPEG in.

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// Decodes the JPEG in `file` (open for reading, positioned at its start) to 8-bit RGB
/// (greyscale expands to grey RGB; values are v/255). Throws OutputError("cannot read 'PATH':
/// REASON") for a corrupt or unsupported (e.g. CMYK) file or one of more than `max_pixels`.
Image read_jpeg(const std::filesystem::path& path, FILE* file, size_t max_pixels);

/// The bytes of a JPEG of `image` at options.jpeg_quality, full-resolution colour (4:4:4),
/// quantised as 8-bit PNG is (options.gamma); each options.metadata pair becomes COM markers
/// "name\nvalue" (split across several when longer than one marker holds). Throws OutputError.
std::string encode_jpeg(const Image& image, const EncodeOptions& options);

/// The metadata of the JPEG in `file` (open, at its start), as encode_jpeg writes it; other
/// comments are skipped. Throws OutputError naming `path`.
ImageMetadata read_jpeg_comments(const std::filesystem::path& path, FILE* file);

}  // namespace mjray
