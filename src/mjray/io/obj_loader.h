#pragma once
/// Wavefront OBJ geometry: positions, normals, texture coordinates and faces (fan-triangulated),
/// and the material names (`mtllib`, `usemtl`) its faces use. Groups, lines, points and
/// free-form statements are skipped.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "mjray/geometry/triangle_mesh.h"

namespace mjray {

/// How much of a file was OBJ, to tell a file that is not one (counted when asked for).
struct ObjSummary {
  size_t statements = 0;          ///< every statement (comments and blank lines aside)
  size_t unknown_statements = 0;  ///< statements whose keyword OBJ does not have
  std::string first_unknown;      ///< the first such keyword
  int first_unknown_line = 0;
};

/// The bytes load_obj reads and parses at a time.
inline constexpr size_t kObjPieceBytes = size_t(1) << 20;

/// Thrown by load_obj when the mesh would take more than the bytes it may.
struct ObjTooLarge : std::runtime_error {
  explicit ObjTooLarge(size_t mesh_bytes)
      : std::runtime_error("the mesh takes more than the memory it may"), bytes(mesh_bytes) {}
  size_t bytes;  ///< what the mesh held when it was stopped
};

/// Reads an OBJ file; throws SceneError naming file and line for malformed input, and a
/// SceneError naming the file when it cannot be opened. `v x y z` (a 4th `w` is ignored),
/// `vn` as written (not normalised), `vt u v` (a 3rd component is ignored). The file is read
/// `piece_bytes` at a time, and the same mesh comes of any size. Throws ObjTooLarge as soon as
/// the mesh holds more than `max_bytes` (TriangleMesh::memory_bytes), so that a small file of
/// many-cornered faces cannot take gigabytes.
TriangleMesh load_obj(const std::filesystem::path& path, ObjSummary* summary = nullptr,
                      size_t piece_bytes = kObjPieceBytes, size_t max_bytes = SIZE_MAX);

/// Parses OBJ text; `source_name` is used in error messages.
TriangleMesh parse_obj(std::string_view text, const std::string& source_name, ObjSummary* summary = nullptr);

/// For a file a scene draws: throws SceneError("NAME: no vertices ..." / "no faces ...") when
/// the mesh is empty; returns a warning when most statements are not OBJ, else "".
std::string check_obj_content(const TriangleMesh& mesh, const ObjSummary& summary, const std::string& name);

}  // namespace mjray
