// The CS 488 `gr.*` scene API: node constructors, node methods, materials, lights and
// gr.render, which snapshots the node graph into a RenderJob.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <string>
#include <unordered_map>
#include <unordered_set>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
}

#include "mjray/camera/camera.h"
#include "mjray/geometry/smooth_normals.h"
#include "mjray/io/obj_loader.h"
#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

// --- node constructors ---------------------------------------------------------------------

int new_node(lua_State* L, const char* fn, std::optional<Shape> shape = std::nullopt,
             Transform node_from_object = {}) {
  auto node = std::make_shared<LuaNode>();
  node->name = arg_string(L, 1, fn, "name");
  keep_bytes(L, node->name.size());
  node->where = caller_location(L);
  node->shape = shape;
  node->node_from_object = node_from_object;
  context(L).nodes.push_back(node);
  push_shared(L, std::move(node), kNodeType);
  return 1;
}

int gr_node(lua_State* L) { return new_node(L, "gr.node"); }
int gr_joint(lua_State* L) { return new_node(L, "gr.joint"); }
int gr_sphere(lua_State* L) { return new_node(L, "gr.sphere", UnitSphere{}); }
int gr_cube(lua_State* L) { return new_node(L, "gr.cube", UnitCube{}); }

/// A radius or edge length: zero (or a value that rounds to zero as a float) would make the
/// shape's transform singular, and a negative one would turn it inside out.
float arg_size(lua_State* L, int index, const char* fn, const char* what) {
  const auto size = float(arg_number(L, index, fn, what));
  if (!(size > 0)) bad_argument(L, fn, index, what, "a positive number");
  return size;
}

int gr_nh_sphere(lua_State* L) {
  const Vector3 centre = arg_vector(L, 2, "gr.nh_sphere", "centre");
  const float radius = arg_size(L, 3, "gr.nh_sphere", "radius");
  return new_node(L, "gr.nh_sphere", UnitSphere{},
                  Transform::translate(centre) * Transform::scale(radius, radius, radius));
}

int gr_nh_box(lua_State* L) {
  const Vector3 corner = arg_vector(L, 2, "gr.nh_box", "corner");
  const float size = arg_size(L, 3, "gr.nh_box", "size");
  return new_node(L, "gr.nh_box", UnitCube{},
                  Transform::translate(corner) * Transform::scale(size, size, size));
}

/// gr.mesh(name, {{x,y,z},...}, {{i,j,k,...},...}) with 0-based convex polygons.
std::shared_ptr<const TriangleMesh> table_mesh(lua_State* L, const char* fn) {
  auto mesh = std::make_shared<TriangleMesh>();
  const auto vertex_count = lua_Integer(lua_rawlen(L, 2));
  for (lua_Integer i = 1; i <= vertex_count; ++i) {
    lua_rawgeti(L, 2, i);
    std::array<double, 3> p{};
    if (const std::string problem = read_tuple3(L, -1, p); !problem.empty())
      throw ArgumentError(std::string(fn) + ": vertex " + std::to_string(i) + " must be a table of 3 numbers, " + problem);
    lua_pop(L, 1);
    mesh->positions.push_back({float(p[0]), float(p[1]), float(p[2])});
  }
  const auto face_count = lua_Integer(lua_rawlen(L, 3));
  std::vector<int32_t> index;
  KeptGrowth kept(L);
  for (lua_Integer f = 1; f <= face_count; ++f) {
    lua_rawgeti(L, 3, f);
    const int face = lua_gettop(L);
    if (lua_type(L, face) != LUA_TTABLE || lua_rawlen(L, face) < 3)
      throw ArgumentError(std::string(fn) + ": face " + std::to_string(f) +
                          " must be a table of at least 3 vertex indices, got " + describe(L, face));
    const auto corners = lua_Integer(lua_rawlen(L, face));
    index.clear();
    for (lua_Integer c = 1; c <= corners; ++c) {
      lua_rawgeti(L, face, c);
      int is_integer = 0;
      const lua_Integer value = lua_tointegerx(L, -1, &is_integer);
      if (!is_integer)
        throw ArgumentError(std::string(fn) + ": face " + std::to_string(f) + " entry " + std::to_string(c) +
                            " must be a whole number (a 0-based vertex index), got " + describe(L, -1));
      lua_pop(L, 1);
      if (value < 0 || value >= vertex_count)
        throw ArgumentError(std::string(fn) + ": face " + std::to_string(f) + " has index " + std::to_string(value) +
                            " outside 0.." + std::to_string(vertex_count - 1));
      index.push_back(int32_t(value));
    }
    lua_pop(L, 1);
    // Fan-triangulate the convex polygon.
    for (size_t k = 2; k < index.size(); ++k)
      mesh->triangles.push_back({MeshCorner{index[0]}, MeshCorner{index[k - 1]}, MeshCorner{index[k]}});
    ++mesh->polygon_count;
    kept.grew_to(mesh->memory_bytes());
  }
  if (mesh->positions.empty() || mesh->triangles.empty())
    throw ArgumentError(std::string(fn) + ": a mesh needs at least one vertex and one face");
  kept.grew_to(mesh->memory_bytes(), true);
  return mesh;
}

