#pragma once
/// What an interrupted render saves so that --resume finishes it to the same image.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "mjray/core/image.h"

namespace mjray {

/// The state of a render between units of work: finished tiles of the first pass, or the
/// image and supersampled set at the start of an anti-aliasing pass.
struct RenderCheckpoint {
  uint64_t fingerprint = 0;           ///< hash of the scene and every option that shapes the image
  int tile_size = 0;
  int antialias_pass = 0;             ///< 0: first pass; k ≥ 1: about to run anti-aliasing pass k
  std::vector<uint8_t> tile_done;     ///< first pass: one flag per tile, row-major
  std::vector<uint8_t> supersampled;  ///< one flag per pixel
  Image image;                        ///< pixels of finished tiles (first pass) or the whole image
};

/// Writes a checkpoint atomically (temporary file + rename). Throws OutputError.
void write_checkpoint(const RenderCheckpoint& checkpoint, const std::filesystem::path& path);

/// Reads a checkpoint; throws SceneError naming the file when it is unreadable or malformed.
RenderCheckpoint read_checkpoint(const std::filesystem::path& path);

/// The state file that belongs to an output image.
inline std::filesystem::path checkpoint_path(const std::filesystem::path& image) {
  return image.string() + ".mjray-state";
}

}  // namespace mjray
