#pragma once
/// The triangle mesh of a scene description: positions, normals, texture coordinates and
/// faces. io/ readers produce it; scene/ places instances of it in the world.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mjray/core/vector.h"

namespace mjray {

/// One corner of a face: 0-based indices into positions/uvs/normals; -1 when absent.
struct MeshCorner {
  int32_t position = -1;
  int32_t uv = -1;
  int32_t normal = -1;

  constexpr bool operator==(const MeshCorner&) const = default;
};

/// An OBJ file's `mtllib` statement: a material file it names, and the line that names it.
struct MaterialLibrary {
  std::string file;
  int line = 0;
};

/// A mesh in its own (object) frame, polygons fan-triangulated.
struct TriangleMesh {
  std::vector<Point3> positions;                     ///< object space
  std::vector<Normal3> normals;                      ///< object space, as given (not normalised)
  std::vector<Point2> uvs;
  std::vector<std::array<MeshCorner, 3>> triangles;  ///< polygon (c0..cn) → (c0, ci-1, ci)
  size_t polygon_count = 0;  ///< faces as written, before triangulation
  /// OBJ materials: the files `mtllib` names; the names `usemtl` chose, in order of first use,
  /// with the line of that use; and per triangle the index of the name in force (kNoMaterial
  /// before the first `usemtl`). All empty for a file without `usemtl`.
  std::vector<MaterialLibrary> material_libraries;
  std::vector<std::string> material_names;
  std::vector<int> material_name_lines;
  std::vector<uint32_t> triangle_materials;
  static constexpr uint32_t kNoMaterial = UINT32_MAX;

  /// The bytes its arrays hold.
  size_t memory_bytes() const {
    size_t names = 0;
    for (const std::string& name : material_names) names += sizeof(name) + name.size() + sizeof(int);
    for (const MaterialLibrary& library : material_libraries) names += sizeof(library) + library.file.size();
    return positions.size() * sizeof(Point3) + normals.size() * sizeof(Normal3) + uvs.size() * sizeof(Point2) +
           triangles.size() * sizeof(triangles[0]) + triangle_materials.size() * sizeof(uint32_t) + names;
  }
};

}  // namespace mjray
