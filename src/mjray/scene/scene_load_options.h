#pragma once
/// How a scene script runs: its sandbox, its limits, the globals it is given. Plain data that
/// the command line fills and lua/ honours.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mjray {

/// Which way node transform calls compose.
enum class TransformOrder {
  kAuto,  ///< post for old-skeleton scripts (they build table-form meshes), else pre
  kPre,   ///< new CS 488 skeleton: each call applies after the earlier ones, M = T·M
  kPost,  ///< old skeleton, OpenGL style: M = M·T
};

/// Default cap on the Lua state's memory (--lua-memory): far above any real scene's needs,
/// below what would push a 24 GiB machine into swap with the render's own buffers.
inline constexpr size_t kDefaultLuaMemoryBytes = size_t(4) << 30;

/// Default limit on how long a script runs (--scene-timeout): far beyond what building any
/// real scene takes, so that a script that never ends cannot keep mjray running for ever.
inline constexpr double kDefaultSceneTimeoutSeconds = 600;

/// How to run the script.
struct SceneLoadOptions {
  bool unsafe_lua = false;  ///< give the script the full standard library and every file
  /// Seeds math.random (--seed), so that a script that draws random numbers describes the same
  /// scene in every run, process and resume.
  uint64_t random_seed = 0;
  /// --allow-read: folders whose trees a sandboxed script may read, beside its own folder's
  /// and the working directory's.
  std::vector<std::filesystem::path> allowed_read_folders;
  TransformOrder transform_order = TransformOrder::kAuto;
  /// Decode 8-bit image textures from sRGB to linear (with --gamma srgb); else use v/255.
  bool srgb_textures = false;
  /// Most bytes the Lua state may hold; past it the allocation fails with a SceneError
  /// naming the line. 0 = no cap.
  size_t lua_memory_bytes = kDefaultLuaMemoryBytes;
  /// Longest the script may run, in seconds (--scene-timeout); 0 = no limit. Checked between
  /// Lua instructions; a script stuck longer than max(2 s, half the timeout) beyond it inside
  /// one library call (e.g. a pathological string pattern) ends the process with exit code 1.
  double timeout_seconds = kDefaultSceneTimeoutSeconds;
  /// Most Lua VM instructions the script may run (deterministic, for tests and fuzzing);
  /// 0 = no limit.
  uint64_t instruction_limit = 0;
  /// -D NAME=VALUE: globals set before the script runs, numbers where Lua reads VALUE as one
  /// ("7", "0.25", "1e3"), else strings. Names must be Lua identifiers that name no global yet.
  std::vector<std::pair<std::string, std::string>> defines;
  /// When set, receives every file the script reads as it reads it (the script itself
  /// excluded), so that a caller knows them also when the script fails (--watch watches them).
  std::vector<std::filesystem::path>* inputs_read = nullptr;
};

}  // namespace mjray
