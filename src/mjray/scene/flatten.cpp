#include "mjray/scene/flatten.h"

#include <map>
#include <set>

namespace mjray {

namespace {

double determinant3(const Matrix4& m) {
  const auto& a = m.m;
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

class Flattener {
 public:
  Flattener(World& world, std::vector<std::string>* warnings) : world_(world), warnings_(warnings) {}

  void visit(const SceneNode& node, const Transform& world_from_parent) {
    const Transform world_from_node = world_from_parent * node.parent_from_node;
    if (node.shape != NodeShape::kNone) emit(node, world_from_node);
    for (const auto& child : node.children) visit(*child, world_from_node);
  }

 private:
  uint32_t material_index(const SceneNode& node) {
    const Material* key = node.material.get();
    if (!key && warned_.insert(&node).second && warnings_)
      warnings_->push_back(node.where.to_string() + ": '" + node.name +
                           "' has no material; rendering it grey");
    auto [it, inserted] = material_ids_.try_emplace(key, uint32_t(world_.materials.size()));
    if (inserted) world_.materials.push_back(key ? *key : default_material());
    return it->second;
  }

  void emit(const SceneNode& node, const Transform& world_from_node) {
    const uint32_t material = material_index(node);
    if (node.shape == NodeShape::kMesh) {
      emit_mesh(*node.mesh, world_from_node, material);
      return;
    }
    world_.shapes.push_back({node.shape, world_from_node * node.node_from_object, material, node.node_from_object});
  }

  void emit_mesh(const ObjMesh& mesh, const Transform& world_from_object, uint32_t material) {
    WorldMesh out;
    out.positions.reserve(mesh.positions.size());
    for (const Point3& p : mesh.positions) out.positions.push_back(world_from_object(p));
    out.normals.reserve(mesh.normals.size());
    for (const Normal3& n : mesh.normals) out.normals.push_back(world_from_object(n));
    out.uvs = mesh.uvs;
    out.triangles = mesh.triangles;
    // A mirroring transform reverses the winding; swap two corners to keep normals outward.
    if (determinant3(world_from_object.matrix()) < 0)
      for (auto& tri : out.triangles) std::swap(tri[1], tri[2]);
    out.world_from_object = world_from_object;
    out.material = material;

    const auto mesh_id = uint32_t(world_.meshes.size());
    world_.triangles.reserve(world_.triangles.size() + out.triangles.size());
    for (uint32_t f = 0; f < out.triangles.size(); ++f) world_.triangles.push_back({mesh_id, f});
    world_.meshes.push_back(std::move(out));
  }

  World& world_;
  std::vector<std::string>* warnings_;
  std::map<const Material*, uint32_t> material_ids_;
  std::set<const SceneNode*> warned_;
};

}  // namespace

World flatten(const RenderJob& job, std::vector<std::string>* warnings) {
  World world;
  world.lights = job.lights;
  world.ambient = job.ambient;
  world.background = job.background;
  if (job.root) Flattener(world, warnings).visit(*job.root, Transform());
  return world;
}

}  // namespace mjray
