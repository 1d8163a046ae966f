#pragma once
/// The flat, immutable, world-space scene that accelerators and integrators read.

#include <array>
#include <cstdint>
#include <vector>

#include "mjray/core/color.h"
#include "mjray/core/transform.h"
#include "mjray/geometry/hit.h"
#include "mjray/geometry/primitive_set.h"
#include "mjray/geometry/surface_interaction.h"
#include "mjray/geometry/triangle_mesh.h"
#include "mjray/light/light.h"
#include "mjray/material/material.h"
#include "mjray/scene/background.h"

namespace mjray {

/// The shading data of one mesh instance; its positions are in World::primitives.
struct WorldMesh {
  uint32_t first_triangle = 0;     ///< its triangles are primitives first_triangle + face
  uint32_t triangle_count = 0;
  uint32_t first_vertex = 0;       ///< its positions start here in primitives.vertices
  std::vector<Normal3> normals;    ///< world space, not normalised
  std::vector<Point2> uvs;
  /// Per face, indices local to the mesh. Empty when the mesh has neither normals nor texture
  /// coordinates: there is nothing to interpolate, and a large scanned mesh saves a copy.
  std::vector<std::array<MeshCorner, 3>> corners;
  Transform world_from_object;     ///< for object-space (solid) texturing
  uint32_t material = 0;
};

/// The shading data of one placed shape (its geometry is in World::primitives).
struct WorldShape {
  Transform world_from_object;
  uint32_t material = 0;
  /// Places the unit primitive in its node's frame (nh_sphere/nh_box placement; identity for
  /// gr.sphere/gr.cube): solid textures are evaluated in that frame.
  Transform node_from_object = {};
};

/// The scene as flat arrays: the primitives accelerators index, and what shading needs.
class World {
 public:
  PrimitiveSet primitives;
  std::vector<WorldMesh> meshes;    ///< in primitive order
  std::vector<WorldShape> shapes;   ///< parallel to primitives.shapes
  std::vector<Material> materials;
  std::vector<Light> lights;
  Color ambient;
  Background background;

  uint32_t primitive_count() const { return primitives.size(); }
  /// Shading data at a hit returned for `ray`. Texture coordinates and the object-space
  /// point are filled in only where the material has a texture, the one thing that reads them.
  SurfaceInteraction interaction(const Ray& ray, const Hit& hit) const;
  /// Only the material and the normals of interaction(ray, hit) (the same values): what a
  /// shadow ray crossing a surface asks.
  SurfaceInteraction crossing(const Ray& ray, const Hit& hit) const;
  /// What a ray that leaves the scene sees.
  Color background_radiance(const Vector3& direction) const;

 private:
  const WorldMesh& mesh_of(uint32_t triangle) const;
  bool reads_texture(uint32_t material) const { return phong_of(materials[material]).texture != nullptr; }
  /// interaction (kFull) or crossing.
  template <bool kFull>
  SurfaceInteraction shade(const Ray& ray, const Hit& hit) const;
};

}  // namespace mjray
