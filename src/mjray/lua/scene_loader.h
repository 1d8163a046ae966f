#pragma once
/// Runs a scene script and returns what it describes.

#include <filesystem>

#include "mjray/scene/scene_description.h"

namespace mjray {

/// Which way node transform calls compose.
enum class TransformOrder {
  kAuto,  ///< post for old-skeleton scripts (they build table-form meshes), else pre
  kPre,   ///< new CS 488 skeleton: each call applies after the earlier ones, M = T·M
  kPost,  ///< old skeleton, OpenGL style: M = M·T
};

/// How to run the script.
struct SceneLoadOptions {
  bool unsafe_lua = false;  ///< give the script the full standard library
  TransformOrder transform_order = TransformOrder::kAuto;
};

/// Runs `script` and collects its gr.render calls. Throws SceneError with "file:line: problem"
/// for syntax errors, runtime errors, bad gr.* arguments and sandbox violations, and when the
/// script renders nothing.
SceneDescription load_scene(const std::filesystem::path& script, const SceneLoadOptions& options);

}  // namespace mjray