std::shared_ptr<const TriangleMesh> file_mesh(lua_State* L, const std::filesystem::path& path, const char* fn) {
  LoaderContext& ctx = context(L);
  const auto key = std::filesystem::weakly_canonical(path);
  auto& cached = ctx.mesh_cache[key];
  try {
    if (!cached) cached = load_checked_obj(L, path);
  } catch (const SceneError& e) {
    // "OBJFILE:LINE: problem" becomes "scene.lua:LINE: gr.mesh: OBJFILE:LINE: problem".
    throw ArgumentError(std::string(fn) + ": " + e.what());
  }
  return cached;
}

int gr_mesh(lua_State* L) {
  const char* fn = "gr.mesh";
  std::shared_ptr<const TriangleMesh> mesh;
  std::filesystem::path file;
  if (lua_type(L, 2) == LUA_TSTRING) {
    file = input_file(L, fn, arg_string(L, 2, fn, "file name"));
    mesh = file_mesh(L, file, fn);
  } else if (lua_type(L, 2) == LUA_TTABLE) {
    if (lua_type(L, 3) != LUA_TTABLE) bad_argument(L, fn, 3, "faces", "a table of faces");
    mesh = table_mesh(L, fn);
  } else {
    bad_argument(L, fn, 2, "mesh", "an OBJ file name, or a vertex table followed by a face table");
  }
  const bool from_tables = lua_type(L, 2) == LUA_TTABLE;
  new_node(L, fn);
  LuaNode& node = **test_shared<LuaNode>(L, -1, kNodeType);
  node.mesh = std::move(mesh);
  node.mesh_file = std::move(file);
  if (from_tables) node.old_skeleton_geometry = "the table-form gr.mesh";
  return 1;
}

// --- node methods --------------------------------------------------------------------------

int node_add_child(lua_State* L) {
  auto& parent = arg_node(L, 1, "node:add_child", "self");
  auto& child = arg_node(L, 2, "node:add_child", "child");
  keep_bytes(L, sizeof(child));
  parent->children.push_back(child);
  return 0;
}

int node_set_material(lua_State* L) {
  auto& node = arg_node(L, 1, "node:set_material", "self");
  auto* material = test_shared<Material>(L, 2, kMaterialType);
  if (!material) bad_argument(L, "node:set_material", 2, "material", "a material");
  node->material = *material;
  return 0;
}

/// mesh:set_smooth_normals(max_angle_degrees): angle-weighted vertex normals for the node's
/// mesh, creases sharper than the angle kept (see geometry/smooth_normals.h). Nodes that
/// share a mesh and an angle share the result.
int node_set_smooth_normals(lua_State* L) {
  const char* fn = "node:set_smooth_normals";
  auto& node = arg_node(L, 1, fn, "self");
  const double degrees = arg_number(L, 2, fn, "max_angle_degrees");
  if (!node->mesh)
    throw ArgumentError(std::string(fn) + ": '" + node->name + "' is not a mesh (gr.mesh or gr.extendedmesh)");
  if (!(degrees > 0 && degrees <= 180))
    throw ArgumentError(std::string(fn) + ": max_angle_degrees must be more than 0 and at most 180, got " +
                        describe(L, 2));
  auto& cached = context(L).smoothed_meshes[{node->mesh, float(degrees)}];
  if (!cached) {
    // The copy's arrays, with a normal per corner at most.
    const TriangleMesh& mesh = *node->mesh;
    keep_bytes(L, mesh.memory_bytes() + mesh.triangles.size() * 3 * sizeof(Normal3));
    cached = std::make_shared<const TriangleMesh>(with_smooth_normals(mesh, float(degrees)));
  }
  node->mesh = cached;
  return 0;
}

