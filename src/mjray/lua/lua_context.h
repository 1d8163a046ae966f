#pragma once
/// State shared by the Lua bindings while one script runs (internal to lua/).

#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <string>
#include <vector>

extern "C" {
#include <lua.h>
}

#include "mjray/core/error.h"
#include "mjray/io/file_hash.h"
#include "mjray/io/image_reader.h"
#include "mjray/io/path_resolver.h"
#include "mjray/lua/scene_loader.h"
#include "mjray/scene/scene_description.h"

namespace mjray::lua {

/// The limits a script runs under and how close it is to them; the Lua state's allocator
/// data, so that the allocator, the budget hook and `guarded` reach it without allocating.
struct ScriptLimits {
  size_t memory_limit = 0;      ///< bytes; 0 = none
  size_t memory_used = 0;       ///< bytes the Lua state holds now
  /// Bytes that gr.* calls keep on the C++ side for the script (nodes and their names, meshes,
  /// images, snapshots), counted as they are made and never given back: what a script keeps
  /// alive is kept to the end, in its gr.render snapshots.
  size_t kept_bytes = 0;
  bool kept_exceeded = false;   ///< a binding was refused memory: the load fails even if the script goes on
  bool enforcing = false;       ///< off while the libraries are installed
  /// Nonzero while a C++ binding runs: its own Lua allocations may pass the cap, since a Lua
  /// memory error would longjmp over its C++ locals; the script's next allocation fails.
  int grace = 0;
  lua_State* L = nullptr;       ///< the main thread, to locate a refused allocation
  std::filesystem::path script; ///< for messages with no Lua line
  FileLocation memory_where;    ///< the Lua line of the last refused allocation

  uint64_t instruction_limit = 0;  ///< 0 = none
  uint64_t instructions = 0;       ///< counted in steps of the hook interval
  double timeout_seconds = 0;      ///< 0 = none
  std::chrono::steady_clock::time_point deadline{};
  bool budget_exceeded = false;
  std::string budget_message;      ///< "file:line: ..." of the first overrun
};

/// The limits of the script running in L.
inline ScriptLimits& script_limits(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<ScriptLimits*>(ud);
}

/// Pushes `text` even past the memory cap, for C functions that hold C++ strings while they
/// push: a Lua memory error there would longjmp over their destructors.
inline void push_string_past_cap(lua_State* L, const std::string& text) {
  ScriptLimits& limits = script_limits(L);
  ++limits.grace;
  lua_pushlstring(L, text.data(), text.size());
  --limits.grace;
}

/// Counts `bytes` that a binding is about to keep for the script against --lua-memory, with
/// the Lua state's own; past the cap, throws ArgumentError instead and the load fails.
void keep_bytes(lua_State* L, size_t bytes);

/// keep_bytes for something a binding builds up from a script's tables (a mesh): charged as
/// it grows, a step at a time, so that tables reused many times over (one face table in
/// every slot) are refused before they cost gigabytes.
class KeptGrowth {
 public:
  explicit KeptGrowth(lua_State* L) : L_(L) {}
  /// The thing now takes `bytes`: charges what it grew by since the last charge, once that is
  /// a step's worth (or when `final`).
  void grew_to(size_t bytes, bool final = false) {
    if (bytes > charged_ && (final || bytes - charged_ >= kStep)) {
      keep_bytes(L_, bytes - charged_);
      charged_ = bytes;
    }
  }

