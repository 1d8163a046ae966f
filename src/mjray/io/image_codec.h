#pragma once
/// The image formats mjray writes, one codec each, chosen by the file's extension.
///
/// To add a format: write `<name>_codec.h/.cpp` with an encoder (image + options → bytes),
/// add a row to the table in image_codec.cpp, and test it in tests/unit/io/.

#include <array>
#include <filesystem>
#include <string>
#include <string_view>

#include "mjray/core/image.h"
#include "mjray/io/encode_options.h"

namespace mjray {

/// One image file format.
struct ImageCodec {
  std::string_view name;                       ///< e.g. "PNG"
  std::array<std::string_view, 2> extensions;  ///< lower case, with the dot; unused slots empty
  /// Why `options` do not suit the format (e.g. a bit depth it lacks), or nothing.
  std::string (*unsupported)(const EncodeOptions& options);
  /// The file's bytes. Throws OutputError.
  std::string (*encode)(const Image& image, const EncodeOptions& options);
};

/// The codec for `path`'s extension (case-insensitive). Throws OutputError("cannot write
/// 'PATH': …") naming the formats mjray writes when there is none.
const ImageCodec& codec_for(const std::filesystem::path& path);

/// The extensions mjray writes, for messages: ".png, .ppm, .jpg, .jpeg, .exr".
std::string writable_extensions();

/// Checks that `path` has a known extension whose format takes `options`. Throws OutputError
/// naming the path.
void check_image_output_format(const std::filesystem::path& path, const EncodeOptions& options);

/// Encodes the image with its path's codec and writes it atomically (see
/// write_file_atomically). Throws OutputError("cannot write 'PATH': REASON").
void write_image(const Image& image, const std::filesystem::path& path, const EncodeOptions& options = {});

}  // namespace mjray
