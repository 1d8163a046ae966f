// The original mjray project's gr.* extensions (except textures): reflective, refractive,
// Fresnel and glossy materials, area lights, and extended meshes with normals and UVs.

#include <cmath>
#include <string>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

#include "mjray/io/obj_loader.h"
#include "mjray/lua/extended_mesh_tables.h"
#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

constexpr const char* kObjDataType = "gr.objdata";

/// kd, ks, shininess: the first three arguments of every material.
PhongMaterial arg_phong(lua_State* L, const char* fn) {
  return {arg_color(L, 1, fn, "kd"), arg_color(L, 2, fn, "ks"), float(arg_number(L, 3, fn, "shininess"))};
}

float arg_unit(lua_State* L, int index, const char* fn, const char* what) {
  const double value = arg_number(L, index, fn, what);
  if (value < 0 || value > 1) bad_argument(L, fn, index, what, "a number from 0 to 1");
  return float(value);
}

float arg_index_of_refraction(lua_State* L, int index, const char* fn, const char* what) {
  const double value = arg_number(L, index, fn, what);
  if (!(value > 0)) bad_argument(L, fn, index, what, "a positive index of refraction");
  return float(value);
}

int push_material(lua_State* L, Material material) {
  push_shared(L, std::make_shared<Material>(std::move(material)), kMaterialType);
  return 1;
}

int gr_reflectivematerial(lua_State* L) {
  const char* fn = "gr.reflectivematerial";
  return push_material(L, ReflectiveMaterial{arg_phong(L, fn), arg_unit(L, 4, fn, "reflectivity")});
}

int gr_refractedmaterial(lua_State* L) {
  const char* fn = "gr.refractedmaterial";
  return push_material(L, RefractiveMaterial{arg_phong(L, fn), 0, arg_index_of_refraction(L, 4, fn, "eta_i"),
                                             arg_index_of_refraction(L, 5, fn, "eta_t")});
}

int gr_reflectrefractmaterial(lua_State* L) {
  const char* fn = "gr.reflectrefractmaterial";
  return push_material(L, RefractiveMaterial{arg_phong(L, fn), arg_unit(L, 4, fn, "reflectivity"),
                                             arg_index_of_refraction(L, 5, fn, "eta_i"),
                                             arg_index_of_refraction(L, 6, fn, "eta_t")});
}

template <const char* kName>
int gr_fresnelmaterial(lua_State* L) {
  return push_material(L, FresnelMaterial{arg_phong(L, kName), arg_index_of_refraction(L, 4, kName, "eta_i"),
                                          arg_index_of_refraction(L, 5, kName, "eta_t")});
}
constexpr char kFresnelOriginal[] = "gr.fresneldiectricmaterial";  // the original's spelling
constexpr char kFresnelCorrect[] = "gr.fresneldielectricmaterial";

int gr_glossyreflectivematerial(lua_State* L) {
  const char* fn = "gr.glossyreflectivematerial";
  const double samples = arg_number(L, 5, fn, "samples");
  if (samples < 1 || samples > 4096 || samples != std::floor(samples))
    bad_argument(L, fn, 5, "samples", "a whole number from 1 to 4096");
  return push_material(L, GlossyMaterial{arg_phong(L, fn), arg_unit(L, 4, fn, "reflectivity"), int(samples)});
}

int gr_arealight(lua_State* L) {
  const char* fn = "gr.arealight";
  AreaLight light;
  light.corner = arg_point(L, 1, fn, "position");
  light.colour = arg_light_colour(L, 2, fn, "colour");
  arg_falloff(L, 3, fn, light.colour, light.falloff);
  light.edge1 = arg_point(L, 4, fn, "corner1") - light.corner;
  light.edge2 = arg_point(L, 5, fn, "corner2") - light.corner;
  if (!(length(cross(light.edge1, light.edge2)) > 0))
    throw ArgumentError(std::string(fn) + ": the three corners lie on one line, so the light has no area");
  push_shared(L, std::make_shared<Light>(light), kLightType);
  return 1;
}

/// read_extended_obj('file.obj'): the OBJ's positions, normals and UVs, for gr.extendedmesh.
int read_extended_obj(lua_State* L) {
  const std::string name = arg_string(L, 1, "read_extended_obj", "file name");
  const std::filesystem::path path = input_file(L, "read_extended_obj", name);
  std::shared_ptr<const TriangleMesh> mesh;
  try {
    mesh = load_checked_obj(L, path);
  } catch (const SceneError& e) {
    throw ArgumentError(std::string("read_extended_obj: ") + e.what());
  }
  push_shared(L, std::move(mesh), kObjDataType);
  return 1;
}

/// gr.extendedmesh(name, use_uvs, read_extended_obj('file.obj')): a mesh whose vertex
/// normals are interpolated (Phong shading) and whose UVs are kept when use_uvs is true.
/// The mesh data is the built-in reader's, or the tables a scene's own reader returns.
int gr_extendedmesh(lua_State* L) {
  const char* fn = "gr.extendedmesh";
  const std::string name = arg_string(L, 1, fn, "name");
  const bool use_uvs = lua_toboolean(L, 2);
  std::shared_ptr<const TriangleMesh> mesh;
  if (auto* data = test_shared<const TriangleMesh>(L, 3, kObjDataType)) {
    mesh = *data;
  } else if (lua_type(L, 3) == LUA_TTABLE) {
    mesh = read_extended_mesh_tables(L, 3, fn);
  } else {
    bad_argument(L, fn, 3, "mesh data",
                 "the result of read_extended_obj('file.obj'), or a table of positions, normals, uvs and faces");
  }
  if (!use_uvs && !mesh->uvs.empty()) {
    auto copy = std::make_shared<TriangleMesh>(*mesh);
    keep_bytes(L, copy->memory_bytes());
    copy->uvs.clear();
    for (auto& triangle : copy->triangles)
      for (auto& corner : triangle) corner.uv = -1;
    mesh = std::move(copy);
  }
  auto node = std::make_shared<LuaNode>();
  // The original project's scenes, like old-skeleton ones, compose transforms post-multiplied.
  node->old_skeleton_geometry = "the gr.extendedmesh";
  keep_bytes(L, name.size());
  node->name = name;
  node->where = caller_location(L);
  node->mesh = std::move(mesh);
  context(L).nodes.push_back(node);  // so that a cycle through it is broken at the end
  push_shared(L, std::move(node), kNodeType);
  return 1;
}

}  // namespace

void register_extensions(lua_State* L) {
  new_userdata_type(L, kObjDataType, collect_shared<const TriangleMesh>);
  lua_pop(L, 1);

  lua_getglobal(L, "gr");
  static const luaL_Reg functions[] = {
      {"reflectivematerial", guarded<gr_reflectivematerial>},
      {"refractedmaterial", guarded<gr_refractedmaterial>},
      {"reflectrefractmaterial", guarded<gr_reflectrefractmaterial>},
      {"fresneldiectricmaterial", guarded<gr_fresnelmaterial<kFresnelOriginal>>},
      {"fresneldielectricmaterial", guarded<gr_fresnelmaterial<kFresnelCorrect>>},
      {"glossyreflectivematerial", guarded<gr_glossyreflectivematerial>},
      {"arealight", guarded<gr_arealight>},
      {"extendedmesh", guarded<gr_extendedmesh>},
      {nullptr, nullptr}};
  luaL_setfuncs(L, functions, 0);
  lua_pop(L, 1);
  lua_pushcfunction(L, guarded<read_extended_obj>);
  lua_setglobal(L, "read_extended_obj");
}

}  // namespace mjray::lua
