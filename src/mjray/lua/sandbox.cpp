// The Lua environment a scene script runs in: CS 488 compatibility shims, path resolution,
// and (by default) a sandbox that keeps a stranger's script from touching the system.

#include <cstring>
#include <string>
#include <string_view>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}

#include "mjray/io/obj_loader.h"
#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

constexpr const char* kUnsafeHint = "scene scripts run sandboxed; run mjray with --unsafe-lua to allow it";

// --- helpers -------------------------------------------------------------------------------

/// Where a file the script writes, removes or renames lives: relative names are beside the
/// script, like the images it renders.
std::filesystem::path write_path(const LoaderContext& ctx, const std::string& name) {
  const std::filesystem::path path(name);
  return path.is_absolute() ? path : ctx.script_dir / path;
}

/// Checks that the script may read `name`; returns the file it means (where io.open will
/// report it missing, if no readable file is found).
std::string checked_read_path(lua_State* L, const char* fn, const std::string& name) {
  const LoaderContext& ctx = context(L);
  try {
    if (const auto found = ctx.read_access.resolve(name)) return found->string();
  } catch (const ReadRefused& e) {
    throw ArgumentError(std::string(fn) + ": " + e.what() + read_refusal_hint());
  }
  const std::filesystem::path path(name);
  const std::filesystem::path meant = path.is_absolute() ? path : ctx.script_dir / path;
  // A device or a pipe in the scene's folder (an archive can hold one) is no file to read.
  std::error_code ec;
  if (!ctx.options.unsafe_lua && std::filesystem::exists(meant, ec) && !std::filesystem::is_regular_file(meant, ec))
    throw ArgumentError(std::string(fn) + ": '" + name + "' is not a regular file (a device, a pipe or a folder); " +
                        kUnsafeHint);
  return meant.string();
}

// --- refusing functions --------------------------------------------------------------------

/// Upvalue 1 names the refused function ("os.execute").
int refuse(lua_State* L) {
  throw ArgumentError(std::string(lua_tostring(L, lua_upvalueindex(1))) + " is not allowed: " + kUnsafeHint);
}

void replace_with_refusal(lua_State* L, const char* table, const char* field) {
  lua_getglobal(L, table);
  if (!lua_istable(L, -1)) {
    lua_pop(L, 1);
    return;
  }
  lua_pushfstring(L, "%s.%s", table, field);
  lua_pushcclosure(L, guarded<refuse>, 1);
  lua_setfield(L, -2, field);
  lua_pop(L, 1);
}

// --- wrappers around io.open / io.lines / io.input / dofile / loadfile / load --------------
// Each keeps the original function as upvalue 1 and calls it with a checked path. Checks
// report by throwing (see `guarded`), so they never use luaL_check*.

/// Message handler of call_original: an error the original raises itself has no location
/// (its caller is C), so it gets the script's line. Upvalue 1 is the original.
int locate_original_error(lua_State* L) {
  lua_Debug ar;
  if (lua_type(L, 1) != LUA_TSTRING || !lua_getstack(L, 1, &ar)) return 1;
  lua_getinfo(L, "f", &ar);
  const bool raised_by_original = lua_rawequal(L, -1, lua_upvalueindex(1));
  lua_pop(L, 1);
  if (!raised_by_original) return 1;  // from Lua code the original ran: already located
  const std::string message = caller_location(L).to_string() + ": " + lua_tostring(L, 1);
  push_string_past_cap(L, message);
  return 1;
}

int call_original(lua_State* L) {
  const int arguments = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushcclosure(L, locate_original_error, 1);
  lua_insert(L, 1);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 2);
  if (lua_pcall(L, arguments, LUA_MULTRET, 1) != LUA_OK) return lua_error(L);
  return lua_gettop(L) - 1;
}

