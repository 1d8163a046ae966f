#include "mjray/lua/scene_loader.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}

#include "mjray/io/obj_loader.h"
#include "mjray/lua/lua_context.h"

namespace mjray {

namespace lua {

// The context lives in the state's extra space (copied into every coroutine Lua makes), not
// in the registry: the bindings ask for it on every call, and a registry lookup is a hashed
// string key each time.
namespace {
LoaderContext*& context_slot(lua_State* L) { return *static_cast<LoaderContext**>(lua_getextraspace(L)); }
}  // namespace

LoaderContext& context(lua_State* L) {
  LoaderContext* ctx = context_slot(L);
  MJRAY_CHECK(ctx != nullptr);
  return *ctx;
}

void set_context(lua_State* L, LoaderContext* ctx) { context_slot(L) = ctx; }

FileLocation caller_location(lua_State* L) {
  // Level 1 is the running C function's caller; skip C frames (e.g. pcall) and mjray's own Lua
  // wrappers (kInternalChunk) to the script's line.
  lua_Debug ar;
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline > 0 && std::strcmp(ar.source, kInternalChunk) != 0) {
      const char* source = ar.source;
      std::string file = (source && source[0] == '@') ? source + 1 : ar.short_src;
      return {file, ar.currentline};
    }
  }
  return {context(L).script.string(), 0};
}

void record_input(lua_State* L, const std::filesystem::path& path) {
  LoaderContext& ctx = context(L);
  ctx.description->inputs.push_back(path);
  ctx.input_hashes.add(path);
  if (ctx.options.inputs_read) ctx.options.inputs_read->push_back(path);
}

void add_warning(lua_State* L, const std::string& text) { add_warning_at(L, caller_location(L), text); }

void add_warning_at(lua_State* L, const FileLocation& where, const std::string& text) {
  LoaderContext& ctx = context(L);
  const std::string warning = where.to_string() + ": " + text;
  if (ctx.warned.insert(warning).second) ctx.description->warnings.push_back(warning);
}

std::shared_ptr<const TriangleMesh> load_checked_obj(lua_State* L, const std::filesystem::path& path) {
  ObjSummary summary;
  std::shared_ptr<const TriangleMesh> mesh;
  try {
    mesh = std::make_shared<const TriangleMesh>(load_obj(path, &summary, kObjPieceBytes, memory_left(L)));
  } catch (const ObjTooLarge& e) {
    keep_bytes(L, e.bytes + 1);  // past the cap: the --lua-memory error
    throw;
  }
  keep_bytes(L, mesh->memory_bytes());
  if (const std::string warning = check_obj_content(*mesh, summary, path.string()); !warning.empty()) add_warning(L, warning);
  return mesh;
}

std::string read_refusal_hint() {
  return " (its own folder tree, the working directory's and those given with --allow-read); run mjray with "
         "--allow-read DIR to let it read a folder, or --unsafe-lua to lift the sandbox";
}

std::filesystem::path input_file(lua_State* L, const char* fn, const std::string& name) {
  std::optional<std::filesystem::path> path;
  try {
    path = context(L).read_access.resolve(name);
  } catch (const ReadRefused& e) {
    throw ArgumentError(std::string(fn) + ": " + e.what() + read_refusal_hint());
  }
  if (!path)
    throw ArgumentError(std::string(fn) + ": cannot find '" + name +
                        "' (looked in the scene's folder, its parent folders, their Assets/ folders and the working "
                        "directory)");
  record_input(L, *path);
  return *path;
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
  push_string_past_cap(L, message);
  return 1;
}

// --- resource limits -----------------------------------------------------------------------

/// Lua instructions between two budget checks.
constexpr int kHookInterval = 1000;

