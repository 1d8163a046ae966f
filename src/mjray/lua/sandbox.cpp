// The Lua environment a scene script runs in: CS 488 compatibility shims, path resolution,
// and (by default) a sandbox that keeps a stranger's script from touching the system.

#include <cstring>
#include <string>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

#include "mjray/io/obj_loader.h"
#include "mjray/io/path_resolver.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

constexpr const char* kUnsafeHint = "scene scripts run sandboxed; run mjray with --unsafe-lua to allow it";

// --- helpers -------------------------------------------------------------------------------

/// Folders a sandboxed script may read: its own folder tree and the Assets/ folder of each
/// folder above it (where CS 488 skeletons keep meshes).
std::vector<std::filesystem::path> read_roots(const std::filesystem::path& script_dir) {
  std::vector<std::filesystem::path> roots;
  std::filesystem::path dir = std::filesystem::weakly_canonical(script_dir);
  roots.push_back(dir);
  while (true) {
    roots.push_back(dir / "Assets");
    const auto parent = dir.parent_path();
    if (parent == dir) break;
    dir = parent;
  }
  return roots;
}

bool is_within(const std::filesystem::path& path, const std::filesystem::path& root) {
  auto p = path.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++p) {
    if (p == path.end() || *p != *r) return false;
  }
  return true;
}

bool may_read(const LoaderContext& ctx, const std::filesystem::path& path) {
  const auto canonical = std::filesystem::weakly_canonical(path);
  for (const auto& root : read_roots(ctx.script_dir))
    if (is_within(canonical, root)) return true;
  return false;
}

/// A relative name resolved like every scene path; names that exist nowhere resolve into the
/// script's folder (so error messages and new files name a sensible place).
std::filesystem::path resolve_script_path(const LoaderContext& ctx, const std::string& name) {
  if (auto found = resolve_input(name, ctx.script_dir)) return *found;
  const std::filesystem::path path(name);
  return path.is_absolute() ? path : ctx.script_dir / path;
}

/// Checks that a sandboxed script may read `name`; returns the resolved path.
std::string checked_read_path(lua_State* L, const char* fn, const std::string& name) {
  const LoaderContext& ctx = context(L);
  const auto path = resolve_script_path(ctx, name);
  if (!ctx.options.unsafe_lua && !may_read(ctx, path))
    throw ArgumentError(std::string(fn) + ": '" + name + "' is outside the scene's folders (" + kUnsafeHint + ")");
  return path.string();
}

// --- refusing functions --------------------------------------------------------------------

int refuse(lua_State* L) {
  return luaL_error(L, "%s is not allowed: %s", lua_tostring(L, lua_upvalueindex(1)), kUnsafeHint);
}

void replace_with_refusal(lua_State* L, const char* table, const char* field) {
  lua_getglobal(L, table);
  if (!lua_istable(L, -1)) {
    lua_pop(L, 1);
    return;
  }
  lua_pushfstring(L, "%s.%s", table, field);
  lua_pushcclosure(L, refuse, 1);
  lua_setfield(L, -2, field);
  lua_pop(L, 1);
}

// --- wrappers around io.open / io.lines / io.input / dofile / loadfile / load --------------
// Each keeps the original function as upvalue 1 and calls it with a checked path.

int call_original(lua_State* L) {
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

int open_checked(lua_State* L) {
  const std::string name = luaL_checkstring(L, 1);
  const char* mode = luaL_optstring(L, 2, "r");
  const bool writes = std::strpbrk(mode, "wa+") != nullptr;
  if (writes && !context(L).options.unsafe_lua)
    throw ArgumentError(std::string("io.open for writing ('") + mode + "') is not allowed: " + kUnsafeHint);
  const std::string path = writes ? resolve_script_path(context(L), name).string()
                                  : checked_read_path(L, "io.open", name);
  lua_pushstring(L, path.c_str());
  lua_replace(L, 1);
  return 0;
}

int io_open(lua_State* L) {
  guarded<open_checked>(L);
  return call_original(L);
}

template <const char* kName>
int path_checked(lua_State* L) {
  if (lua_type(L, 1) != LUA_TSTRING) {
    if (lua_isnoneornil(L, 1) && !context(L).options.unsafe_lua && std::strcmp(kName, "io.lines") != 0)
      throw ArgumentError(std::string(kName) + " without a file name reads standard input, which is not allowed: " + kUnsafeHint);
    return 0;
  }
  const std::string path = checked_read_path(L, kName, lua_tostring(L, 1));
  lua_pushstring(L, path.c_str());
  lua_replace(L, 1);
  return 0;
}

constexpr char kIoLines[] = "io.lines";
constexpr char kIoInput[] = "io.input";
constexpr char kDofile[] = "dofile";
constexpr char kLoadfile[] = "loadfile";

template <const char* kName>
int path_wrapper(lua_State* L) {
  guarded<path_checked<kName>>(L);
  return call_original(L);
}

int loadfile_text_only(lua_State* L) {
  guarded<path_checked<kLoadfile>>(L);
  lua_settop(L, std::max(lua_gettop(L), 3));
  lua_pushstring(L, "t");  // binary chunks can crash the VM
  lua_replace(L, 2);
  return call_original(L);
}

int load_text_only(lua_State* L) {
  lua_settop(L, std::max(lua_gettop(L), 4));
  lua_pushstring(L, "t");
  lua_replace(L, 3);
  return call_original(L);
}

int io_output_checked(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING)
    return luaL_error(L, "io.output to a file is not allowed: %s", kUnsafeHint);
  return call_original(L);
}