int open_checked(lua_State* L) {
  if (lua_type(L, 1) != LUA_TSTRING) return 0;  // the original reports bad arguments
  // A non-string mode is refused by the original, so "r" here opens nothing it would not.
  const char* mode = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "r";
  const bool writes = std::strpbrk(mode, "wa+") != nullptr;
  if (writes && !context(L).options.unsafe_lua)
    throw ArgumentError(std::string("io.open for writing ('") + mode + "') is not allowed: " + kUnsafeHint);
  const std::string name = lua_tostring(L, 1);
  const std::string path = writes ? write_path(context(L), name).string() : checked_read_path(L, "io.open", name);
  if (!writes) record_input(L, path);
  lua_pushstring(L, path.c_str());
  lua_replace(L, 1);
  return 0;
}

int io_open(lua_State* L) {
  guarded<open_checked>(L);
  return call_original(L);
}

/// Resolves and checks a file-name argument 1; kStdin: without a name the function would
/// read standard input, which a sandboxed script may not.
template <const char* kName, bool kStdin>
int path_checked(lua_State* L) {
  if (lua_type(L, 1) != LUA_TSTRING) {
    if (kStdin && lua_isnoneornil(L, 1) && !context(L).options.unsafe_lua)
      throw ArgumentError(std::string(kName) + " without a file name reads standard input, which is not allowed: " +
                          kUnsafeHint);
    return 0;
  }
  const std::string path = checked_read_path(L, kName, lua_tostring(L, 1));
  record_input(L, path);
  lua_pushstring(L, path.c_str());
  lua_replace(L, 1);
  return 0;
}

constexpr char kIoLines[] = "io.lines";
constexpr char kIoInput[] = "io.input";
constexpr char kDofile[] = "dofile";
constexpr char kLoadfile[] = "loadfile";

template <const char* kName, bool kStdin>
int path_wrapper(lua_State* L) {
  guarded<path_checked<kName, kStdin>>(L);
  return call_original(L);
}

/// Gives the error message on top of the stack the caller's line, as errors the originals
/// raise get it (locate_original_error).
int locate_message(lua_State* L) {
  const std::string message = caller_location(L).to_string() + ": " + lua_tostring(L, -1);
  lua_pop(L, 1);
  push_string_past_cap(L, message);
  return 1;
}

/// Continues dofile once its chunk has returned: every value the chunk returned.
int dofile_results(lua_State* L, int, lua_KContext) { return lua_gettop(L) - 1; }

/// dofile(name) loading text only, as loadfile does: a precompiled chunk can crash the VM.
/// (No C++ object lives across the calls that may raise.)
int dofile_text_only(lua_State* L) {
  guarded<path_checked<kDofile, true>>(L);
  lua_settop(L, 1);
  if (luaL_loadfilex(L, lua_tostring(L, 1), "t") != LUA_OK) {
    guarded<locate_message>(L);
    return lua_error(L);
  }
  lua_callk(L, 0, LUA_MULTRET, 0, dofile_results);
  return dofile_results(L, 0, 0);
}

/// Refuses a mode argument at `index` that asks for binary chunks only ('b'): forcing it to
/// text would read the text the script meant to refuse.
void refuse_binary_mode(lua_State* L, int index, const char* fn) {
  if (lua_type(L, index) == LUA_TSTRING && std::strchr(lua_tostring(L, index), 't') == nullptr)
    throw ArgumentError(std::string(fn) + " of precompiled (binary) chunks ('" + escape_control_characters(lua_tostring(L, index), false) +
                        "') is not allowed: " + kUnsafeHint);
}

int loadfile_mode_checked(lua_State* L) {
  refuse_binary_mode(L, 2, "loadfile");
  return 0;
}

/// loadfile(name, mode, env) with mode forced to text: binary chunks can crash the VM.
int loadfile_text_only(lua_State* L) {
  guarded<path_checked<kLoadfile, true>>(L);
  if (!context(L).options.unsafe_lua) guarded<loadfile_mode_checked>(L);
  // Pad only up to the mode: an absent env must stay absent (nil would be an empty _ENV).
  lua_settop(L, std::max(lua_gettop(L), 2));
  lua_pushstring(L, "t");
  lua_replace(L, 2);
  return call_original(L);
}

