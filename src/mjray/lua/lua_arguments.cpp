#include "mjray/lua/lua_arguments.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>

namespace mjray::lua {

namespace {

/// `text` as a message shows it, reading back as it was (see escape_control_characters).
std::string printable(std::string_view text) { return escape_control_characters(text, false); }

}  // namespace

void new_userdata_type(lua_State* L, const char* type, lua_CFunction gc) {
  luaL_newmetatable(L, type);
  lua_pushcfunction(L, gc);
  lua_setfield(L, -2, "__gc");
  lua_pushstring(L, type);
  lua_setfield(L, -2, "__name");
  lua_pushstring(L, type);
  lua_setfield(L, -2, "__metatable");
}

// --- argument readers (throw ArgumentError; `guarded` adds the caller's file:line) --------

/// How the value at `index` reads in a message: "nothing", "nil", "the number 2.5", "the string 'x'",
/// "an empty table", "a table of 2 values", "a gr.light".
std::string describe(lua_State* L, int index) {
  index = lua_absindex(L, index);
  switch (lua_type(L, index)) {
    case LUA_TNONE:
      return "nothing";
    case LUA_TNIL:
      return "nil";
    case LUA_TNUMBER:
      return "the number " + (std::isnan(lua_tonumber(L, index)) ? std::string("nan") : format_number(lua_tonumber(L, index)));
    case LUA_TSTRING: {
      constexpr size_t kMaxShown = 40;
      size_t length = 0;
      const char* text = lua_tolstring(L, index, &length);
      if (length == 0) return "an empty string";
      return "the string '" + printable({text, std::min(length, kMaxShown)}) + (length > kMaxShown ? "...'" : "'");
    }
    case LUA_TTABLE: {
      const auto count = lua_rawlen(L, index);
      if (count == 1) return "a table of 1 value";
      if (count > 1) return "a table of " + std::to_string(count) + " values";
      lua_pushnil(L);
      if (lua_next(L, index) == 0) return "an empty table";
      lua_pop(L, 2);
      return "a table without list entries";
    }
    case LUA_TUSERDATA: {
      // Our userdata types carry __name ("gr.node", "gr.material", "gr.light").
      std::string name = "userdata";
      if (const int type = luaL_getmetafield(L, index, "__name"); type != LUA_TNIL) {
        if (type == LUA_TSTRING) name = lua_tostring(L, -1);
        lua_pop(L, 1);
      }
      return "a " + name;
    }
    default:
      return std::string("a ") + lua_typename(L, lua_type(L, index));
  }
}

/// Methods ("node:translate") number their arguments after self, as the script writes them.
[[noreturn]] void bad_argument(lua_State* L, const char* fn, int index, const char* what,
                               const char* expected) {
  const bool method = std::strchr(fn, ':') != nullptr;
  if (method && index == 1)
    throw ArgumentError(std::string(fn) + ": must be called on a node (with ':'), got " + describe(L, index));
  throw ArgumentError(std::string(fn) + ": argument " + std::to_string(method ? index - 1 : index) + " (" + what +
                      ") must be " + expected + ", got " + describe(L, index));
}

/// A string; numbers are accepted and converted, as luaL_checkstring does in the course binding.
/// Control characters are refused: a NUL would cut a file name short where the system reads it
/// (another file than the one checked), and a line break or an escape in a name would reach
/// the terminal raw in messages.
std::string arg_string(lua_State* L, int index, const char* fn, const char* what) {
  const int type = lua_type(L, index);
  if (type != LUA_TSTRING && type != LUA_TNUMBER) bad_argument(L, fn, index, what, "a string");
  size_t length = 0;
  const char* text = lua_tolstring(L, index, &length);
  std::string result(text, length);
  if (std::any_of(result.begin(), result.end(), is_control_character))
    bad_argument(L, fn, index, what, "a string without control characters (such as a NUL, a tab or a line break)");
  return result;
}

namespace {

/// Scene numbers become floats: a larger magnitude would turn into infinity.
bool fits_float(double value) { return std::abs(value) <= double(std::numeric_limits<float>::max()); }

}  // namespace

/// A finite number within float range; numeric strings are accepted, as luaL_checknumber does
/// in the course binding.
double arg_number(lua_State* L, int index, const char* fn, const char* what) {
  int is_number = 0;
  const double value = lua_tonumberx(L, index, &is_number);
  if (!is_number) bad_argument(L, fn, index, what, "a number");
  if (!std::isfinite(value)) bad_argument(L, fn, index, what, "a finite number");
  if (!fits_float(value)) bad_argument(L, fn, index, what, "a number of magnitude at most 3.4e38");
  return value;
}

/// Reads the {x, y, z} table at `index` (exactly 3 finite numbers) into `out`; returns "" or
/// what was found instead ("got ...").
std::string read_tuple3(lua_State* L, int index, std::array<double, 3>& out) {
  index = lua_absindex(L, index);
  if (lua_type(L, index) != LUA_TTABLE || lua_rawlen(L, index) != 3) return "got " + describe(L, index);
  for (int i = 0; i < 3; ++i) {
    lua_rawgeti(L, index, i + 1);
    int is_number = 0;
    out[size_t(i)] = lua_tonumberx(L, -1, &is_number);
    std::string problem;
    if (!is_number) problem = describe(L, -1);
    else if (!std::isfinite(out[size_t(i)])) problem = "not finite";
    else if (!fits_float(out[size_t(i)])) problem = "beyond 3.4e38";
    lua_pop(L, 1);
    if (!problem.empty()) return "got a table whose entry " + std::to_string(i + 1) + " is " + problem;
  }
  return "";
}

std::array<double, 3> arg_tuple3(lua_State* L, int index, const char* fn, const char* what) {
  std::array<double, 3> out{};
  if (const std::string problem = read_tuple3(L, index, out); !problem.empty())
    throw ArgumentError(std::string(fn) + ": argument " + std::to_string(index) + " (" + what +
                        ") must be a table of 3 numbers, " + problem);
  return out;
}

Point3 arg_point(lua_State* L, int index, const char* fn, const char* what) {
  const auto t = arg_tuple3(L, index, fn, what);
  return {float(t[0]), float(t[1]), float(t[2])};
}
Vector3 arg_vector(lua_State* L, int index, const char* fn, const char* what) {
  const auto t = arg_tuple3(L, index, fn, what);
  return {float(t[0]), float(t[1]), float(t[2])};
}
Color arg_color(lua_State* L, int index, const char* fn, const char* what) {
  const Color c = arg_light_colour(L, index, fn, what);
  warn_if_0_to_255(L, c, fn, what);
  return c;
}

Color arg_light_colour(lua_State* L, int index, const char* fn, const char* what) {
  const auto t = arg_tuple3(L, index, fn, what);
  return {float(t[0]), float(t[1]), float(t[2])};
}

void warn_if_0_to_255(lua_State* L, const Color& c, const char* fn, const char* what) {
  constexpr float kFarAboveOne = 2;
  if (std::max({c.r, c.g, c.b}) <= kFarAboveOne) return;
  add_warning(L, std::string(fn) + ": " + what + " {" + format_number(c.r) + ", " + format_number(c.g) + ", " +
                     format_number(c.b) + "} is far above 1; mjray colours run from 0 to 1 (for 0-255 values, "
                     "divide by 255)");
}

void arg_falloff(lua_State* L, int index, const char* fn, const Color& colour, float (&falloff)[3]) {
  const auto given = arg_tuple3(L, index, fn, "falloff");
  for (int i = 0; i < 3; ++i) falloff[i] = float(given[size_t(i)]);
  if (given[1] == 0 && given[2] == 0) warn_if_0_to_255(L, colour, fn, "colour (with no distance falloff)");
}

std::shared_ptr<LuaNode>& arg_node(lua_State* L, int index, const char* fn, const char* what) {
  auto* node = test_shared<LuaNode>(L, index, kNodeType);
  if (!node) bad_argument(L, fn, index, what, "a node");
  return *node;
}

/// A number as a person writes it: "0", "2.5", "180".
std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", value);
  return buffer;
}

}  // namespace mjray::lua
