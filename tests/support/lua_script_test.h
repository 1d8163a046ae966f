#pragma once
/// A fixture for tests that run scene scripts: write "scene.lua" into a scratch folder, load
/// it, and read the error it raises.

#include <string>

#include "mjray/lua/scene_loader.h"
#include "support/scratch_files.h"

namespace mjray::test {

class LuaScriptTest : public ScratchFolderTest {
 protected:
  /// Loads `script` written as dir_/scene.lua. Scripts get a minute unless the options say
  /// otherwise, so that a test never hangs on one.
  SceneDescription load(const std::string& script, const SceneLoadOptions& options = {}) {
    SceneLoadOptions limited = options;
    if (limited.timeout_seconds == 0) limited.timeout_seconds = 60;
    return load_scene(write("scene.lua", script), limited);
  }

  /// The message load_scene throws for `script`, or "(no error)".
  std::string error_of(const std::string& script, const SceneLoadOptions& options = {}) {
    try {
      load(script, options);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "(no error)";
  }

  /// "<dir>/scene.lua:LINE: ", the prefix of an error raised on that line.
  std::string at(int line) const { return (dir_ / "scene.lua").string() + ":" + std::to_string(line) + ": "; }
};

}  // namespace mjray::test
