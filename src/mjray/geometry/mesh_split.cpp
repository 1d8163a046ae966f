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
  // Compute the materials in order, the faces without one last, and each one's faces.
  std::vector<uint32_t> used(mesh.triangle_materials);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<std::vector<uint32_t>> faces(used.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const uint32_t material = mesh.triangle_materials[f];
    faces[size_t(std::lower_bound(used.begin(), used.end(), material) - used.begin())].push_back(uint32_t(f));
  }
  // Compute each part, renumbering through arrays shared by all parts and reset after each
  // from the entries it used, so that many materials cost no more than one.
  std::vector<int32_t> positions(mesh.positions.size(), -1), normals(mesh.normals.size(), -1), uvs(mesh.uvs.size(), -1);
  std::vector<MaterialPart> parts;
  for (size_t p = 0; p < used.size(); ++p) {
    MaterialPart part{used[p], {}};
    std::vector<int32_t> touched_positions, touched_normals, touched_uvs;
    const auto take_tracked = [&](const auto& from, int32_t index, auto& to, std::vector<int32_t>& renumbered,
                                  std::vector<int32_t>& touched) {
      if (index >= 0 && renumbered[size_t(index)] < 0) touched.push_back(index);
      return take(from, index, to, renumbered);
    };
    for (const uint32_t f : faces[p]) {
      std::array<MeshCorner, 3> corners;
      for (size_t k = 0; k < 3; ++k) {
        const MeshCorner& c = mesh.triangles[f][k];
        corners[k] = {take_tracked(mesh.positions, c.position, part.mesh.positions, positions, touched_positions),
                      take_tracked(mesh.uvs, c.uv, part.mesh.uvs, uvs, touched_uvs),
                      take_tracked(mesh.normals, c.normal, part.mesh.normals, normals, touched_normals)};
      }
      part.mesh.triangles.push_back(corners);
    }
    for (const int32_t i : touched_positions) positions[size_t(i)] = -1;
    for (const int32_t i : touched_normals) normals[size_t(i)] = -1;
    for (const int32_t i : touched_uvs) uvs[size_t(i)] = -1;
    part.mesh.polygon_count = part.mesh.triangles.size();
    parts.push_back(std::move(part));
  }
  return parts;
}

}  // namespace mjray