 private:
  static constexpr size_t kStep = size_t(1) << 20;
  lua_State* L_;
  size_t charged_ = 0;
};

/// The bytes a binding may still take under --lua-memory (SIZE_MAX without a cap), so that it
/// can refuse what would pass it before allocating (a decompression bomb, a mesh of millions
/// of triangles from a few lines of text).
size_t memory_left(lua_State* L);

/// Reads an image file for `fn` within memory_left, charged to the script as it keeps it;
/// throws ArgumentError("FN: ...") when it cannot be read, and the --lua-memory error when it
/// is larger than the script may still take.
std::shared_ptr<Image> read_kept_image(lua_State* L, const char* fn, const std::filesystem::path& path,
                                       ImageReadOptions options);

/// A node as the script builds it: mutable until a gr.render call snapshots it.
struct LuaNode {
  std::string name;
  FileLocation where;
  std::optional<Shape> shape;  ///< with `mesh`: what the node draws (neither: a group)
  Transform node_from_object;
  std::shared_ptr<const TriangleMesh> mesh;
  std::filesystem::path mesh_file;  ///< the OBJ file of gr.mesh(name, file), whose materials it may use
  std::shared_ptr<Material> material;
  std::vector<Transform> transform_calls;  ///< in call order
  /// "the table-form gr.mesh" or "the gr.extendedmesh": geometry only old-skeleton and
  /// original-project scenes make, which decides the automatic transform order.
  const char* old_skeleton_geometry = nullptr;
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
  ReadAccess read_access;  ///< what the script may read (everything with --unsafe-lua)
  /// The automatic transform order, decided at the first gr.render (see docs/scene-format.md).
  std::optional<bool> post_multiply;
  SceneDescription* description = nullptr;
  std::map<std::filesystem::path, std::shared_ptr<const TriangleMesh>> mesh_cache;
  /// The materials of each OBJ file whose own materials a node uses, by file (obj_materials.cpp).
  std::map<std::filesystem::path, std::vector<std::shared_ptr<const Material>>> obj_materials;
  /// Meshes split by material, by the mesh split.
  std::map<std::shared_ptr<const TriangleMesh>, std::vector<MeshPart>> mesh_parts;
  /// mesh:set_smooth_normals's meshes, by the mesh smoothed and the angle.
  std::map<std::pair<std::shared_ptr<const TriangleMesh>, float>, std::shared_ptr<const TriangleMesh>> smoothed_meshes;
  BackgroundFileHashes input_hashes;  ///< of description->inputs, for the resume fingerprints
  std::vector<std::weak_ptr<LuaNode>> nodes;  ///< every node made, to break cycles at the end
  std::set<std::string> warned;  ///< warnings given, so that a loop gives each once
  /// gr.lens's and gr.background's, for the gr.render calls after them.
  float aperture_radius = 0, focus_distance = 0;
  Background background;

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

/// The parts a node draws for `mesh`, read from `obj` (its file): one per material its faces
/// use, each with the material its file's `.mtl` gives. Warnings and errors name `where`,
/// the gr.mesh call, and the file and line at fault.
std::vector<MeshPart> obj_mesh_parts(lua_State* L, const FileLocation& where, const std::filesystem::path& obj,
                                     const std::shared_ptr<const TriangleMesh>& mesh);

/// Defines the `gr` table and the userdata types.
void register_gr(lua_State* L);
/// Adds the original project's extensions (materials, area lights, extended meshes) to `gr`.
void register_extensions(lua_State* L);
/// Adds the textures (gr.*texture) to `gr` and set_material_texture to materials; needs
/// register_gr first.
void register_textures(lua_State* L);
/// Adds gr.lens and gr.background to `gr`; needs register_gr first.
void register_view(lua_State* L);
/// Adds gr.spotlight and gr.sunlight to `gr`; needs register_gr first.
void register_lights(lua_State* L);
/// Adds what CS 488 scripts of both course generations expect: unpack, string.gfind,
/// the scene folder on the require path, and a built-in readobj module.
void install_compatibility(lua_State* L);
/// Replaces every standard function that could run programs, write files, load native code
/// or read outside the scene's folders with one that refuses, naming itself.
void install_sandbox(lua_State* L);
/// Wraps io.open/io.lines/io.input/dofile/loadfile so relative names resolve like every other
/// scene path (writes, os.remove and os.rename: beside the script), and forces loadfile to text.
void install_path_resolution(lua_State* L);

/// Makes reading a missing name from `gr`, a node or a material an error that suggests the
/// closest name: "gr.sphre is not a gr function; did you mean gr.sphere?". Call after every
/// gr function and method is registered.
void guard_gr_names(lua_State* L);

/// Adds a file the script reads to SceneDescription::inputs.
void record_input(lua_State* L, const std::filesystem::path& path);

/// Reads an OBJ file a scene draws: SceneError for malformed or empty files (no vertices or
/// no faces), a warning when most of it is not OBJ.
std::shared_ptr<const TriangleMesh> load_checked_obj(lua_State* L, const std::filesystem::path& path);

/// Adds "file:line: text" (the caller's line) to SceneDescription::warnings, once per line
/// and text.
void add_warning(lua_State* L, const std::string& text);
/// add_warning for a call made earlier (`where`), such as the gr.mesh whose file is read late.
void add_warning_at(lua_State* L, const FileLocation& where, const std::string& text);

/// "file:line" of the Lua code that called the running C function.
FileLocation caller_location(lua_State* L);

/// The chunk name of mjray's own Lua code (the sandbox's wrappers), which caller_location
/// passes over: a refusal names the script's line, not the wrapper's.
inline constexpr const char* kInternalChunk = "=(mjray)";

/// The file a script names for `fn` to read (a mesh, a texture, an environment): found like
/// every scene input, refused outside what the script may read, and recorded as an input.
/// Throws ArgumentError("FN: ...") when it is missing or refused.
std::filesystem::path input_file(lua_State* L, const char* fn, const std::string& name);

/// What a refused read adds to its message: how the user allows more.
std::string read_refusal_hint();

/// An error that names an earlier call of the script (a gr.mesh whose file is read at
/// gr.render): `guarded` reports it as it is, without the caller's line.
struct EarlierCallError : std::runtime_error {
  EarlierCallError(const FileLocation& where, const std::string& problem)
      : std::runtime_error(where.to_string() + ": " + problem) {}
};

/// A C function that reports C++ exceptions as Lua errors at the caller's line (the
/// exception is gone before lua_error unwinds, so no C++ destructor is skipped). F itself must
/// report problems by throwing: a luaL_error/luaL_check* inside F would longjmp over F's
/// C++ locals. While F runs, its Lua allocations may pass the memory cap (see ScriptLimits).
template <int (*F)(lua_State*)>
int guarded(lua_State* L) {
  ScriptLimits& limits = script_limits(L);
  ++limits.grace;
  int results = -1;
  try {
    results = F(L);
  } catch (const EarlierCallError& e) {
    lua_pushstring(L, e.what());
  } catch (const std::exception& e) {
    lua_pushstring(L, (caller_location(L).to_string() + ": " + error_message(e)).c_str());
  } catch (...) {
    lua_pushstring(L, (caller_location(L).to_string() + ": internal error in a gr binding").c_str());
  }
  --limits.grace;
  if (results >= 0) return results;
  return lua_error(L);
}

/// Thrown by bindings for a bad argument; `guarded` prefixes the caller's location.
class ArgumentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mjray::lua