int node_translate(lua_State* L) {
  auto& node = arg_node(L, 1, "node:translate", "self");
  const Vector3 d{float(arg_number(L, 2, "node:translate", "x")), float(arg_number(L, 3, "node:translate", "y")),
                  float(arg_number(L, 4, "node:translate", "z"))};
  keep_bytes(L, sizeof(Transform));
  node->transform_calls.push_back(Transform::translate(d));
  return 0;
}

int node_scale(lua_State* L) {
  auto& node = arg_node(L, 1, "node:scale", "self");
  const auto x = float(arg_number(L, 2, "node:scale", "x")), y = float(arg_number(L, 3, "node:scale", "y")),
             z = float(arg_number(L, 4, "node:scale", "z"));
  if (x == 0 || y == 0 || z == 0) throw ArgumentError("node:scale: a scale factor of 0 flattens the node to nothing");
  keep_bytes(L, sizeof(Transform));
  node->transform_calls.push_back(Transform::scale(x, y, z));
  return 0;
}

int node_rotate(lua_State* L) {
  auto& node = arg_node(L, 1, "node:rotate", "self");
  const std::string axis = arg_string(L, 2, "node:rotate", "axis");
  const auto degrees = float(arg_number(L, 3, "node:rotate", "angle"));
  const std::string axes = "xyzXYZ";
  const auto at = axes.find(axis);
  if (axis.size() != 1 || at == std::string::npos)
    throw ArgumentError("node:rotate: axis must be 'x', 'y' or 'z', got '" + axis + "'");
  keep_bytes(L, sizeof(Transform));
  node->transform_calls.push_back(Transform::rotate(int(at % 3), degrees));
  return 0;
}

// --- materials and lights ------------------------------------------------------------------

int gr_material(lua_State* L) {
  const char* fn = "gr.material";
  PhongMaterial m{arg_color(L, 1, fn, "kd"), arg_color(L, 2, fn, "ks"), float(arg_number(L, 3, fn, "shininess"))};
  push_shared(L, std::make_shared<Material>(m), kMaterialType);
  return 1;
}

int gr_light(lua_State* L) {
  const char* fn = "gr.light";
  PointLight light;
  light.position = arg_point(L, 1, fn, "position");
  light.colour = arg_light_colour(L, 2, fn, "colour");
  arg_falloff(L, 3, fn, light.colour, light.falloff);
  push_shared(L, std::make_shared<Light>(light), kLightType);
  return 1;
}

// --- gr.render: snapshot the graph ---------------------------------------------------------

/// Copies the live graph into immutable nodes, composing each node's transform calls by the
/// chosen rule and keeping shared children shared.
class Snapshot {
 public:
  /// Deeper graphs are refused: copying and flattening recurse once per level.
  static constexpr int kMaxDepth = 1000;

  Snapshot(lua_State* L, bool post_multiply) : L_(L), post_multiply_(post_multiply) {}

  /// The bytes of the copies made so far.
  size_t bytes() const { return bytes_; }

  std::shared_ptr<const SceneNode> copy(const std::shared_ptr<LuaNode>& live, int depth = 0) {
    if (auto it = done_.find(live.get()); it != done_.end()) return it->second;
    if (!in_progress_.insert(live.get()).second)
      throw ArgumentError("gr.render: node '" + live->name + "' (created at " + live->where.to_string() +
                          ") is its own ancestor: the scene graph has a cycle");
    if (depth >= kMaxDepth)
      throw ArgumentError("gr.render: the scene graph is nested deeper than " + std::to_string(kMaxDepth) +
                          " levels (at node '" + live->name + "', created at " + live->where.to_string() + ")");
    auto node = std::make_shared<SceneNode>();
    bytes_ += sizeof(SceneNode) + live->name.size() + live->children.size() * sizeof(node);
    node->name = live->name;
    node->where = live->where;
    node->shape = live->shape;
    node->node_from_object = live->node_from_object;
    node->mesh = live->mesh;
    node->material = frozen_material(live->material);
    // Without a material of its own, a mesh takes its OBJ file's.
    if (!node->material && live->mesh && !live->mesh->material_names.empty() && !live->mesh_file.empty())
      node->mesh_parts = obj_mesh_parts(L_, live->where, live->mesh_file, live->mesh);
    for (const Transform& call : live->transform_calls)
      node->parent_from_node = post_multiply_ ? node->parent_from_node * call : call * node->parent_from_node;
    for (const auto& child : live->children) node->children.push_back(copy(child, depth + 1));
    in_progress_.erase(live.get());
    done_[live.get()] = node;
    return node;
  }