/// "64 MiB", "4 GiB" or "1000 bytes".
std::string format_bytes(size_t bytes) {
  constexpr size_t kMiB = size_t(1) << 20, kGiB = size_t(1) << 30;
  if (bytes >= kGiB && bytes % kGiB == 0) return std::to_string(bytes / kGiB) + " GiB";
  if (bytes >= kMiB) return std::to_string((bytes + kMiB / 2) / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

/// The Lua line running in L (level 0 is the innermost), or the script when none is.
FileLocation running_location(lua_State* L, const std::filesystem::path& script) {
  lua_Debug ar;
  for (int level = 0; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline > 0) {
      const char* source = ar.source;
      return {(source && source[0] == '@') ? source + 1 : ar.short_src, ar.currentline};
    }
  }
  return {script.string(), 0};
}

/// The message of a script stopped by the --lua-memory cap.
std::string memory_message(const ScriptLimits& limits) {
  const FileLocation where = limits.memory_where.file.empty() ? FileLocation{limits.script.string(), 0} : limits.memory_where;
  return where.to_string() + ": the script needs more than " + format_bytes(limits.memory_limit) +
         " of memory (the --lua-memory limit, which counts the Lua state and what its gr.* calls keep)";
}

/// lua_Alloc with the --lua-memory cap. Shrinking never fails; growing fails past the cap
/// (Lua then collects garbage and tries once more before raising its memory error).
void* limited_alloc(void* ud, void* block, size_t old_size, size_t new_size) {
  auto& limits = *static_cast<ScriptLimits*>(ud);
  if (block == nullptr) old_size = 0;  // old_size then encodes the kind of object
  if (new_size == 0) {
    std::free(block);
    limits.memory_used -= old_size;
    return nullptr;
  }
  if (new_size > old_size && limits.memory_limit != 0 && limits.enforcing && limits.grace == 0 &&
      limits.memory_used - old_size + new_size + limits.kept_bytes > limits.memory_limit) {
    // Reading the call stack allocates nothing, and Lua keeps it consistent wherever it allocates.
    limits.memory_where = running_location(limits.L, limits.script);
    return nullptr;
  }
  void* grown = std::realloc(block, new_size);
  if (grown != nullptr) limits.memory_used = limits.memory_used - old_size + new_size;
  return grown;
}

/// Count hook: stops the script once it passes its instruction or time budget. After the
/// first overrun it fires on every instruction, so a script's own pcall cannot swallow it.
void budget_hook(lua_State* L, lua_Debug*) {
  ScriptLimits& limits = script_limits(L);
  limits.grace = 0;  // Lua code is running, so no binding is
  limits.instructions += kHookInterval;
  if (!limits.budget_exceeded) {
    const bool out_of_instructions = limits.instruction_limit != 0 && limits.instructions > limits.instruction_limit;
    const bool out_of_time = limits.timeout_seconds > 0 && std::chrono::steady_clock::now() > limits.deadline;
    if (!out_of_instructions && !out_of_time) return;
    // No C++ object may be alive when lua_error unwinds this frame: build the text in a buffer.
    const FileLocation where = running_location(L, limits.script);
    char text[160];
    if (out_of_time)
      std::snprintf(text, sizeof text, "the script ran longer than %g s (the --scene-timeout limit)", limits.timeout_seconds);
    else
      std::snprintf(text, sizeof text, "the script ran more than %llu Lua instructions (the instruction limit)",
                    static_cast<unsigned long long>(limits.instruction_limit));
    limits.budget_message = where.to_string() + ": " + text;
    limits.budget_exceeded = true;
  }
  lua_sethook(L, budget_hook, LUA_MASKCOUNT, 1);
  lua_pushstring(L, limits.budget_message.c_str());
  lua_error(L);
}

/// Last resort for --scene-timeout: a script stuck inside one library call never reaches the
/// hook, so past the deadline and a grace period the process ends with the usual error exit.
class Watchdog {
 public:
  Watchdog(double timeout_seconds, std::string script) {
    if (!(timeout_seconds > 0)) return;
    const double grace = std::max(2.0, timeout_seconds / 2);
    const auto limit = std::chrono::duration<double>(timeout_seconds + grace);
    thread_ = std::thread([this, limit, timeout_seconds, script = std::move(script)] {
      std::unique_lock lock(mutex_);
      if (done_cv_.wait_for(lock, limit, [this] { return done_; })) return;
      std::fprintf(stderr, "mjray: error: %s: the script is still running %g s after the %g s --scene-timeout "
                   "(stuck inside one library call); stopping\n", script.c_str(),
                   std::chrono::duration<double>(limit).count() - timeout_seconds, timeout_seconds);
      std::fflush(stderr);
      std::_Exit(1);
    });
  }
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;
  ~Watchdog() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    done_cv_.notify_one();
    thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable done_cv_;
  bool done_ = false;
  std::thread thread_;
};

/// Sets the -D globals: a number where Lua reads the text as one, else the text.
void set_defines(lua_State* L, const SceneLoadOptions& options, const std::filesystem::path& script) {
  for (const auto& [name, value] : options.defines) {
    const int type = lua_getglobal(L, name.c_str());
    lua_pop(L, 1);
    if (type != LUA_TNIL)
      throw SceneError(script.string() + ": -D " + name + "=" + value + " would replace the global '" + name +
                       "' that mjray or Lua defines (a " + lua_typename(L, type) + "); choose another name");
    if (lua_stringtonumber(L, value.c_str()) == 0) lua_pushstring(L, value.c_str());
    lua_setglobal(L, name.c_str());
  }
}

/// Lua 5.4 seeds math.random from the time and an address: seed it from --seed instead.
/// Lua 5.4 seeds math.random from the time and an address, and math.randomseed() without a
/// value does so again: both take --seed instead, so that every run describes one scene.
/// Upvalue 1: the original randomseed; 2: the seed.
int randomseed_or_the_seed(lua_State* L) {
  if (lua_gettop(L) == 0) lua_pushvalue(L, lua_upvalueindex(2));
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

void seed_math_random(lua_State* L, uint64_t seed) {
  lua_getglobal(L, "math");
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, lua_Integer(seed));
  lua_call(L, 1, 0);
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, lua_Integer(seed));
  lua_pushcclosure(L, randomseed_or_the_seed, 2);
  lua_setfield(L, -2, "randomseed");
  lua_pop(L, 1);
}

