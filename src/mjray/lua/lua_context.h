#pragma once
/// State shared by the Lua bindings while one script runs (internal to lua/).

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

extern "C" {
#include <lua.h>
}

#include "mjray/lua/scene_loader.h"
#include "mjray/scene/scene_description.h"

namespace mjray::lua {

/// A node as the script builds it: mutable until a gr.render call snapshots it.
struct LuaNode {
  std::string name;
  FileLocation where;
  NodeShape shape = NodeShape::kNone;
  Transform node_from_object;
  std::shared_ptr<const ObjMesh> mesh;
  std::shared_ptr<Material> material;
  std::vector<Transform> transform_calls;  ///< in call order
  std::vector<std::shared_ptr<LuaNode>> children;

  LuaNode() = default;
  LuaNode(const LuaNode&) = delete;
  LuaNode& operator=(const LuaNode&) = delete;
  /// Frees a long chain of sole-owned children iteratively: a script can build one deeper
  /// than the C++ stack.
  ~LuaNode();
};

/// Everything the bindings need to know about the running script.
struct LoaderContext {
  std::filesystem::path script;
  std::filesystem::path script_dir;
  SceneLoadOptions options;
  bool saw_table_mesh = false;  ///< decides the automatic transform order
  SceneDescription* description = nullptr;
  std::map<std::filesystem::path, std::shared_ptr<const ObjMesh>> mesh_cache;
  std::vector<std::weak_ptr<LuaNode>> nodes;  ///< every node made, to break cycles at the end

  LoaderContext() = default;
  LoaderContext(const LoaderContext&) = delete;
  LoaderContext& operator=(const LoaderContext&) = delete;
  /// Empties the child lists of nodes still alive, so that a script's cycles do not leak.
  ~LoaderContext();
};

/// The context of the script running in L.
LoaderContext& context(lua_State* L);
/// Stores the context pointer in L's registry.
void set_context(lua_State* L, LoaderContext* ctx);

/// Defines the `gr` table and the userdata types.
void register_gr(lua_State* L);
/// Adds the original project's extensions (materials, area lights, extended meshes) to `gr`.
void register_extensions(lua_State* L);
/// Adds the textures (gr.*texture) to `gr` and set_material_texture to materials; needs
/// register_gr first.
void register_textures(lua_State* L);
/// Adds what CS 488 scripts of both course generations expect: unpack, string.gfind,
/// the scene folder on the require path, and a built-in readobj module.
void install_compatibility(lua_State* L);
/// Replaces every standard function that could run programs, write files, load native code
/// or read outside the scene's folders with one that refuses, naming itself.
void install_sandbox(lua_State* L);
/// Wraps io.open/io.lines/io.input/dofile/loadfile so relative names resolve like every other
/// scene path (writes, os.remove and os.rename: beside the script), and forces loadfile to text.
void install_path_resolution(lua_State* L);

/// "file:line" of the Lua code that called the running C function.
FileLocation caller_location(lua_State* L);

/// "cannot find 'name' (looked in ...)": the message for a relative input found nowhere.
std::string not_found_message(const std::string& name);

/// A C function that reports C++ exceptions as Lua errors at the caller's line (the
/// exception is gone before lua_error unwinds, so no C++ destructor is skipped). F itself must
/// report problems by throwing: a luaL_error/luaL_check* inside F would longjmp over F's
/// C++ locals.
template <int (*F)(lua_State*)>
int guarded(lua_State* L) {
  try {
    return F(L);
  } catch (const std::exception& e) {
    lua_pushstring(L, (caller_location(L).to_string() + ": " + e.what()).c_str());
  }
  return lua_error(L);
}

/// Thrown by bindings for a bad argument; `guarded` prefixes the caller's location.
class ArgumentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mjray::lua
