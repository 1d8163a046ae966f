// libFuzzer target: Lua scene text through the sandboxed loader and flatten, under small limits
// (16 MiB of Lua memory, 200 000 Lua instructions, 100 000 flattened primitives). A bad
// script must end in a SceneError; a crash, a sanitizer report, a leak, another exception or a
// hang (libFuzzer's -timeout) is a finding.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "mjray/core/error.h"
#include "mjray/lua/scene_loader.h"
#include "mjray/scene/flatten.h"

namespace {

/// A private folder holding scene.lua (the loader reads files); removed at exit. Never
/// destroyed, so that the exit handler can still use it.
const std::filesystem::path& script_path() {
  static const std::filesystem::path* path = [] {
    std::string folder = (std::filesystem::temp_directory_path() / "mjray-fuzz-scene-XXXXXX").string();
    if (::mkdtemp(folder.data()) == nullptr) std::abort();
    auto* file = new std::filesystem::path(std::filesystem::path(folder) / "scene.lua");
    std::atexit([] { std::filesystem::remove_all(script_path().parent_path()); });
    return file;
  }();
  return *path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& path = script_path();
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0) std::abort();
  mjray::SceneLoadOptions options;
  options.lua_memory_bytes = size_t(16) << 20;
  options.instruction_limit = 200'000;
  options.timeout_seconds = 0;  // the instruction limit bounds the script; libFuzzer's -timeout the rest
  try {
    const mjray::SceneDescription scene = mjray::load_scene(path, options);
    for (const mjray::RenderJob& job : scene.jobs) {
      const mjray::World world = mjray::flatten(job, nullptr, 100'000);
      if (world.primitive_count() > 100'000) std::abort();
    }
  } catch (const mjray::SceneError&) {
  }
  return 0;
}