int load_checked(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING && lua_tostring(L, 1)[0] == LUA_SIGNATURE[0])
    throw ArgumentError(std::string("load of a precompiled (binary) chunk is not allowed: ") + kUnsafeHint);
  refuse_binary_mode(L, 3, "load");
  return 0;
}


/// load(chunk, chunkname, mode, env) with mode forced to text.
int load_text_only(lua_State* L) {
  guarded<load_checked>(L);
  lua_settop(L, std::max(lua_gettop(L), 3));
  lua_pushstring(L, "t");
  lua_replace(L, 3);
  return call_original(L);
}

/// os.remove(name) / os.rename(from, to) (unsafe only): names resolve like io.open's writes.
int file_names_resolved(lua_State* L) {
  for (int index = 1; index <= std::min(lua_gettop(L), 2); ++index) {
    if (lua_type(L, index) != LUA_TSTRING) continue;
    const std::string path = write_path(context(L), lua_tostring(L, index)).string();
    lua_pushstring(L, path.c_str());
    lua_replace(L, index);
  }
  return 0;
}

int os_file_operation(lua_State* L) {
  guarded<file_names_resolved>(L);
  return call_original(L);
}

int output_checked(lua_State* L) {
  if (lua_type(L, 1) == LUA_TSTRING)
    throw ArgumentError(std::string("io.output to a file is not allowed: ") + kUnsafeHint);
  return 0;
}

int io_output(lua_State* L) {
  guarded<output_checked>(L);
  return call_original(L);
}

/// setmetatable(t, mt) without a __gc finalizer: Lua runs finalizers with no hooks, so no
/// time or instruction limit reaches them, and some run only when the state closes.
int finalizer_refused(lua_State* L) {
  if (lua_type(L, 1) != LUA_TTABLE)
    throw ArgumentError("setmetatable: argument 1 must be a table, got " + describe(L, 1));
  if (lua_type(L, 2) != LUA_TTABLE) return 0;  // the original reports bad arguments
  lua_pushliteral(L, "__gc");
  const bool has_finalizer = lua_rawget(L, 2) != LUA_TNIL;
  lua_pop(L, 1);
  if (has_finalizer)
    throw ArgumentError(std::string("setmetatable with a __gc finalizer is not allowed (finalizers run outside the "
                                    "script's time limit): ") + kUnsafeHint);
  return 0;
}

int setmetatable_checked(lua_State* L) {
  guarded<finalizer_refused>(L);
  return call_original(L);
}

/// os.time(), os.clock() and os.date() without a time: their answer differs from run to run,
/// and so may the scene. Notes the first such read (SceneDescription::reads_clock). Upvalue 2
/// names the function.
int clock_noted(lua_State* L) {
  const char* name = lua_tostring(L, lua_upvalueindex(2));
  const bool given_time = std::strcmp(name, "os.time") == 0 ? !lua_isnoneornil(L, 1)
                          : std::strcmp(name, "os.date") == 0 ? !lua_isnoneornil(L, 2)
                                                               : false;
  std::string& first = context(L).description->reads_clock;
  if (!given_time && first.empty()) first = std::string(name) + " at " + caller_location(L).to_string();
  return 0;
}

int clock_reader(lua_State* L) {
  guarded<clock_noted>(L);
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

/// package.searchers entry: finds "<name>.lua" (or "<name>/init.lua") in the scene's folders;
/// sandboxed, only in those it may read.
int scene_searcher(lua_State* L) {
  if (lua_type(L, 1) != LUA_TSTRING) return 0;
  const std::string name = lua_tostring(L, 1);
  std::string relative = name;
  for (char& c : relative)
    if (c == '.') c = '/';
  const LoaderContext& ctx = context(L);
  for (const auto& folder : search_folders(ctx.script_dir)) {
    for (const char* pattern : {".lua", "/init.lua"}) {
      // Concatenated, not path-joined: a name like ".x" must not become the absolute "/x".
      const std::filesystem::path candidate = folder.string() + "/" + relative + pattern;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(candidate, ec)) continue;
      if (!ctx.read_access.allows(candidate)) continue;
      const std::string path = candidate.lexically_normal().string();
      record_input(L, path);
      if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK)
        throw ArgumentError("error loading module '" + name + "' from file '" + path + "':\n\t" + lua_tostring(L, -1));
      lua_pushstring(L, path.c_str());
      return 2;
    }
  }
  lua_pushstring(L, ("no file '" + relative + ".lua' in the scene's folders").c_str());
  return 1;
}

