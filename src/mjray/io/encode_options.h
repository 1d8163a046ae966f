#pragma once
/// What decides how an image is encoded, whatever the format.

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
  /// Text the file keeps where its format has room for it (name, value), e.g. the options.
  /// PNG: tEXt chunks; PPM: header comments "# name: line", one per line of the value.
  ImageMetadata metadata;
};

}  // namespace mjray
