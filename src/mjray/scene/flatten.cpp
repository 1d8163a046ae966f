#include "mjray/scene/flatten.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>

#include "mjray/core/available_memory.h"

namespace mjray {

namespace {

double determinant3(const Matrix4& m) {
  const auto& a = m.m;
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
         a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/// Every entry finite and within float range: geometry is stored and intersected as floats.
bool fits_float(const Matrix4& m) {
  for (const auto& row : m.m)
    for (const double x : row)
      if (!(std::abs(x) <= double(std::numeric_limits<float>::max()))) return false;
  return true;
}

/// What one emitted instance of a node costs: primitives plus the mesh vertices it copies (at
/// least 1 for a mesh, which is emitted even when empty, so that every emitted instance counts).
uint64_t own_size(const SceneNode& node) {
  if (!node.mesh_parts.empty()) {
    uint64_t size = 0;
    for (const MeshPart& part : node.mesh_parts)
      size += std::max<uint64_t>(1, part.mesh->triangles.size() + part.mesh->positions.size() + part.mesh->normals.size());
    return size;
  }
  if (node.mesh)
    return std::max<uint64_t>(1, node.mesh->triangles.size() + node.mesh->positions.size() + node.mesh->normals.size());
  return node.shape ? 1 : 0;
}

/// What the scene expands to once every instance is counted.
struct ExpandedSize {
  uint64_t total = 0;   ///< primitives plus the mesh vertices they copy (own_size)
  uint64_t shapes = 0;  ///< shape instances
};

/// A node as the flattener sees it: what it expands to, and its children that emit something.
/// Only those are walked, so that the walk takes time in proportion to what it emits: empty
/// nodes shared down many levels would otherwise be visited once per path, 2^60 times for a
/// script of five lines.
struct ExpandedNode {
  ExpandedSize size;
  std::vector<const SceneNode*> children_that_emit;
};
using ExpandedGraph = std::unordered_map<const SceneNode*, ExpandedNode>;

/// What a flattened scene takes with its acceleration structure, per shape instance and per
/// other element (a triangle or a mesh vertex), as measured on the bench scenes (a field of
/// spheres: about 800 bytes each; the 871k-triangle dragon: about 120 per element).
constexpr uint64_t kBytesPerShape = 800, kBytesPerElement = 120;

/// Refuses, before anything is built, a scene that would not fit in the memory this process
/// may still take: a script of a few lines can instance a node millions of times.
void check_fits_in_memory(const RenderJob& job, const ExpandedSize& size) {
  const uint64_t available = available_memory_bytes();
  if (available == 0 || size.total > (uint64_t(1) << 40)) return;  // unknown; or refused by the size limit
  const uint64_t needed = size.shapes * kBytesPerShape + (size.total - size.shapes) * kBytesPerElement;
  if (needed <= available) return;
  constexpr double kGiB = double(uint64_t(1) << 30);
  char text[160];
  std::snprintf(text, sizeof text, "about %.1f GiB with its acceleration structure, more than the %.1f GiB this "
                "machine has available", double(needed) / kGiB, double(available) / kGiB);
  throw SceneError(job.where, "gr.render: the scene expands to " + std::to_string(size.total) +
                                  " primitives and mesh vertices once every instance is counted, " + text);
}

/// Every node below the root, expanded, counting a node once per path to it (saturating),
/// without recursion: a node DAG can be deeper than the C++ stack and, through shared children,
/// expand exponentially.
ExpandedGraph expanded_graph(const SceneNode& root) {
  constexpr uint64_t kSaturated = std::numeric_limits<uint64_t>::max();
  const auto add = [](uint64_t a, uint64_t b) { return b > kSaturated - a ? kSaturated : a + b; };
  ExpandedGraph graph;
  std::set<const SceneNode*> in_progress;
  std::vector<std::pair<const SceneNode*, bool>> stack{{&root, false}};
  while (!stack.empty()) {
    const auto [node, children_done] = stack.back();
    stack.pop_back();
    if (!children_done) {
      if (graph.count(node)) continue;
      if (!in_progress.insert(node).second)
        throw SceneError(node->where, "node '" + node->name + "' is its own ancestor: the scene graph has a cycle");
      stack.push_back({node, true});
      for (const auto& child : node->children)
        if (!graph.count(child.get())) stack.push_back({child.get(), false});
      continue;
    }
    ExpandedNode expanded{{own_size(*node), node->shape && !node->mesh ? 1u : 0u}, {}};
    ExpandedSize& total = expanded.size;
    for (const auto& child : node->children) {
      const ExpandedSize& below = graph.at(child.get()).size;
      total = {add(total.total, below.total), add(total.shapes, below.shapes)};
      if (below.total > 0) expanded.children_that_emit.push_back(child.get());
    }
    in_progress.erase(node);
    graph.emplace(node, std::move(expanded));
  }
  return graph;
}

class Flattener {
 public:
  Flattener(World& world, std::vector<std::string>* warnings) : world_(world), warnings_(warnings) {}

  /// Emits the DAG below `root` in pre-order, children in order, with an explicit stack of
  /// one entry per level (a node with thousands of children pushes no copies of its transform);
  /// subtrees that emit nothing are skipped.
  void visit(const SceneNode& root, const ExpandedGraph& graph) {
    struct Level {
      const std::vector<const SceneNode*>* children;
      Transform world_from_node;
      size_t next_child = 0;
    };
    std::vector<Level> stack;
    const auto enter = [&](const SceneNode& node, Transform world_from_node) {
      if (node.mesh || node.shape) emit(node, world_from_node);
      const auto& children = graph.at(&node).children_that_emit;
      if (!children.empty()) stack.push_back({&children, std::move(world_from_node)});
    };
    enter(root, Transform() * root.parent_from_node);
    while (!stack.empty()) {
      Level& level = stack.back();
      if (level.next_child == level.children->size()) {
        stack.pop_back();
        continue;
      }
      const SceneNode& child = *(*level.children)[level.next_child++];
      enter(child, level.world_from_node * child.parent_from_node);  // computed before the stack grows
    }
    warn_of_the_rest_without_material();
  }

 private:
  /// Nodes without a material that get a warning of their own; the rest are counted in one.
  static constexpr size_t kNamedWithoutMaterial = 3;

  /// After the walk: one line for the nodes without a material past those named.
  void warn_of_the_rest_without_material() {
    if (!warnings_ || nodes_without_material_.size() <= kNamedWithoutMaterial) return;
    const size_t rest = nodes_without_material_.size() - kNamedWithoutMaterial;
    warnings_->push_back(rest == 1 ? std::string("1 more node has no material; rendering it grey too")
                                   : std::to_string(rest) + " more nodes have no material; rendering them grey too");
  }

  /// The index of `key` (null: the default grey, with a warning for the node).
  uint32_t material_index(const SceneNode& node, const Material* key) {
    if (!key && nodes_without_material_.insert(&node).second && warnings_ &&
        nodes_without_material_.size() <= kNamedWithoutMaterial)
      warnings_->push_back(node.where.to_string() + ": '" + node.name + "' has " +
                           (node.mesh_parts.empty() ? "no material" : "faces without a material in its OBJ file") +
                           "; rendering " + (node.mesh_parts.empty() ? "it" : "them") + " grey");
    auto [it, inserted] = material_ids_.try_emplace(key, uint32_t(world_.materials.size()));
    if (inserted) world_.materials.push_back(key ? *key : default_material());
    return it->second;
  }

  [[noreturn]] static void overflow(const SceneNode& node) {
    throw SceneError(node.where, "'" + node.name + "' is scaled or moved so far (its transforms composed down " +
                                     "the scene graph) that its geometry leaves float range");
  }

  void emit(const SceneNode& node, const Transform& world_from_node) {
    const Transform world_from_object = world_from_node * node.node_from_object;
    if (!fits_float(world_from_object.matrix()) || !fits_float(world_from_object.inverse_matrix())) overflow(node);
    // A mesh that takes its file's materials: each material's faces as a mesh of their own.
    for (const MeshPart& part : node.mesh_parts)
      emit_mesh(node, *part.mesh, world_from_node, material_index(node, part.material.get()));
    if (!node.mesh_parts.empty()) return;
    const uint32_t material = material_index(node, node.material.get());
    if (node.mesh) {
      emit_mesh(node, *node.mesh, world_from_node, material);
      return;
    }
    world_.primitives.add_shape(*node.shape, world_from_object);
    world_.shapes.push_back({world_from_object, material, node.node_from_object});
  }

  void emit_mesh(const SceneNode& node, const TriangleMesh& mesh, const Transform& world_from_object,
                 uint32_t material) {
    PrimitiveSet& prims = world_.primitives;
    WorldMesh out;
    out.first_triangle = uint32_t(prims.triangles.size());
    out.first_vertex = uint32_t(prims.vertices.size());
    prims.vertices.reserve(prims.vertices.size() + mesh.positions.size());
    for (const Point3& p : mesh.positions) {
      prims.vertices.push_back(world_from_object(p));
      if (!is_finite(prims.vertices.back())) overflow(node);
    }
    out.normals.reserve(mesh.normals.size());
    for (const Normal3& n : mesh.normals) out.normals.push_back(world_from_object(n));
    out.uvs = mesh.uvs;
    out.triangle_count = uint32_t(mesh.triangles.size());
    // A mirroring transform reverses the winding; swap two corners to keep normals outward.
    const bool mirrored = determinant3(world_from_object.matrix()) < 0;
    if (!mesh.normals.empty() || !mesh.uvs.empty()) {
      out.corners = mesh.triangles;
      if (mirrored)
        for (auto& tri : out.corners) std::swap(tri[1], tri[2]);
    }
    out.world_from_object = world_from_object;
    out.material = material;

    prims.triangles.reserve(prims.triangles.size() + mesh.triangles.size());
    for (const auto& c : mesh.triangles) {
      const uint32_t second = uint32_t(c[mirrored ? 2 : 1].position), third = uint32_t(c[mirrored ? 1 : 2].position);
      prims.triangles.push_back(
          {out.first_vertex + uint32_t(c[0].position), out.first_vertex + second, out.first_vertex + third});
    }
    world_.meshes.push_back(std::move(out));
  }

  World& world_;
  std::vector<std::string>* warnings_;
  std::map<const Material*, uint32_t> material_ids_;
  std::set<const SceneNode*> nodes_without_material_;
};

/// Flags the primitives whose material lets shadow rays through (none: no flags at all).
void mark_transmissive(World& world) {
  std::vector<uint8_t> by_material(world.materials.size());
  bool any = false;
  for (size_t m = 0; m < world.materials.size(); ++m) any |= (by_material[m] = transmissive(world.materials[m])) != 0;
  if (!any) return;
  PrimitiveSet& prims = world.primitives;
  prims.transmissive_flags.assign(prims.size(), 0);
  for (const WorldMesh& mesh : world.meshes)
    std::fill_n(prims.transmissive_flags.begin() + mesh.first_triangle, mesh.triangle_count, by_material[mesh.material]);
  for (size_t s = 0; s < world.shapes.size(); ++s)
    prims.transmissive_flags[prims.triangles.size() + s] = by_material[world.shapes[s].material];
}

}  // namespace

World flatten(const RenderJob& job, std::vector<std::string>* warnings, uint64_t max_size) {
  World world;
  world.lights = job.lights;
  world.ambient = job.ambient;
  world.background = job.background;
  if (!job.root) return world;
  // Compute the expanded size first, so that a small script instancing a mesh 2^60 times
  // fails at once instead of filling memory.
  const ExpandedGraph graph = expanded_graph(*job.root);
  const ExpandedSize& expanded = graph.at(job.root.get()).size;
  if (const uint64_t size = expanded.total; size > max_size)
    throw SceneError(job.where, "gr.render: the scene expands to " +
                                    (size == std::numeric_limits<uint64_t>::max() ? std::string("more than 10^19")
                                                                                  : std::to_string(size)) +
                                    " primitives and mesh vertices once every instance is counted, more than the "
                                    "limit of " + std::to_string(max_size));
  check_fits_in_memory(job, expanded);
  // Each shape's entries are large: grown by doubling they would be copied and faulted in twice.
  world.shapes.reserve(size_t(expanded.shapes));
  world.primitives.shapes.reserve(size_t(expanded.shapes));
  Flattener(world, warnings).visit(*job.root, graph);
  mark_transmissive(world);
  // A sun's shadow rays start beyond the scene, and its photons cover it.
  if (world.primitive_count() > 0) {
    const Bounds3 box = world.primitives.bounds();
    double diagonal2 = 0;
    for (int a = 0; a < 3; ++a) diagonal2 += double(box.diagonal()[a]) * double(box.diagonal()[a]);
    const double radius = std::sqrt(diagonal2) / 2;
    for (Light& light : world.lights) {
      auto* sun = std::get_if<SunLight>(&light);
      if (!sun) continue;
      if (!(radius < 1e18))
        throw SceneError(job.where, "gr.render: the scene spans more than 10^18 units, too far for gr.sunlight's light "
                                    "to cross it");
      sun->fit_to_scene(box.centre(), float(radius));
    }
  }
  return world;
}

}  // namespace mjray