/// lua_atpanic: an error outside any protected call (only while the libraries are installed).
int on_panic(lua_State* L) {
  const char* message = lua_tostring(L, -1);
  std::fprintf(stderr, "mjray: error: Lua panic: %s\n", message ? message : "(no message)");
  std::abort();
}

}  // namespace

size_t memory_left(lua_State* L) {
  const ScriptLimits& limits = script_limits(L);
  if (limits.memory_limit == 0 || !limits.enforcing) return SIZE_MAX;
  const size_t used = limits.memory_used + limits.kept_bytes;
  return used >= limits.memory_limit ? 0 : limits.memory_limit - used;
}

std::shared_ptr<Image> read_kept_image(lua_State* L, const char* fn, const std::filesystem::path& path,
                                       ImageReadOptions options) {
  // A decoded pixel takes a Color; decoding may hold up to a pixel's 16-bit RGB beside it.
  constexpr size_t kDecodingBytesPerPixel = sizeof(Color) + 6;
  const size_t left = memory_left(L);
  options.max_pixels = std::min(options.max_pixels, left / kDecodingBytesPerPixel);
  std::shared_ptr<Image> image;
  try {
    image = std::make_shared<Image>(read_image(path, options));
  } catch (const ImageTooLarge& e) {
    if (left != SIZE_MAX) keep_bytes(L, size_t(e.width * e.height * kDecodingBytesPerPixel));
    throw ArgumentError(std::string(fn) + ": " + e.what());
  } catch (const OutputError& e) {
    throw ArgumentError(std::string(fn) + ": " + e.what());
  }
  keep_bytes(L, image->pixels().size() * sizeof(Color));
  return image;
}

