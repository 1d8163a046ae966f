// Misspelled gr functions and methods: "gr.sphre is not a gr function; did you mean
// gr.sphere?" instead of Lua's "attempt to call a nil value".

#include <algorithm>
#include <cctype>
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

/// Levenshtein distance, ignoring case.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      const size_t substitution = diagonal + (same ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

/// Whether `name`'s letters appear in `candidate` in order ("set_texture" in "set_material_texture").
bool is_abbreviation(const std::string& name, const std::string& candidate) {
  size_t at = 0;
  for (const char c : candidate)
    if (at < name.size() && std::tolower(static_cast<unsigned char>(c)) == std::tolower(static_cast<unsigned char>(name[at])))
      ++at;
  return name.size() >= 4 && at == name.size();
}

/// The function name in the table at `table` closest to `name`: the fewest edits (at most
/// about a third of the name), else the shortest that `name` abbreviates; "" when none is close.
std::string closest_function(lua_State* L, int table, const std::string& name) {
  std::string best, abbreviated;
  size_t best_distance = std::max<size_t>(2, name.size() / 3) + 1;
  lua_pushnil(L);
  while (lua_next(L, table) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING && lua_isfunction(L, -1)) {
      const std::string candidate = lua_tostring(L, -2);
      const size_t distance = edit_distance(name, candidate);
      if (distance < best_distance || (distance == best_distance && candidate < best)) {
        best = candidate;
        best_distance = distance;
      }
      if (is_abbreviation(name, candidate) && (abbreviated.empty() || candidate.size() < abbreviated.size()))
        abbreviated = candidate;
    }
    lua_pop(L, 1);
  }
  return best.empty() ? abbreviated : best;
}

/// __index of a guarded table: upvalue 1 is the prefix ("gr."), upvalue 2 the kind ("gr function").
int unknown_name(lua_State* L) {
  if (lua_type(L, 2) != LUA_TSTRING) return 0;
  const std::string prefix = lua_tostring(L, lua_upvalueindex(1)), kind = lua_tostring(L, lua_upvalueindex(2));
  const std::string name = lua_tostring(L, 2);
  const std::string best = closest_function(L, 1, name);
  throw ArgumentError(prefix + name + " is not a " + kind + (best.empty() ? "" : "; did you mean " + prefix + best + "?"));
}

/// Gives the table on top of the stack a metatable whose __index is unknown_name, and pops it.
void guard_top(lua_State* L, const char* prefix, const char* kind) {
  lua_newtable(L);
  lua_pushstring(L, prefix);
  lua_pushstring(L, kind);
  lua_pushcclosure(L, guarded<unknown_name>, 2);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
  lua_pop(L, 1);
}

/// Pushes the __index table of a userdata type's metatable.
void push_methods(lua_State* L, const char* type) {
  luaL_getmetatable(L, type);
  lua_getfield(L, -1, "__index");
  lua_remove(L, -2);
}

}  // namespace

void guard_gr_names(lua_State* L) {
  lua_getglobal(L, "gr");
  guard_top(L, "gr.", "gr function");
  push_methods(L, kNodeType);
  guard_top(L, "node:", "node method");
  push_methods(L, kMaterialType);
  guard_top(L, "material:", "material method");
}

}  // namespace mjray::lua