/// package.searchers entry for native modules in the sandbox.
int refuse_native_module(lua_State* L) {
  lua_pushfstring(L, "require of C modules ('%s') is not allowed: %s", lua_tostring(L, 1), kUnsafeHint);
  return 1;
}

// --- built-in readobj ----------------------------------------------------------------------

/// readobj(file) -> vertices, faces (0-based triangles), as the course's readobj.lua returns.
int builtin_readobj_impl(lua_State* L) {
  if (lua_type(L, 1) != LUA_TSTRING)
    throw ArgumentError("readobj: argument 1 (file name) must be a string, got a " + std::string(luaL_typename(L, 1)));
  const std::filesystem::path path = input_file(L, "readobj", lua_tostring(L, 1));
  TriangleMesh mesh;
  try {
    mesh = *load_checked_obj(L, path);
  } catch (const SceneError& e) {
    throw ArgumentError(std::string("readobj: ") + e.what());
  }
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
  const char* name = lua_tostring(L, 1);
  if (name && std::strcmp(name, "readobj") == 0) {
    lua_pushcfunction(L, builtin_module_loader);
    lua_pushstring(L, "built-in readobj");
    return 2;
  }
  lua_pushfstring(L, "no built-in module '%s'", name ? name : "?");
  return 1;
}

constexpr lua_Integer kAtEnd = 0;

/// Puts `searcher` at `position` (or kAtEnd) of package.searchers, moving later entries up.
void insert_searcher(lua_State* L, lua_Integer position, lua_CFunction searcher) {
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "searchers");
  if (position == kAtEnd) position = lua_Integer(lua_rawlen(L, -1)) + 1;
  for (auto i = lua_Integer(lua_rawlen(L, -1)); i >= position; --i) {
    lua_rawgeti(L, -1, i);
    lua_rawseti(L, -2, i + 1);
  }
  lua_pushcfunction(L, searcher);
  lua_rawseti(L, -2, position);
  lua_pop(L, 2);
}

// --- what reaches the terminal, and standard input -----------------------------------------

/// escape(text): the text with terminal commands shown as escapes (escape_control_characters).
int escape_for_terminal(lua_State* L) {
  size_t length = 0;
  const char* text = lua_tolstring(L, 1, &length);
  push_string_past_cap(L, escape_control_characters(std::string_view(text ? text : "", length), true));
  return 1;
}

/// Wraps print, io.write and every file's write so that terminal commands a script writes
/// ("\027[2J") show as escapes, as its messages do; and every way to read standard input
/// (io.read and io.lines on the default input, a file's read and lines on stdin) so that they
/// refuse. The functions they call are captured now, before the script can replace any.
/// Arguments of the chunk: escape, io.stdin, the refusal's hint.
constexpr const char* kTerminalGuard = R"lua(
local escape, stdin, hint = ...
local raw_print, write, read, lines, input = print, io.write, io.read, io.lines, io.input
local select, tostring, type, concat, unpack, error = select, tostring, type, table.concat, table.unpack, error
local methods = getmetatable(stdin).__index
local file_write, file_read, file_lines = methods.write, methods.read, methods.lines
local function escaped(n, ...)
  local values = {...}
  for i = 1, n do
    if type(values[i]) == 'string' then values[i] = escape(values[i]) end
  end
  return unpack(values, 1, n)
end
local function refuse_stdin(file, what)
  if file == stdin then error(what .. ' from standard input is not allowed: ' .. hint, 3) end
end
print = function(...)
  local n, parts = select('#', ...), {...}
  for i = 1, n do parts[i] = escape(tostring(parts[i])) end
  raw_print(concat(parts, '	', 1, n))
