#include "mjray/lua/scene_loader.h"

#include <memory>

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
  if (!options.unsafe_lua) lua::install_sandbox(L);
  lua::install_compatibility(L);
  lua::install_path_resolution(L);
  lua::register_gr(L);

  // Compute: load and run the chunk; errors arrive as "file:line: message" strings.
  std::string error;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(script, ec)) throw SceneError(script.string() + ": cannot open the scene file");
  if (luaL_loadfilex(L, script.c_str(), "t") != LUA_OK || lua_pcall(L, 0, 0, 0) != LUA_OK) {
    const char* message = lua_tostring(L, -1);
    error = message ? message : "error object is not a string";
  }
  if (!error.empty()) throw SceneError(error);
  if (description.jobs.empty()) throw SceneError(script.string() + ": the scene never calls gr.render");
  return description;
}

}  // namespace mjray
