#pragma once
/// Image output (8-bit PNG and binary PPM), written atomically, and reading those files (and
/// JPEG, for textures) back.

#include <cstdint>
#include <filesystem>

#include "mjray/core/image.h"

namespace mjray {

/// How linear colours become 8-bit values.
enum class OutputGamma { kLinear, kSrgb };

/// Quantises a linear value to 8 bits: clamp to [0,1], optional sRGB encoding, round to nearest
/// (v*255+0.5). NaN becomes 0.
uint8_t to_8bit(float linear, OutputGamma gamma);

/// Writes the image to `path`, format chosen by extension (.png 8-bit RGB, .ppm binary P6
/// 8-bit); case-insensitive extension. Atomic: writes "<path>.tmp-<pid>" in the same folder,
/// fsyncs, then renames over `path`, so a reader never sees a torn file and a failed write keeps
/// the previous file intact. Throws OutputError("cannot write 'PATH': REASON") on any failure
/// (unknown extension, missing or unwritable folder, disk full), removing the temporary file.
void write_image(const Image& image, const std::filesystem::path& path,
                 OutputGamma gamma = OutputGamma::kLinear);

/// Reads a PNG (any colour type; 16-bit reduced to 8, alpha dropped), an 8-bit binary PPM or a
/// JPEG (for tests, resume and image textures), format chosen by the file's magic bytes;
/// throws OutputError("cannot read 'PATH': REASON") on failure. Values are v/255 (no gamma
/// decoding).
Image read_image(const std::filesystem::path& path);

}  // namespace mjray