void keep_bytes(lua_State* L, size_t bytes) {
  ScriptLimits& limits = script_limits(L);
  const auto over = [&] {
    return limits.memory_limit != 0 && limits.enforcing &&
           (bytes > limits.memory_limit || limits.memory_used + limits.kept_bytes + bytes > limits.memory_limit);
  };
  // As Lua's allocator does before it fails: collect the garbage, and ask again.
  if (over()) lua_gc(L, LUA_GCCOLLECT);
  if (over()) {
    limits.memory_where = caller_location(L);
    limits.kept_exceeded = true;
    throw ArgumentError(memory_message(limits).substr(limits.memory_where.to_string().size() + 2));
  }
  limits.kept_bytes += bytes;
}

}  // namespace lua

SceneDescription load_scene(const std::filesystem::path& script, const SceneLoadOptions& options) {
  SceneDescription description;
  description.script = script;
  lua::LoaderContext ctx;
  ctx.script = script;
  ctx.script_dir = std::filesystem::absolute(script).parent_path();
  ctx.options = options;
  if (!options.unsafe_lua) ctx.read_access = ReadAccess(ctx.script_dir, options.allowed_read_folders);
  ctx.description = &description;

  // Compute the state on the capped allocator; the cap and budget start with the script.
  lua::ScriptLimits limits;
  limits.memory_limit = options.lua_memory_bytes;
  limits.instruction_limit = options.instruction_limit;
  limits.timeout_seconds = options.timeout_seconds;
  limits.script = script;
  std::unique_ptr<lua_State, decltype(&lua_close)> state(lua_newstate(lua::limited_alloc, &limits), &lua_close);
  if (!state) throw SceneError("cannot create a Lua state (out of memory)");
  lua_State* L = state.get();
  limits.L = L;
  lua_atpanic(L, lua::on_panic);
  luaL_openlibs(L);
  lua::seed_math_random(L, options.random_seed);
  lua::set_context(L, &ctx);
  // The sandbox goes last: it rebuilds package.searchers from what compatibility installed.
  lua::install_compatibility(L);
  lua::install_path_resolution(L);
  if (!options.unsafe_lua) lua::install_sandbox(L);
  lua::register_gr(L);
  lua::register_extensions(L);
  lua::guard_gr_names(L);
  lua::set_defines(L, options, script);
  description.defines = options.defines;

  std::error_code ec;
  if (!std::filesystem::exists(script, ec))
    throw SceneError(script.string() + ": cannot open the scene file (no such file)");
  if (!std::filesystem::is_regular_file(script, ec))
    throw SceneError(script.string() + ": cannot open the scene file (not a regular file)");

  // Compute: load and run the chunk; errors arrive as "file:line: message" strings.
  lua_pushcfunction(L, lua::describe_error_value);
  limits.deadline = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(options.timeout_seconds));
  lua_sethook(L, lua::budget_hook, LUA_MASKCOUNT, lua::kHookInterval);
  limits.enforcing = true;
  std::string error;
  {
    // The state closes while the watchdog watches and the memory cap holds: finalizers run
    // then, and Lua runs no hooks inside them.
    const lua::Watchdog watchdog(options.timeout_seconds, script.string());
    int status = luaL_loadfilex(L, script.c_str(), "t");
    if (status == LUA_OK) status = lua_pcall(L, 0, 0, 1);
    if (limits.budget_exceeded) {
      error = limits.budget_message;
    } else if (status == LUA_ERRMEM || limits.kept_exceeded) {
      error = lua::memory_message(limits);
    } else if (status != LUA_OK) {
      const char* message = lua_tostring(L, -1);
      // A script's message may hold terminal commands ("\027[2J"): shown escaped.
      error = message ? escape_control_characters(message, true)
                      : script.string() + ": the script raised an error that is not a string";
    }
    state.reset();
  }
  if (!error.empty()) throw SceneError(error);
  if (description.jobs.empty()) throw SceneError(script.string() + ": the scene never calls gr.render");
  description.input_hashes = ctx.input_hashes.wait();
  return description;
}

}  // namespace mjray
