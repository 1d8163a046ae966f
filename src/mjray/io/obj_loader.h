#pragma once
/// Wavefront OBJ geometry: positions, normals, texture coordinates and faces (fan-triangulated).
/// Materials, groups, lines, points and free-form statements are skipped.

#include <filesystem>
#include <string>
#include <string_view>

#include "mjray/geometry/triangle_mesh.h"

namespace mjray {

/// Reads an OBJ file; throws SceneError naming file and line for malformed input, and a
/// SceneError naming the file when it cannot be opened. `v x y z` (a 4th `w` is ignored),
/// `vn` as written (not normalised), `vt u v` (a 3rd component is ignored).
TriangleMesh load_obj(const std::filesystem::path& path);

/// Parses OBJ text; `source_name` is used in error messages.
TriangleMesh parse_obj(std::string_view text, const std::string& source_name);

}  // namespace mjray
