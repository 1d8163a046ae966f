#pragma once
/// The triangle mesh of a scene description: positions, normals, texture coordinates and
/// faces. io/ readers produce it; scene/ places instances of it in the world.

#include <array>
#include <cstddef>
#include <cstdint>
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

/// A mesh in its own (object) frame, polygons fan-triangulated.
struct TriangleMesh {
  std::vector<Point3> positions;                     ///< object space
  std::vector<Normal3> normals;                      ///< object space, as given (not normalised)
  std::vector<Point2> uvs;
  std::vector<std::array<MeshCorner, 3>> triangles;  ///< polygon (c0..cn) → (c0, ci-1, ci)
  size_t polygon_count = 0;  ///< faces as written, before triangulation

  /// The bytes its arrays hold.
  size_t memory_bytes() const {
    return positions.size() * sizeof(Point3) + normals.size() * sizeof(Normal3) + uvs.size() * sizeof(Point2) +
           triangles.size() * sizeof(triangles[0]);
  }
};

}  // namespace mjray