 private:
  lua_State* L_;
  bool post_multiply_;
  /// A copy of the material as it is now (a script may still change it, e.g. set a texture
  /// for the next frame); shared materials stay shared within the snapshot.
  std::shared_ptr<const Material> frozen_material(const std::shared_ptr<Material>& live) {
    if (!live) return nullptr;
    auto& copy = materials_[live.get()];
    if (!copy) {
      copy = std::make_shared<const Material>(*live);
      bytes_ += sizeof(Material);
    }
    return copy;
  }

  // Hashed: a scene of 8,000 nodes looks each up several times.
  std::unordered_map<const LuaNode*, std::shared_ptr<const SceneNode>> done_;
  std::unordered_map<const Material*, std::shared_ptr<const Material>> materials_;
  std::unordered_set<const LuaNode*> in_progress_;
  size_t bytes_ = 0;
};

/// Checks the camera here so that the error names the gr.render line; the tests mirror
/// Camera's, which stays the final word.
void check_camera(const RenderJob& job) {
  const CameraDescription& c = job.camera;
  // Scaled to a largest component of 1 first, so that huge or tiny vectors square safely.
  const Vector3 view = c.view / std::max(max_component(abs(c.view)), 1e-38f);
  const Vector3 up = c.up / std::max(max_component(abs(c.up)), 1e-38f);
  if (!(length(view) > 0)) throw ArgumentError("gr.render: the view direction is zero");
  if (!(c.fovy_degrees > 0 && c.fovy_degrees < 180))
    throw ArgumentError("gr.render: fovy must be between 0 and 180 degrees, got " + format_number(c.fovy_degrees));
  const Vector3 forward = normalize(view);
  const Vector3 up_ortho = up - forward * dot(up, forward);
  if (!(length(up_ortho) > 1e-6f * length(up)))
    throw ArgumentError("gr.render: the up vector is parallel to the view direction");
  try {
    Camera(c, job.width, job.height);
  } catch (const SceneError& e) {
    throw ArgumentError(std::string("gr.render: ") + e.what());
  }
}

/// The first node under `root` (depth first, each node once) made by old-skeleton geometry.
const LuaNode* find_old_skeleton_geometry(const LuaNode& root) {
  std::vector<const LuaNode*> pending = {&root};
  std::unordered_set<const LuaNode*> seen;
  while (!pending.empty()) {
    const LuaNode* node = pending.back();
    pending.pop_back();
    if (!seen.insert(node).second) continue;
    if (node->old_skeleton_geometry) return node;
    for (auto it = node->children.rbegin(); it != node->children.rend(); ++it) pending.push_back(it->get());
  }
  return nullptr;
}

/// The automatic rule: post-multiplied for the whole script when the graph its first
/// gr.render draws holds a table-form gr.mesh or a gr.extendedmesh, else pre-multiplied.
bool automatic_transform_order(lua_State* L, const std::shared_ptr<LuaNode>& root, const FileLocation& where) {
  LoaderContext& ctx = context(L);
  if (ctx.post_multiply) return *ctx.post_multiply;
  const LuaNode* found = find_old_skeleton_geometry(*root);
  ctx.post_multiply = found != nullptr;
  if (found)
    ctx.description->notes.push_back(
        where.to_string() + ": node transforms compose post-multiplied (M = M·T, the old course skeleton's order) for "
        "every gr.render of this script, because this scene holds " + found->old_skeleton_geometry + " '" +
        found->name + "' made at " + found->where.to_string() + "; --transform-order pre overrides");
  return found != nullptr;
}

