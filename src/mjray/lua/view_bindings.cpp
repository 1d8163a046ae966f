// How the gr.render calls after them see the scene: gr.lens (a thin lens for depth of field)
// and gr.background (one colour, a vertical gradient, or an equirectangular environment).

#include <cmath>
#include <memory>
#include <string>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

#include "mjray/io/image_reader.h"
#include "mjray/io/quantise.h"
#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

/// gr.lens(aperture_radius, focus_distance): radius 0 is the pinhole (the distance may then
/// be left out).
int gr_lens(lua_State* L) {
  const char* fn = "gr.lens";
  const double radius = arg_number(L, 1, fn, "aperture radius");
  if (!(radius >= 0) || !std::isfinite(radius)) bad_argument(L, fn, 1, "aperture radius", "a number of at least 0");
  double distance = 0;
  if (radius > 0 || !lua_isnoneornil(L, 2)) {
    distance = arg_number(L, 2, fn, "focus distance");
    if (!(distance > 0) || !std::isfinite(distance)) bad_argument(L, fn, 2, "focus distance", "a positive distance");
  }
  LoaderContext& ctx = context(L);
  ctx.aperture_radius = float(radius);
  ctx.focus_distance = float(distance);
  return 0;
}

/// The environment image `name`, found like every other scene input; 8-bit files are decoded
/// from sRGB with --gamma srgb, as image textures are.
std::shared_ptr<const Image> environment_image(lua_State* L, const std::string& name) {
  const char* fn = "gr.background";
  if (name.empty()) bad_argument(L, fn, 1, "environment image", "a file name");
  const std::filesystem::path path = input_file(L, fn, name);
  std::shared_ptr<Image> image = read_kept_image(L, fn, path, {.keep_16_bits = true});
  if (context(L).options.srgb_textures && !holds_linear_values(path)) decode_srgb_8bit(*image);
  return image;
}

/// gr.background({r,g,b}), gr.background({top}, {bottom}), gr.background('env.exr'), or
/// gr.background() for the default gradient again.
int gr_background(lua_State* L) {
  const char* fn = "gr.background";
  Background background;
  if (lua_type(L, 1) == LUA_TSTRING) {
    background.environment = environment_image(L, arg_string(L, 1, fn, "environment image"));
  } else if (lua_type(L, 1) == LUA_TTABLE) {
    background.zenith = arg_color(L, 1, fn, "colour");
    background.horizon = lua_isnoneornil(L, 2) ? background.zenith : arg_color(L, 2, fn, "bottom colour");
  } else if (!lua_isnone(L, 1)) {
    bad_argument(L, fn, 1, "background", "a colour {r, g, b}, two colours (top, bottom) or an image file name");
  }
  context(L).background = std::move(background);
  return 0;
}

}  // namespace

void register_view(lua_State* L) {
  lua_getglobal(L, "gr");
  static const luaL_Reg functions[] = {
      {"lens", guarded<gr_lens>}, {"background", guarded<gr_background>}, {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
  lua_pop(L, 1);
}

}  // namespace mjray::lua
