#pragma once
/// The flat, immutable, world-space scene that accelerators and integrators read.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mjray/core/bounds.h"
#include "mjray/core/color.h"
#include "mjray/core/transform.h"
#include "mjray/geometry/hit.h"
#include "mjray/io/obj_loader.h"
#include "mjray/light/light.h"
#include "mjray/material/material.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// A mesh instance with its vertices already in world space.
struct WorldMesh {
  std::vector<Point3> positions;   ///< world space
  std::vector<Normal3> normals;    ///< world space, not normalised
  std::vector<Point2> uvs;
  std::vector<std::array<ObjCorner, 3>> triangles;
  Transform world_from_object;     ///< for object-space (solid) texturing
  uint32_t material = 0;
};

/// One triangle of one mesh: a primitive of its own.
struct WorldTriangle {
  uint32_t mesh;
  uint32_t face;
};

/// A transformed unit sphere or unit cube.
struct WorldShape {
  NodeShape kind;
  Transform world_from_object;
  uint32_t material = 0;
  /// Places the unit primitive in its node's frame (nh_sphere/nh_box placement; identity for
  /// gr.sphere/gr.cube): solid textures are evaluated in that frame.
  Transform node_from_object = {};
};

/// Everything the integrator needs to shade a hit, computed once for the closest hit.
struct SurfaceInteraction {
  Point3 point;              ///< world space
  Normal3 geometric_normal;  ///< unit, world space, as the surface is oriented (not flipped)
  Normal3 shading_normal;    ///< unit, world space, on the same side as geometric_normal
  Point2 uv;
  /// The hit in the frame the primitive's geometry is written in, where solid textures are
  /// evaluated: the unit shape's frame for gr.sphere/gr.cube, the node's frame for
  /// nh_sphere/nh_box (whose centre and corner are given there) and meshes.
  Point3 object_point;
  uint32_t material = 0;
};

/// The scene as flat arrays. Primitive ids [0, triangles.size()) are triangles; the rest
/// are shapes, id triangles.size() + index.
class World {
 public:
  std::vector<WorldMesh> meshes;
  std::vector<WorldTriangle> triangles;
  std::vector<WorldShape> shapes;
  std::vector<Material> materials;
  std::vector<Light> lights;
  Color ambient;
  Background background;

  uint32_t primitive_count() const { return uint32_t(triangles.size() + shapes.size()); }
  bool is_triangle(uint32_t prim) const { return prim < triangles.size(); }

  /// The three world-space corners of triangle primitive `prim`.
  std::array<Point3, 3> triangle_vertices(uint32_t prim) const;
  /// World-space bounds of one primitive (Arvo's transformed box for shapes).
  Bounds3 primitive_bounds(uint32_t prim) const;
  /// Bounds of everything.
  Bounds3 bounds() const;
  /// Intersects one primitive for t in (0, t_max).
  std::optional<Hit> intersect_primitive(uint32_t prim, const Ray& ray, float t_max) const;
  /// Shading data at a hit returned for `ray`.
  SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;
  /// What a ray that leaves the scene sees.
  Color background_radiance(const Vector3& direction) const;
};

}  // namespace mjray
