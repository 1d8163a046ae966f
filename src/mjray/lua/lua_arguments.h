#pragma once
/// Reading gr.* arguments from the Lua stack: each reader throws ArgumentError with a message
/// naming the function, the argument and what was found (`guarded` adds the file:line).

#include <array>
#include <cstring>
#include <memory>
#include <new>
#include <string>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

#include "mjray/core/color.h"
#include "mjray/core/vector.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

inline constexpr const char* kNodeType = "gr.node";
inline constexpr const char* kMaterialType = "gr.material";
inline constexpr const char* kLightType = "gr.light";
inline constexpr const char* kTextureType = "gr.texture";

/// Pushes a userdata owning `value`, with the metatable of `type`.
template <class T>
void push_shared(lua_State* L, std::shared_ptr<T> value, const char* type) {
  keep_bytes(L, sizeof(T));
  void* memory = lua_newuserdatauv(L, sizeof(std::shared_ptr<T>), 0);
  new (memory) std::shared_ptr<T>(std::move(value));
  luaL_setmetatable(L, type);
}

/// The shared_ptr inside a userdata of `type`, or null.
template <class T>
std::shared_ptr<T>* test_shared(lua_State* L, int index, const char* type) {
  return static_cast<std::shared_ptr<T>*>(luaL_testudata(L, index, type));
}

/// __gc of a push_shared userdata. It leaves an empty pointer behind, so that a second call
/// does nothing (scripts cannot reach it: new_userdata_type hides the metatable).
template <class T>
int collect_shared(lua_State* L) {
  auto* p = static_cast<std::shared_ptr<T>*>(lua_touserdata(L, 1));
  if (p) *p = nullptr;
  return 0;
}

/// Makes the metatable of a userdata type and leaves it on the stack: `gc` as __gc, the type's
/// name as __name, and __metatable set, so that getmetatable shows a script the name only and
/// no script can call, replace or add a finalizer.
void new_userdata_type(lua_State* L, const char* type, lua_CFunction gc);

/// How the value at `index` reads in a message: "nothing", "nil", "the number 2.5", "the string 'x'",
/// "an empty table", "a table of 2 values", "a gr.light".
std::string describe(lua_State* L, int index);

/// Throws "fn: argument N (what) must be EXPECTED, got ..."; methods ("node:translate")
/// number their arguments after self.
[[noreturn]] void bad_argument(lua_State* L, const char* fn, int index, const char* what, const char* expected);

std::string arg_string(lua_State* L, int index, const char* fn, const char* what);
double arg_number(lua_State* L, int index, const char* fn, const char* what);
/// Reads the {x, y, z} table at `index` into `out`; returns "" or what was found instead.
std::string read_tuple3(lua_State* L, int index, std::array<double, 3>& out);
std::array<double, 3> arg_tuple3(lua_State* L, int index, const char* fn, const char* what);
Point3 arg_point(lua_State* L, int index, const char* fn, const char* what);
Vector3 arg_vector(lua_State* L, int index, const char* fn, const char* what);
/// A colour that reflects (kd, ks, ambient, texture colours); one with a component above 2 is
/// read but warned about (a 0-255 value by mistake).
Color arg_color(lua_State* L, int index, const char* fn, const char* what);
/// A light's colour, which may be any brightness: no warning.
Color arg_light_colour(lua_State* L, int index, const char* fn, const char* what);
/// Warns (once per line) when a colour has a component above 2, which looks like 0-255.
void warn_if_0_to_255(lua_State* L, const Color& colour, const char* fn, const char* what);
/// A light's falloff {c0, c1, c2} into `falloff`; a light that does not fall off with distance
/// has its `colour` checked by warn_if_0_to_255.
void arg_falloff(lua_State* L, int index, const char* fn, const Color& colour, float (&falloff)[3]);
std::shared_ptr<LuaNode>& arg_node(lua_State* L, int index, const char* fn, const char* what);
/// A number as a person writes it: "0", "2.5", "180".
std::string format_number(double value);

}  // namespace mjray::lua
