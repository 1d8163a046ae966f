#include "mjray/geometry/mesh_split.h"

#include <algorithm>

namespace mjray {

namespace {

/// Copies the entries of `from` that the corners use into `to`, once each, renumbering.
template <typename T>
int32_t take(const std::vector<T>& from, int32_t index, std::vector<T>& to, std::vector<int32_t>& renumbered) {
  if (index < 0) return -1;
  int32_t& slot = renumbered[size_t(index)];
  if (slot < 0) {
    slot = int32_t(to.size());
    to.push_back(from[size_t(index)]);
  }
  return slot;
}

}  // namespace

std::vector<MaterialPart> split_by_material(const TriangleMesh& mesh) {
  if (mesh.triangle_materials.empty()) return {{TriangleMesh::kNoMaterial, mesh}};
  // Compute the materials in order, the faces without one last.
  std::vector<uint32_t> used(mesh.triangle_materials);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<MaterialPart> parts;
  for (const uint32_t material : used) {
    MaterialPart part{material, {}};
    std::vector<int32_t> positions(mesh.positions.size(), -1), normals(mesh.normals.size(), -1), uvs(mesh.uvs.size(), -1);
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
      if (mesh.triangle_materials[f] != material) continue;
      std::array<MeshCorner, 3> corners;
      for (size_t k = 0; k < 3; ++k) {
        const MeshCorner& c = mesh.triangles[f][k];
        corners[k] = {take(mesh.positions, c.position, part.mesh.positions, positions),
                      take(mesh.uvs, c.uv, part.mesh.uvs, uvs), take(mesh.normals, c.normal, part.mesh.normals, normals)};
      }
      part.mesh.triangles.push_back(corners);
    }
    part.mesh.polygon_count = part.mesh.triangles.size();
    parts.push_back(std::move(part));
  }
  return parts;
}

}  // namespace mjray
