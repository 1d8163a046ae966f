// gr.spotlight and gr.sunlight: the lights beyond the CS 488 point light and the original
// project's area light.

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include <lauxlib.h>
#include <lua.h>

#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180;
/// The widest sun: its samples are uniform over the disc's tangent plane, which is the disc's
/// solid angle only for small discs; a wider light is an area light.
constexpr double kMaxSunDegrees = 20;

/// A unit direction from a non-zero {x, y, z}.
Vector3 arg_direction(lua_State* L, int index, const char* fn, const char* what) {
  const Vector3 v = arg_vector(L, index, fn, what);
  const float len = length(v);
  if (!(len > 0) || !std::isfinite(len))
    throw ArgumentError(std::string(fn) + ": argument " + std::to_string(index) + " (" + what +
                        ") must be a direction, not {0, 0, 0}");
  return v / len;
}

/// An angle in degrees within [low, high] (or (low, high] when low is excluded), or
/// `fallback` when the argument is absent.
double arg_degrees(lua_State* L, int index, const char* fn, const char* what, double low, bool low_included,
                   double high, double fallback) {
  if (lua_isnoneornil(L, index)) return fallback;
  const double degrees = arg_number(L, index, fn, what);
  if (!(low_included ? degrees >= low : degrees > low) || !(degrees <= high))
    throw ArgumentError(std::string(fn) + ": argument " + std::to_string(index) + " (" + what + ") must be " +
                        (low_included ? "from " : "more than ") + format_number(low) +
                        (low_included ? " to " : " and at most ") + format_number(high) + " degrees, got " +
                        describe(L, index));
  return degrees;
}

/// gr.spotlight({pos}, {dir}, {colour}, {c0, c1, c2}, cone_degrees[, penumbra_degrees]).
int gr_spotlight(lua_State* L) {
  const char* fn = "gr.spotlight";
  SpotLight light;
  light.position = arg_point(L, 1, fn, "position");
  light.direction = arg_direction(L, 2, fn, "direction");
  light.colour = arg_light_colour(L, 3, fn, "colour");
  arg_falloff(L, 4, fn, light.colour, light.falloff);
  if (lua_isnoneornil(L, 5)) bad_argument(L, fn, 5, "cone_degrees", "a number");
  const double cone = arg_degrees(L, 5, fn, "cone_degrees", 0, false, 180, 0);
  const double penumbra = arg_degrees(L, 6, fn, "penumbra_degrees", 0, true, 180, 0);
  if (cone + penumbra > 180)  // past the whole sphere
    throw ArgumentError(std::string(fn) + ": the cone (" + format_number(cone) + "°) and its penumbra (" +
                        format_number(penumbra) + "°) together reach past 180°");
  light.cone = float(cone * kRadiansPerDegree);
  light.penumbra = float(penumbra * kRadiansPerDegree);
  push_shared(L, std::make_shared<Light>(light), kLightType);
  return 1;
}

/// gr.sunlight({dir}, {colour}[, angular_diameter_degrees]).
int gr_sunlight(lua_State* L) {
  const char* fn = "gr.sunlight";
  SunLight light;
  light.direction = arg_direction(L, 1, fn, "direction");
  light.colour = arg_light_colour(L, 2, fn, "colour");
  warn_if_0_to_255(L, light.colour, fn, "colour");
  // The sun seen from the Earth spans about 0.53°.
  const double diameter = arg_degrees(L, 3, fn, "angular_diameter_degrees", 0, true, kMaxSunDegrees, 0.53);
  light.half_angle = float(diameter / 2 * kRadiansPerDegree);
  push_shared(L, std::make_shared<Light>(light), kLightType);
  return 1;
}

}  // namespace

void register_lights(lua_State* L) {
  lua_getglobal(L, "gr");
  static const luaL_Reg functions[] = {
      {"spotlight", guarded<gr_spotlight>}, {"sunlight", guarded<gr_sunlight>}, {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
  lua_pop(L, 1);
}

}  // namespace mjray::lua
