#pragma once
/// Small scenes built in C++ for tests, without Lua.

#include <memory>

#include "mjray/scene/scene_description.h"
#include "mjray/scene/world.h"

namespace mjray::test {

/// The world of `nodes` under `lights`, flattened as the renderer flattens a job.
World flattened_world(std::vector<std::shared_ptr<const SceneNode>> nodes, std::vector<Light> lights);

inline std::shared_ptr<SceneNode> group(std::vector<std::shared_ptr<const SceneNode>> children,
                                        Transform parent_from_node = {}) {
  auto node = std::make_shared<SceneNode>();
  node->name = "group";
  node->parent_from_node = parent_from_node;
  node->children = std::move(children);
  return node;
}

inline std::shared_ptr<SceneNode> sphere(Point3 centre, float radius, Material material = default_material()) {
  auto node = std::make_shared<SceneNode>();
  node->name = "sphere";
  node->shape = UnitSphere{};
  node->node_from_object = Transform::translate({centre.x, centre.y, centre.z}) * Transform::scale(radius, radius, radius);
  node->material = std::make_shared<Material>(material);
  return node;
}

/// An axis-aligned box from lo to hi.
inline std::shared_ptr<SceneNode> box(Point3 lo, Point3 hi, Material material = default_material()) {
  auto node = std::make_shared<SceneNode>();
  node->name = "box";
  node->shape = UnitCube{};
  node->node_from_object = Transform::translate({lo.x, lo.y, lo.z}) * Transform::scale(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z);
  node->material = std::make_shared<Material>(material);
  return node;
}

inline std::shared_ptr<SceneNode> mesh(TriangleMesh data, Material material = default_material(), Transform parent_from_node = {}) {
  auto node = std::make_shared<SceneNode>();
  node->name = "mesh";
  node->mesh = std::make_shared<TriangleMesh>(std::move(data));
  node->material = std::make_shared<Material>(material);
  node->parent_from_node = parent_from_node;
  return node;
}

/// The square [-s, s]² in the plane y = 0 as two triangles, normal +y.
inline TriangleMesh floor_quad(float s) {
  TriangleMesh m;
  m.positions = {{-s, 0, -s}, {s, 0, -s}, {s, 0, s}, {-s, 0, s}};
  m.triangles = {{MeshCorner{0}, MeshCorner{3}, MeshCorner{2}}, {MeshCorner{0}, MeshCorner{2}, MeshCorner{1}}};
  m.polygon_count = 1;
  return m;
}

/// A closed, welded UV sphere of radius 1 (rings × segments).
TriangleMesh uv_sphere(int rings, int segments);

/// The surface of revolution about +y of a closed outline of (radius, height) points, walked
/// with the solid on its left: each outline segment a band of `segments` quads, with normals
/// smooth around the axis and flat along the outline.
TriangleMesh lathe(const std::vector<Point2>& outline, int segments);

}  // namespace mjray::test
