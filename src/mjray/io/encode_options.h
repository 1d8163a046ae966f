#pragma once
/// What decides how an image is encoded, whatever the format.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mjray/io/quantise.h"

namespace mjray {

/// Text an image file keeps: (name, value) pairs.
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

/// How to encode an image file.
struct EncodeOptions {
  OutputGamma gamma = OutputGamma::kLinear;  ///< integer formats only
  int bit_depth = 8;                         ///< bits per channel where the format offers a choice
  int jpeg_quality = 90;                     ///< JPEG only: 1 (smallest) to 100 (best)
  /// Threads that may share the work (PNG's compression); the bytes never depend on it.
  int threads = 1;
  /// Seconds the render took, for formats whose header has a place for it (EXR). Integer
  /// formats leave it out, so that the same render always gives the same bytes.
  std::optional<double> render_seconds{};
  /// Text the file keeps where its format has room for it (name, value), e.g. the options.
  /// PNG: tEXt chunks; PPM: header comments "# name: line", one per line of the value; JPEG:
  /// COM markers "name\nvalue"; EXR: string attributes.
  ImageMetadata metadata{};
};

}  // namespace mjray
