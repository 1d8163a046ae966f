// gr.extendedmesh from plain Lua tables (see extended_mesh_tables.h for the form).

#include "mjray/lua/extended_mesh_tables.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

constexpr std::array<const char*, 4> kParts = {"positions", "normals", "uvs", "faces"};

[[noreturn]] void fail(const char* fn, const std::string& problem) {
  throw ArgumentError(std::string(fn) + ": " + problem);
}

/// Pushes the four part tables (nil where a part is absent) and returns the index of the first.
int push_parts(lua_State* L, int index, const char* fn) {
  index = lua_absindex(L, index);
  const bool one_table = lua_type(L, index) == LUA_TTABLE && lua_type(L, index + 1) == LUA_TNONE;
  for (int part = 0; part < 4; ++part) {
    if (!one_table) {
      lua_pushvalue(L, index + part);
    } else if (lua_getfield(L, index, kParts[size_t(part)]) == LUA_TNIL) {
      lua_pop(L, 1);
      lua_rawgeti(L, index, part + 1);
    }
    const int type = lua_type(L, -1);
    if (type != LUA_TTABLE && type != LUA_TNIL && type != LUA_TNONE)
      fail(fn, std::string("the mesh's ") + kParts[size_t(part)] + " must be a table, got " + describe(L, -1));
  }
  return lua_gettop(L) - 3;
}

/// Entries of the table at `table` as tuples of `size` numbers (a longer tuple keeps its first
/// `size`, as an OBJ 'vt u v w' line does).
template <size_t kSize>
std::vector<std::array<float, kSize>> read_tuples(lua_State* L, int table, const char* fn, const char* part) {
  std::vector<std::array<float, kSize>> out;
  if (lua_type(L, table) != LUA_TTABLE) return out;
  const auto count = lua_Integer(lua_rawlen(L, table));
  for (lua_Integer i = 1; i <= count; ++i) {
    lua_rawgeti(L, table, i);
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) < kSize)
      fail(fn, std::string(part) + " entry " + std::to_string(i) + " must be a table of " + std::to_string(kSize) +
                   " numbers, got " + describe(L, -1));
    std::array<float, kSize> tuple{};
    for (size_t k = 0; k < kSize; ++k) {
      lua_rawgeti(L, -1, lua_Integer(k + 1));
      int is_number = 0;
      const double value = lua_tonumberx(L, -1, &is_number);
      if (!is_number || !std::isfinite(value) || std::abs(value) > 3.4e38)
        fail(fn, std::string(part) + " entry " + std::to_string(i) + " has a component that is not a finite number: " +
                     describe(L, -1));
      tuple[k] = float(value);
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    out.push_back(tuple);
  }
  return out;
}

/// One 0-based index of a corner, -1 when absent; checked against `count` entries. Only an
/// `optional` one (a uv or a normal) is said to take -1 or nil for none in messages.
int32_t corner_index(lua_State* L, int value, size_t count, const char* fn, const std::string& where,
                     const char* what, bool optional) {
  if (lua_isnil(L, value)) return -1;
  int is_integer = 0;
  const lua_Integer index = lua_tointegerx(L, value, &is_integer);
  if (!is_integer) fail(fn, where + " " + what + " must be a whole number (0-based), got " + describe(L, value));
  if (index == -1) return -1;
  if (index < 0)
    fail(fn, where + " " + what + " index must be 0 or more" + (optional ? " (-1 or nil: none)" : "") + ", got " +
                 std::to_string(index));
  if (index >= lua_Integer(count))
    fail(fn, where + " has " + what + " index " + std::to_string(index) +
                 (count ? " outside 0.." + std::to_string(count - 1) : std::string(", but the mesh has no ") + what + "s"));
  return int32_t(index);
}

/// A corner: a position index, or {position, uv, normal}.
MeshCorner read_corner(lua_State* L, const TriangleMesh& mesh, const char* fn, const std::string& where) {
  MeshCorner corner;
  if (lua_type(L, -1) != LUA_TTABLE) {
    corner.position = corner_index(L, lua_gettop(L), mesh.positions.size(), fn, where, "position", false);
    if (corner.position < 0) fail(fn, where + " needs a position index");
    return corner;
  }
  const int table = lua_gettop(L);
  const char* names[3] = {"position", "uv", "normal"};
  const size_t counts[3] = {mesh.positions.size(), mesh.uvs.size(), mesh.normals.size()};
  int32_t indices[3];
  for (int k = 0; k < 3; ++k) {
    lua_rawgeti(L, table, k + 1);
    indices[k] = corner_index(L, lua_gettop(L), counts[k], fn, where, names[k], k > 0);
    lua_pop(L, 1);
  }
  if (indices[0] < 0) fail(fn, where + " needs a position index");
  corner.position = indices[0];
  corner.uv = indices[1];
  corner.normal = indices[2];
  return corner;
}

}  // namespace

std::shared_ptr<const TriangleMesh> read_extended_mesh_tables(lua_State* L, int index, const char* fn) {
  const int top = lua_gettop(L);
  const int parts = push_parts(L, index, fn);
  auto mesh = std::make_shared<TriangleMesh>();
  for (const auto& p : read_tuples<3>(L, parts, fn, "positions")) mesh->positions.push_back({p[0], p[1], p[2]});
  for (const auto& n : read_tuples<3>(L, parts + 1, fn, "normals")) mesh->normals.push_back({n[0], n[1], n[2]});
  for (const auto& t : read_tuples<2>(L, parts + 2, fn, "uvs")) mesh->uvs.push_back({t[0], t[1]});

  const int faces = parts + 3;
  if (lua_type(L, faces) != LUA_TTABLE) fail(fn, "the mesh needs a faces table");
  const auto face_count = lua_Integer(lua_rawlen(L, faces));
  std::vector<MeshCorner> corners;
  KeptGrowth kept(L);
  for (lua_Integer f = 1; f <= face_count; ++f) {
    lua_rawgeti(L, faces, f);
    const std::string where = "face " + std::to_string(f);
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) < 3)
      fail(fn, where + " must be a table of at least 3 corners, got " + describe(L, -1));
    const auto corner_count = lua_Integer(lua_rawlen(L, -1));
    corners.clear();
    for (lua_Integer c = 1; c <= corner_count; ++c) {
      lua_rawgeti(L, -1, c);
      corners.push_back(read_corner(L, *mesh, fn, where + " corner " + std::to_string(c)));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    for (size_t k = 2; k < corners.size(); ++k) mesh->triangles.push_back({corners[0], corners[k - 1], corners[k]});
    ++mesh->polygon_count;
    kept.grew_to(mesh->memory_bytes());
  }
  lua_settop(L, top);
  if (mesh->positions.empty() || mesh->triangles.empty())
    fail(fn, "a mesh needs at least one position and one face");
  kept.grew_to(mesh->memory_bytes(), true);
  return mesh;
}

}  // namespace mjray::lua
