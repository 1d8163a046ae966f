#pragma once
/// What an interrupted render saves so that --resume finishes it to the same image.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "mjray/render/film.h"

namespace mjray {

/// The state of a render between units of work: the film with everything finished, which
/// first-pass tiles are done, and how far adaptive anti-aliasing got.
struct RenderCheckpoint {
  std::string fingerprint;            ///< what shaped the image: the scene, its files, the options (job_fingerprint)
  int tile_size = 0;
  int antialias_pass = 0;             ///< 0: first pass; k ≥ 1: in anti-aliasing pass k
  std::vector<uint8_t> tile_done;     ///< one flag per tile, row-major
  std::vector<uint8_t> supersampled;  ///< one flag per pixel: planned by an anti-aliasing pass so far
  std::vector<int32_t> pass_pixels;   ///< the plan of pass `antialias_pass` (empty: not planned yet)
  std::vector<uint8_t> pass_done;     ///< one flag per planned pixel: finished
  Film film;
};

/// Writes a checkpoint atomically (temporary file + rename). Throws OutputError.
void write_checkpoint(const RenderCheckpoint& checkpoint, const std::filesystem::path& path);

/// Reads a checkpoint; throws SceneError naming the file when it is unreadable or malformed.
RenderCheckpoint read_checkpoint(const std::filesystem::path& path);

/// The bytes of a state file (to write, or to send to another process).
std::string encode_checkpoint(const RenderCheckpoint& checkpoint);

/// Decodes the bytes of a state file; throws SceneError naming `origin` when they are malformed.
RenderCheckpoint decode_checkpoint(const std::string& bytes, const std::filesystem::path& origin);

/// The state file that belongs to an output image.
inline std::filesystem::path checkpoint_path(const std::filesystem::path& image) {
  return image.string() + ".mjray-state";
}

}  // namespace mjray