void wrap(lua_State* L, const char* table, const char* field, lua_CFunction wrapper) {
  if (table) lua_getglobal(L, table); else lua_pushglobaltable(L);
  lua_getfield(L, -1, field);
  lua_pushcclosure(L, wrapper, 1);
  lua_setfield(L, -2, field);
  lua_pop(L, 1);
}

// --- require -------------------------------------------------------------------------------

/// package.searchers entry: finds "<name>.lua" in the scene's readable folders only.
int scene_searcher(lua_State* L) {
  const std::string name = luaL_checkstring(L, 1);
  std::string relative = name;
  for (char& c : relative)
    if (c == '.') c = '/';
  const LoaderContext& ctx = context(L);
  for (const auto& folder : search_folders(ctx.script_dir)) {
    for (const char* pattern : {".lua", "/init.lua"}) {
      const auto candidate = folder / (relative + pattern);
      std::error_code ec;
      if (!std::filesystem::is_regular_file(candidate, ec)) continue;
      if (!ctx.options.unsafe_lua && !may_read(ctx, candidate)) continue;
      const std::string path = candidate.string();
      if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK)
        return luaL_error(L, "error loading module '%s' from '%s':\n\t%s", name.c_str(), path.c_str(), lua_tostring(L, -1));
      lua_pushstring(L, path.c_str());
      return 2;
    }
  }
  lua_pushfstring(L, "no file '%s.lua' in the scene's folders", relative.c_str());
  return 1;
}

/// package.searchers entry for native modules in the sandbox.
int refuse_native_module(lua_State* L) {
  lua_pushfstring(L, "require of C modules ('%s') is not allowed: %s", luaL_checkstring(L, 1), kUnsafeHint);
  return 1;
}

// --- built-in readobj ----------------------------------------------------------------------

/// readobj(file) -> vertices, faces (0-based triangles), as the course's readobj.lua returns.
int builtin_readobj_impl(lua_State* L) {
  const std::string name = luaL_checkstring(L, 1);
  const auto path = resolve_input(name, context(L).script_dir);
  if (!path) throw ArgumentError("readobj: cannot find '" + name + "'");
  const ObjMesh mesh = load_obj(*path);
  lua_createtable(L, int(mesh.positions.size()), 0);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    lua_createtable(L, 3, 0);
    for (int k = 0; k < 3; ++k) {
      lua_pushnumber(L, mesh.positions[i][k]);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawseti(L, -2, lua_Integer(i + 1));
  }
  lua_createtable(L, int(mesh.triangles.size()), 0);
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    lua_createtable(L, 3, 0);
    for (int k = 0; k < 3; ++k) {
      lua_pushinteger(L, mesh.triangles[f][size_t(k)].position);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawseti(L, -2, lua_Integer(f + 1));
  }
  return 2;
}

int builtin_module_loader(lua_State*) { return 0; }

/// package.searchers entry: `require('readobj')` without a scene file of that name.
int builtin_searcher(lua_State* L) {
  if (std::strcmp(luaL_checkstring(L, 1), "readobj") == 0) {
    lua_pushcfunction(L, builtin_module_loader);
    lua_pushstring(L, "built-in readobj");
    return 2;
  }
  lua_pushstring(L, "no built-in module of that name");
  return 1;
}

void append_searcher(lua_State* L, lua_CFunction searcher) {
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "searchers");
  lua_pushcfunction(L, searcher);
  lua_rawseti(L, -2, lua_Integer(lua_rawlen(L, -2) + 1));
  lua_pop(L, 2);
}

}  // namespace

void install_compatibility(lua_State* L) {
  // Lua 5.1 names used by old-skeleton scenes.
  lua_getglobal(L, "table");
  lua_getfield(L, -1, "unpack");
  lua_setglobal(L, "unpack");
  lua_pop(L, 1);
  lua_getglobal(L, "string");
  lua_getfield(L, -1, "gmatch");
  lua_setfield(L, -2, "gfind");
  lua_pop(L, 1);
  lua_pushcfunction(L, guarded<builtin_readobj_impl>);
  lua_setglobal(L, "readobj");

  // require finds the scene's own modules first (searcher 2 is package.path's).
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "searchers");
  lua_pushcfunction(L, scene_searcher);
  lua_rawseti(L, -2, 2);
  lua_pop(L, 2);
  append_searcher(L, builtin_searcher);
}

void install_path_resolution(lua_State* L) {
  wrap(L, "io", "open", io_open);
  wrap(L, "io", "lines", path_wrapper<kIoLines>);
  wrap(L, "io", "input", path_wrapper<kIoInput>);
  wrap(L, nullptr, "dofile", path_wrapper<kDofile>);
  wrap(L, nullptr, "loadfile", loadfile_text_only);
}

void install_sandbox(lua_State* L) {
  for (const char* field : {"execute", "exit", "remove", "rename", "tmpname"}) replace_with_refusal(L, "os", field);
  for (const char* field : {"popen", "tmpfile"}) replace_with_refusal(L, "io", field);
  replace_with_refusal(L, "package", "loadlib");
  wrap(L, "io", "output", io_output_checked);
  wrap(L, nullptr, "load", load_text_only);

  // No native modules: searchers 3 and 4 load C libraries.
  lua_getglobal(L, "package");
  lua_pushstring(L, "");
  lua_setfield(L, -2, "cpath");
  lua_getfield(L, -1, "searchers");
  lua_pushcfunction(L, refuse_native_module);
  lua_rawseti(L, -2, 3);
  lua_pushnil(L);
  lua_rawseti(L, -2, 4);
  lua_pop(L, 2);

  // The debug library can reach every upvalue and the registry: remove it.
  lua_pushnil(L);
  lua_setglobal(L, "debug");
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "loaded");
  lua_pushnil(L);
  lua_setfield(L, -2, "debug");
  lua_pop(L, 2);
}

}  // namespace mjray::lua
