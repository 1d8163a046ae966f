#include "mjray/lua/scene_loader.h"

#include <memory>
#include <string>
#include <vector>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}

#include "mjray/lua/lua_context.h"

namespace mjray {

namespace lua {

namespace {
constexpr const char* kContextKey = "mjray.context";
}

LoaderContext& context(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kContextKey);
  auto* ctx = static_cast<LoaderContext*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  MJRAY_CHECK(ctx != nullptr);
  return *ctx;
}

void set_context(lua_State* L, LoaderContext* ctx) {
  lua_pushlightuserdata(L, ctx);
  lua_setfield(L, LUA_REGISTRYINDEX, kContextKey);
}

FileLocation caller_location(lua_State* L) {
  // Level 1 is the running C function's caller; skip C frames (e.g. pcall) to the Lua line.
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline > 0) {
      const char* source = ar.source;
      std::string file = (source && source[0] == '@') ? source + 1 : ar.short_src;
      return {file, ar.currentline};
    }
  }
  return {context(L).script.string(), 0};
}

std::string not_found_message(const std::string& name) {
  return "cannot find '" + name +
         "' (looked in the scene's folder, its parent folders, their Assets/ folders and the working directory)";
}

LuaNode::~LuaNode() {
  std::vector<std::shared_ptr<LuaNode>> pending = std::move(children);
  while (!pending.empty()) {
    std::shared_ptr<LuaNode> node = std::move(pending.back());
    pending.pop_back();
    // Sole owner: take its children so that destroying it recurses no further.
    if (node.use_count() == 1) {
      for (auto& child : node->children) pending.push_back(std::move(child));
      node->children.clear();
    }
  }
}

LoaderContext::~LoaderContext() {
  for (const auto& weak : nodes) {
    if (auto node = weak.lock()) {
      auto children = std::move(node->children);
      node->children.clear();
    }
  }
}

namespace {

/// lua_pcall message handler: string messages already carry "file:line:" (from Lua or
/// `guarded`); any other error value is described at the line that raised it.
int describe_error_value(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING) return 1;
  const int type = lua_type(L, 1);
  const std::string what = type == LUA_TNIL ? std::string("nil") : std::string("a ") + lua_typename(L, type);
  const std::string message =
      caller_location(L).to_string() + ": the script raised an error value that is not a string (" + what + ")";
  lua_pushstring(L, message.c_str());
  return 1;
}

}  // namespace

}  // namespace lua

SceneDescription load_scene(const std::filesystem::path& script, const SceneLoadOptions& options) {
  SceneDescription description;
  description.script = script;
  lua::LoaderContext ctx;
  ctx.script = script;
  ctx.script_dir = std::filesystem::absolute(script).parent_path();
  ctx.options = options;
  ctx.description = &description;

  std::unique_ptr<lua_State, decltype(&lua_close)> state(luaL_newstate(), &lua_close);
  if (!state) throw SceneError("cannot create a Lua state (out of memory)");
  lua_State* L = state.get();
  luaL_openlibs(L);
  lua::set_context(L, &ctx);
  // The sandbox goes last: it rebuilds package.searchers from what compatibility installed.
  lua::install_compatibility(L);
  lua::install_path_resolution(L);
  if (!options.unsafe_lua) lua::install_sandbox(L);
  lua::register_gr(L);
  lua::register_extensions(L);

  std::error_code ec;
  if (!std::filesystem::exists(script, ec))
    throw SceneError(script.string() + ": cannot open the scene file (no such file)");
  if (!std::filesystem::is_regular_file(script, ec))
    throw SceneError(script.string() + ": cannot open the scene file (not a regular file)");

  // Compute: load and run the chunk; errors arrive as "file:line: message" strings.
  lua_pushcfunction(L, lua::describe_error_value);
  if (luaL_loadfilex(L, script.c_str(), "t") != LUA_OK || lua_pcall(L, 0, 0, 1) != LUA_OK) {
    const char* message = lua_tostring(L, -1);
    throw SceneError(message ? message : script.string() + ": the script raised an error that is not a string");
  }
  if (description.jobs.empty()) throw SceneError(script.string() + ": the scene never calls gr.render");
  return description;
}

}  // namespace mjray
