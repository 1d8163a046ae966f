#pragma once
/// What an interrupted render saves so that --resume finishes it to the same image.

#include <cstdint>
#include <filesystem>
#include <functional>
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

/// Called with a state's fingerprint once its header has passed its checks and before the rest
/// is read, so that a state of another job is refused without reading it; throws to refuse.
using FingerprintCheck = std::function<void(const std::string& fingerprint)>;

/// Reads a checkpoint; throws SceneError naming the file when it is unreadable, damaged (a
/// checksum or a size does not match) or not a state file. Its size is checked against what
/// its header says before anything of that size is read or allocated.
RenderCheckpoint read_checkpoint(const std::filesystem::path& path, const FingerprintCheck& check = {});

/// Whether `path` is a resume state file of mjray's (its header intact), not someone's file
/// that happens to have the name.
bool is_checkpoint_file(const std::filesystem::path& path);

/// The bytes of a state file (to write, or to send to another process): a header (what the
/// state belongs to, the image size, the counts of what follows) and a body (the flags and the
/// film), each followed by its XXH3 checksum.
std::string encode_checkpoint(const RenderCheckpoint& checkpoint);

/// Decodes the bytes of a state file; throws SceneError naming `origin` when they are damaged.
RenderCheckpoint decode_checkpoint(const std::string& bytes, const std::filesystem::path& origin);

/// The state file that belongs to an output image.
inline std::filesystem::path checkpoint_path(const std::filesystem::path& image) {
  return image.string() + ".mjray-state";
}

}  // namespace mjray