int gr_render(lua_State* L) {
  const char* fn = "gr.render";
  LoaderContext& ctx = context(L);
  RenderJob job;
  job.where = caller_location(L);
  auto& root = arg_node(L, 1, fn, "root node");
  job.output = arg_string(L, 2, fn, "output file");
  if (job.output.empty()) bad_argument(L, fn, 2, "output file", "a file name");
  const double width = arg_number(L, 3, fn, "width"), height = arg_number(L, 4, fn, "height");
  if (width < 1 || height < 1 || width != std::floor(width) || height != std::floor(height) ||
      width > kMaxImageSide || height > kMaxImageSide)
    throw ArgumentError("gr.render: width and height must be whole numbers from 1 to " + std::to_string(kMaxImageSide) + ", got " +
                        format_number(width) + " x " + format_number(height));
  if (width * height > double(kMaxImagePixels))
    throw ArgumentError("gr.render: a " + format_number(width) + " x " + format_number(height) + " image (" +
                        format_number(width * height / 1e6) + " million pixels) needs about " +
                        format_number(std::ceil(width * height * 40 / double(1 << 30))) +
                        " GiB of buffers; the limit is " + format_number(double(kMaxImagePixels) / 1e6) +
                        " million pixels (e.g. 16384 x 8192)");
  job.width = int(width);
  job.height = int(height);
  job.camera.eye = arg_point(L, 5, fn, "eye");
  job.camera.view = arg_vector(L, 6, fn, "view");
  job.camera.up = arg_vector(L, 7, fn, "up");
  job.camera.fovy_degrees = float(arg_number(L, 8, fn, "fovy"));
  job.camera.aperture_radius = ctx.aperture_radius;
  job.camera.focus_distance = ctx.focus_distance;
  job.background = ctx.background;
  job.ambient = arg_color(L, 9, fn, "ambient");
  if (lua_type(L, 10) != LUA_TTABLE) bad_argument(L, fn, 10, "lights", "a table of lights");
  const auto light_count = lua_Integer(lua_rawlen(L, 10));
  if (light_count == 0) throw ArgumentError("gr.render: the lights table is empty (give at least one gr.light)");
  for (lua_Integer i = 1; i <= light_count; ++i) {
    lua_rawgeti(L, 10, i);
    auto* light = test_shared<Light>(L, -1, kLightType);
    if (!light)
      throw ArgumentError("gr.render: lights entry " + std::to_string(i) + " must be a light, got " + describe(L, -1));
    lua_pop(L, 1);
    job.lights.push_back(**light);
  }
  check_camera(job);

  bool post = ctx.options.transform_order == TransformOrder::kPost;
  if (ctx.options.transform_order == TransformOrder::kAuto) post = automatic_transform_order(L, root, job.where);
  Snapshot snapshot(L, post);
  job.root = snapshot.copy(root);
  keep_bytes(L, snapshot.bytes() + job.lights.size() * sizeof(Light));
  job.post_multiplied = post;
  ctx.description->jobs.push_back(std::move(job));
  return 0;
}

int node_tostring(lua_State* L) {
  auto* node = test_shared<LuaNode>(L, 1, kNodeType);
  lua_pushfstring(L, "gr.node '%s'", node ? (*node)->name.c_str() : "?");
  return 1;
}

}  // namespace

void register_gr(lua_State* L) {
  // Node type: methods through __index.
  new_userdata_type(L, kNodeType, collect_shared<LuaNode>);
  static const luaL_Reg node_methods[] = {
      {"add_child", guarded<node_add_child>}, {"set_material", guarded<node_set_material>},
      {"translate", guarded<node_translate>}, {"scale", guarded<node_scale>},
      {"rotate", guarded<node_rotate>},       {"render", guarded<gr_render>},
      {"set_smooth_normals", guarded<node_set_smooth_normals>},
      {nullptr, nullptr}};
  luaL_newlib(L, node_methods);
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, node_tostring);
  lua_setfield(L, -2, "__tostring");
  lua_pop(L, 1);

  new_userdata_type(L, kMaterialType, collect_shared<Material>);
  lua_newtable(L);
  lua_setfield(L, -2, "__index");
  lua_pop(L, 1);
  new_userdata_type(L, kLightType, collect_shared<Light>);
  lua_pop(L, 1);

  static const luaL_Reg gr_functions[] = {
      {"node", guarded<gr_node>},         {"joint", guarded<gr_joint>},
      {"sphere", guarded<gr_sphere>},     {"cube", guarded<gr_cube>},
      {"nh_sphere", guarded<gr_nh_sphere>}, {"nh_box", guarded<gr_nh_box>},
      {"mesh", guarded<gr_mesh>},         {"material", guarded<gr_material>},
      {"light", guarded<gr_light>},       {"render", guarded<gr_render>},
      {nullptr, nullptr}};
  luaL_newlib(L, gr_functions);
  lua_setglobal(L, "gr");
  register_textures(L);
  register_view(L);
  register_lights(L);
}

}  // namespace mjray::lua