end
io.write = function(...) return write(escaped(select('#', ...), ...)) end
methods.write = function(file, ...) return file_write(file, escaped(select('#', ...), ...)) end
io.read = function(...)
  refuse_stdin(input(), 'io.read')
  return read(...)
end
io.lines = function(name, ...)
  if name == nil then refuse_stdin(input(), 'io.lines') end
  return lines(name, ...)
end
methods.read = function(file, ...)
  refuse_stdin(file, 'file:read')
  return file_read(file, ...)
end
methods.lines = function(file, ...)
  refuse_stdin(file, 'file:lines')
  return file_lines(file, ...)
end
)lua";

void install_terminal_guard(lua_State* L) {
  MJRAY_CHECK(luaL_loadbufferx(L, kTerminalGuard, std::strlen(kTerminalGuard), kInternalChunk, "t") == LUA_OK);
  lua_pushcfunction(L, guarded<escape_for_terminal>);
  lua_getglobal(L, "io");
  lua_getfield(L, -1, "stdin");
  lua_remove(L, -2);
  lua_pushstring(L, kUnsafeHint);
  lua_call(L, 3, 0);
  // No script reaches the files' metatable: it could give files a finalizer, or undo the above.
  luaL_getmetatable(L, LUA_FILEHANDLE);
  lua_pushliteral(L, "FILE*");
  lua_setfield(L, -2, "__metatable");
  lua_pop(L, 1);
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

  // require: preload, then the scene's folders, then package.path/cpath, then the built-ins
  // (last, so that a scene's own readobj.lua wins).
  insert_searcher(L, 2, guarded<scene_searcher>);
  insert_searcher(L, kAtEnd, builtin_searcher);
}

void install_path_resolution(lua_State* L) {
  wrap(L, "io", "open", io_open);
  wrap(L, "io", "lines", path_wrapper<kIoLines, false>);
  wrap(L, "io", "input", path_wrapper<kIoInput, false>);
  lua_pushcfunction(L, dofile_text_only);
  lua_setglobal(L, "dofile");
  wrap(L, nullptr, "loadfile", loadfile_text_only);
  for (const char* field : {"time", "clock", "date"}) {
    lua_getglobal(L, "os");
    lua_getfield(L, -1, field);
    lua_pushfstring(L, "os.%s", field);
    lua_pushcclosure(L, clock_reader, 2);
    lua_setfield(L, -2, field);
    lua_pop(L, 1);
  }
  wrap(L, "os", "remove", os_file_operation);
  wrap(L, "os", "rename", os_file_operation);
}

void install_sandbox(lua_State* L) {
  // os.getenv tells a script about the user; os.setlocale changes how the whole process
  // writes numbers (statistics JSON with decimal commas).
  for (const char* field : {"execute", "exit", "remove", "rename", "tmpname", "getenv", "setlocale"})
    replace_with_refusal(L, "os", field);
  for (const char* field : {"popen", "tmpfile"}) replace_with_refusal(L, "io", field);
  // package.searchpath tells whether a file exists anywhere.
  for (const char* field : {"loadlib", "searchpath"}) replace_with_refusal(L, "package", field);
  wrap(L, "io", "output", io_output);
  wrap(L, nullptr, "load", load_text_only);
  wrap(L, nullptr, "setmetatable", setmetatable_checked);

  // require: preload, the scene's readable folders, the built-ins, and a refusal for native
  // modules; the package.path/cpath searchers go, so neither path can reach outside.
  lua_getglobal(L, "package");
  lua_pushstring(L, "");
  lua_setfield(L, -2, "cpath");
  lua_getfield(L, -1, "searchers");
  for (auto i = lua_Integer(lua_rawlen(L, -1)); i > 1; --i) {
    lua_pushnil(L);
    lua_rawseti(L, -2, i);
  }
  const lua_CFunction searchers[] = {guarded<scene_searcher>, builtin_searcher, refuse_native_module};
  lua_Integer position = 2;
  for (const lua_CFunction searcher : searchers) {
    lua_pushcfunction(L, searcher);
    lua_rawseti(L, -2, position++);
  }
  lua_pop(L, 2);

  install_terminal_guard(L);

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
