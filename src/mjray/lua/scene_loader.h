#pragma once
/// Runs a scene script and returns what it describes.

#include <filesystem>

#include "mjray/scene/scene_description.h"
#include "mjray/scene/scene_load_options.h"

namespace mjray {

/// Runs `script` and collects its gr.render calls. Throws SceneError with "file:line: problem"
/// for syntax errors, runtime errors, bad gr.* arguments and sandbox violations, and when the
/// script renders nothing; and for a -D that would replace a global mjray or Lua defines.
SceneDescription load_scene(const std::filesystem::path& script, const SceneLoadOptions& options);

}  // namespace mjray
