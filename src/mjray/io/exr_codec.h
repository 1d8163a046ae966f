#pragma once
/// OpenEXR: linear half-float RGB out, RGB or luminance EXR (half, float or integer) in.

#include <cstddef>
#include <filesystem>
#include <string>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// Whether `bytes` (at least 4) start like an OpenEXR file.
bool has_exr_magic(const unsigned char* bytes, size_t size);

/// The bytes of a ZIP-compressed EXR of `image`: R, G, B as half floats, the film's linear
/// values unclamped and without gamma (beyond 65504 they become infinite, as half floats do).
/// The header keeps options.metadata as string attributes, options.render_seconds as the
/// float "renderSeconds", and the capture date ("capDate", local time). Throws OutputError.
std::string encode_exr(const Image& image, const EncodeOptions& options);

/// Decodes an EXR file: R, G, B (a missing one reads 0), or Y as grey; linear values as
/// stored. Throws OutputError("cannot read 'PATH': REASON"), also for more than `max_pixels`.
Image decode_exr(const std::filesystem::path& path, size_t max_pixels);

/// The string attributes of an EXR file's header (as encode_exr writes options.metadata).
/// Throws OutputError.
ImageMetadata decode_exr_metadata(const std::filesystem::path& path);

}  // namespace mjray
