#pragma once
/// Turning linear film values into the integers of 8- and 16-bit image files, and back.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "mjray/core/image.h"

namespace mjray {

/// How linear colours become integer values.
enum class OutputGamma {
  kLinear,  ///< values as they are, as CS 488 writes them
  kSrgb,    ///< the sRGB transfer curve (--gamma srgb)
};

/// The sRGB encoding of a linear value in [0, 1].
inline float srgb_encode(float v) { return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f; }

/// The linear value of an sRGB-encoded value in [0, 1].
inline float srgb_decode(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

/// Quantises a linear value to 8 bits: clamp to [0,1], optional sRGB encoding, round to
/// nearest (v·255 + 0.5). NaN becomes 0.
inline uint8_t to_8bit(float linear, OutputGamma gamma) {
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  const float v = gamma == OutputGamma::kSrgb ? srgb_encode(linear) : linear;
  // v > 0, so truncation is floor (and needs no libm call without SSE4.1).
  return uint8_t(std::min(255, int(v * 255.0f + 0.5f)));
}

/// Quantises a linear value to 16 bits, as to_8bit with 65535 steps.
inline uint16_t to_16bit(float linear, OutputGamma gamma) {
  if (!(linear > 0.0f)) return 0;
  if (linear >= 1.0f) return 65535;
  const double v = gamma == OutputGamma::kSrgb ? double(srgb_encode(linear)) : double(linear);
  return uint16_t(std::min(65535.0, std::floor(v * 65535.0 + 0.5)));
}

/// An image of interleaved 8-bit RGB rows (top first), values v/255 (no gamma decoding).
inline Image image_from_rgb8(const uint8_t* rgb, int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint8_t* p = rgb + (size_t(y) * size_t(width) + size_t(x)) * 3;
      image.at(x, y) = Color(float(p[0]) / 255.0f, float(p[1]) / 255.0f, float(p[2]) / 255.0f);
    }
  return image;
}

/// Decodes an image read from an 8-bit sRGB file (values v/255) to linear values, in place.
inline void decode_srgb_8bit(Image& image) {
  float linear[256];
  for (int v = 0; v < 256; ++v) linear[v] = srgb_decode(float(v) / 255.0f);
  const auto decode = [&](float value) { return linear[int(std::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f)]; };
  Color* pixels = image.data();
  for (size_t i = 0; i < image.pixels().size(); ++i) pixels[i] = Color(decode(pixels[i].r), decode(pixels[i].g), decode(pixels[i].b));
}

}  // namespace mjray
