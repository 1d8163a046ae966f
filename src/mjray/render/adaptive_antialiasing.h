#pragma once
/// The original project's adaptive anti-aliasing (report §5.2): after one sample per pixel,
/// "bad" pixels — those that differ from a neighbour by more than a threshold — and their
/// neighbours are supersampled; passes repeat on newly bad pixels, and no pixel is
/// supersampled twice.

#include <cstdint>
#include <vector>

#include "mjray/core/image.h"

namespace mjray {

/// Whether pixel (x, y) differs from any of its 8 neighbours by more than `threshold` in
/// some channel.
bool is_bad_pixel(const Image& image, int x, int y, float threshold);

/// The next pixels to supersample: every bad pixel not yet supersampled, with its 8
/// neighbours that are not yet supersampled either, in row-major order; they are marked in
/// `supersampled` (one flag per pixel, row-major).
std::vector<int> next_supersample_set(const Image& image, float threshold, std::vector<uint8_t>& supersampled);

}  // namespace mjray
