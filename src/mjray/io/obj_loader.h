#pragma once
/// Wavefront OBJ geometry: positions, normals, texture coordinates and faces (fan-triangulated).
/// Materials, groups, lines, points and free-form statements are skipped.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "mjray/core/vector.h"

namespace mjray {

/// One corner of an OBJ face: 0-based indices into positions/uvs/normals; -1 when absent.
struct ObjCorner {
  int32_t position = -1;
  int32_t uv = -1;
  int32_t normal = -1;

  constexpr bool operator==(const ObjCorner&) const = default;
};

/// A mesh as read from an OBJ file, polygons fan-triangulated.
struct ObjMesh {
  std::vector<Point3> positions;                    ///< `v x y z` (a 4th `w` is ignored)
  std::vector<Normal3> normals;                     ///< `vn x y z`, as written (not normalised)
  std::vector<Point2> uvs;                          ///< (u, v); a 3rd vt component is ignored
  std::vector<std::array<ObjCorner, 3>> triangles;  ///< polygon (c0..cn) → (c0, ci-1, ci)
  size_t polygon_count = 0;  ///< faces as written in the file, before triangulation
};

/// Reads an OBJ file; throws SceneError naming file and line for malformed input, and a
/// SceneError naming the file when it cannot be opened.
ObjMesh load_obj(const std::filesystem::path& path);

/// Parses OBJ text; `source_name` is used in error messages.
ObjMesh parse_obj(std::string_view text, const std::string& source_name);

}  // namespace mjray
