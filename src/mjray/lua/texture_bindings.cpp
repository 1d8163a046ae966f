// The original project's textures: gr.checkerboardtexture, the five gr.perlinnoise*texture
// solid textures, gr.filetexture, and material:set_material_texture.

#include <memory>
#include <string>
#include <type_traits>
#include <variant>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

#include "mjray/io/image_reader.h"
#include "mjray/io/quantise.h"
#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"
#include "mjray/texture/texture.h"

namespace mjray::lua {

namespace {

int push_texture(lua_State* L, Texture texture) {
  push_shared(L, std::make_shared<const Texture>(std::move(texture)), kTextureType);
  return 1;
}

float arg_scale(lua_State* L, int index, const char* fn) {
  const double value = arg_number(L, index, fn, "scale");
  if (!(value > 0)) bad_argument(L, fn, index, "scale", "a positive number");
  return float(value);
}

int gr_checkerboardtexture(lua_State* L) {
  const char* fn = "gr.checkerboardtexture";
  return push_texture(L, CheckerboardTexture{arg_color(L, 1, fn, "colour1"), arg_color(L, 2, fn, "colour2"),
                                             arg_scale(L, 3, fn)});
}

/// gr.perlinnoise*texture(colour1, colour2, scale[, noise_multiplier]).
template <const char* kName, PerlinPattern kPattern>
int gr_perlintexture(lua_State* L) {
  PerlinTexture texture{kPattern, arg_color(L, 1, kName, "colour1"), arg_color(L, 2, kName, "colour2"),
                        arg_scale(L, 3, kName)};
  if constexpr (kPattern == PerlinPattern::kWavy)
    texture.noise_multiplier = float(arg_number(L, 4, kName, "noise_multiplier"));
  return push_texture(L, texture);
}
constexpr char kLinear[] = "gr.perlinnoiselininterptexture";
constexpr char kCosine[] = "gr.perlinnoisecosineinterptexture";
constexpr char kMarble[] = "gr.perlinnoisemarbletexture";
constexpr char kWavy[] = "gr.perlinnoisewavytexture";
constexpr char kWood[] = "gr.perlinnoisewoodgraintexture";

/// gr.filetexture('image.png'): a PNG, JPEG or EXR found like every other scene input.
int gr_filetexture(lua_State* L) {
  const char* fn = "gr.filetexture";
  const std::string name = arg_string(L, 1, fn, "file name");
  if (name.empty()) bad_argument(L, fn, 1, "file name", "a file name");
  const std::filesystem::path path = input_file(L, fn, name);
  ImageTexture texture;
  texture.image = std::move(*read_kept_image(L, fn, path, {}));
  if (context(L).options.srgb_textures && !holds_linear_values(path)) decode_srgb_8bit(texture.image);
  return push_texture(L, std::move(texture));
}

/// material:set_material_texture(texture[, 'world' | 'object']): every material's Phong part
/// takes the texture; solid textures read the world-space point unless 'object' is given.
int material_set_material_texture(lua_State* L) {
  const char* fn = "material:set_material_texture";
  auto* material = test_shared<Material>(L, 1, kMaterialType);
  if (!material)
    throw ArgumentError(std::string(fn) + ": must be called on a material (with ':'), got " + describe(L, 1));
  auto* texture = test_shared<const Texture>(L, 2, kTextureType);
  if (!texture) bad_argument(L, fn, 2, "texture", "a texture (gr.checkerboardtexture, gr.perlinnoise...texture or gr.filetexture)");
  TextureSpace space = TextureSpace::kWorld;
  if (!lua_isnoneornil(L, 3)) {
    const std::string name = lua_type(L, 3) == LUA_TSTRING ? lua_tostring(L, 3) : "";
    if (name == "object") space = TextureSpace::kObject;
    else if (name != "world") bad_argument(L, fn, 3, "texture space", "'world' or 'object'");
  }
  std::visit([&](auto& m) {
    PhongMaterial* phong;
    if constexpr (std::is_same_v<std::decay_t<decltype(m)>, PhongMaterial>) phong = &m;
    else phong = &m.base;
    phong->texture = *texture;
    phong->texture_space = space;
  }, **material);
  return 0;
}

}  // namespace

void register_textures(lua_State* L) {
  new_userdata_type(L, kTextureType, collect_shared<const Texture>);
  lua_pop(L, 1);

  // The material method joins the gr.material metatable's __index table.
  luaL_getmetatable(L, kMaterialType);
  lua_getfield(L, -1, "__index");
  lua_pushcfunction(L, guarded<material_set_material_texture>);
  lua_setfield(L, -2, "set_material_texture");
  lua_pop(L, 2);

  lua_getglobal(L, "gr");
  static const luaL_Reg functions[] = {
      {"checkerboardtexture", guarded<gr_checkerboardtexture>},
      {"perlinnoiselininterptexture", guarded<gr_perlintexture<kLinear, PerlinPattern::kLinear>>},
      {"perlinnoisecosineinterptexture", guarded<gr_perlintexture<kCosine, PerlinPattern::kCosine>>},
      {"perlinnoisemarbletexture", guarded<gr_perlintexture<kMarble, PerlinPattern::kMarble>>},
      {"perlinnoisewavytexture", guarded<gr_perlintexture<kWavy, PerlinPattern::kWavy>>},
      {"perlinnoisewoodgraintexture", guarded<gr_perlintexture<kWood, PerlinPattern::kWoodGrain>>},
      {"filetexture", guarded<gr_filetexture>},
      {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
  lua_pop(L, 1);
}

}  // namespace mjray::lua
