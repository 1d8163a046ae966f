#include "mjray/geometry/smooth_normals.h"

#include <cmath>
#include <numbers>
#include <unordered_map>

#include "mjray/core/error.h"

namespace mjray {

namespace {

/// Equal positions, bit for bit, are one vertex.
struct PositionHash {
  size_t operator()(const Point3& p) const {
    const auto bits = [](float f) { return std::hash<float>{}(f); };
    return bits(p.x) * 73856093u ^ bits(p.y) * 19349663u ^ bits(p.z) * 83492791u;
  }
};
struct PositionEqual {
  bool operator()(const Point3& a, const Point3& b) const { return a.x == b.x && a.y == b.y && a.z == b.z; }
};

/// Above this many faces at a vertex, its corners are not compared pairwise.
constexpr uint32_t kMaxExactValence = 64;

/// The angle of the triangle at corner a, between the edges to b and to c.
float corner_angle(const Point3& a, const Point3& b, const Point3& c) {
  const Vector3 u = b - a, v = c - a;
  return std::atan2(length(cross(u, v)), dot(u, v));
}

}  // namespace

TriangleMesh with_smooth_normals(const TriangleMesh& mesh, float max_angle_degrees) {
  MJRAY_CHECK(max_angle_degrees > 0 && max_angle_degrees <= 180);
  // Compute each face's unit normal (zero when it has no area) and each position's vertex.
  const size_t face_count = mesh.triangles.size();
  std::vector<Vector3> face_normals(face_count);
  for (size_t f = 0; f < face_count; ++f) {
    const auto& t = mesh.triangles[f];
    const Vector3 n = cross(mesh.positions[size_t(t[1].position)] - mesh.positions[size_t(t[0].position)],
                            mesh.positions[size_t(t[2].position)] - mesh.positions[size_t(t[0].position)]);
    const float len = length(n);
    if (len > 0 && std::isfinite(len)) face_normals[f] = n / len;
  }
  std::unordered_map<Point3, uint32_t, PositionHash, PositionEqual> first_of;
  std::vector<uint32_t> vertex_of(mesh.positions.size());
  for (size_t p = 0; p < mesh.positions.size(); ++p)
    vertex_of[p] = first_of.try_emplace(mesh.positions[p], uint32_t(first_of.size())).first->second;

  // Compute the corners around each vertex: (face, corner) pairs, grouped by vertex.
  std::vector<uint32_t> start(first_of.size() + 1, 0);
  for (const auto& t : mesh.triangles)
    for (const MeshCorner& c : t) ++start[vertex_of[size_t(c.position)] + 1];
  for (size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<uint32_t> around(face_count * 3), fill(start.begin(), start.end() - 1);
  for (size_t f = 0; f < face_count; ++f)
    for (uint32_t k = 0; k < 3; ++k)
      around[fill[vertex_of[size_t(mesh.triangles[f][k].position)]]++] = uint32_t(f * 3 + k);

  // Compute each corner's normal from the faces around its vertex within the angle; corners
  // of one vertex that come out equal share one normal.
  const float cos_max = std::cos(max_angle_degrees * std::numbers::pi_v<float> / 180);
  TriangleMesh out = mesh;
  out.normals.clear();
  std::vector<float> angle_at(face_count * 3);
  for (size_t f = 0; f < face_count; ++f)
    for (size_t k = 0; k < 3; ++k) {
      const auto& t = mesh.triangles[f];
      angle_at[f * 3 + k] =
          corner_angle(mesh.positions[size_t(t[k].position)], mesh.positions[size_t(t[(k + 1) % 3].position)],
                       mesh.positions[size_t(t[(k + 2) % 3].position)]);
    }
  for (size_t v = 0; v + 1 < start.size(); ++v) {
    const size_t first_normal = out.normals.size();
    const uint32_t begin = start[v], end = start[v + 1];
    // The normal of the faces at this vertex within the angle of `own`.
    const auto smoothed = [&](const Vector3& own) {
      Vector3 sum;
      for (uint32_t j = begin; j < end; ++j) {
        const Vector3& other = face_normals[around[j] / 3];
        if (other != Vector3{} && dot(own, other) >= cos_max) sum += other * angle_at[around[j]];
      }
      const float len = length(sum);
      return len > 0 ? Normal3(sum / len) : Normal3(own);
    };
    // A vertex shared by very many faces (a fan of thousands) would cost their square: its
    // faces within the angle of their mean share one normal, the rest are flat.
    const bool crowded = end - begin > kMaxExactValence;
    Vector3 mean;
    int32_t mean_index = -1;
    if (crowded) {
      for (uint32_t j = begin; j < end; ++j) mean += face_normals[around[j] / 3] * angle_at[around[j]];
      mean = Vector3(smoothed(length(mean) > 0 ? normalize(mean) : Vector3{}));
    }
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t corner = around[i];
      const Vector3& own = face_normals[corner / 3];
      MeshCorner& target = out.triangles[corner / 3][corner % 3];
      target.normal = -1;
      if (own == Vector3{}) continue;
      if (crowded) {
        // The shared normal once, or the face's own.
        if (mean == Vector3{} || dot(own, mean) < cos_max) {
          target.normal = int32_t(out.normals.size());
          out.normals.push_back(Normal3(own));
          continue;
        }
        if (mean_index < 0) {
          mean_index = int32_t(out.normals.size());
          out.normals.push_back(Normal3(mean));
        }
        target.normal = mean_index;
        continue;
      }
      // Corners of one vertex that come out equal share one normal.
      const Normal3 n = smoothed(own);
      size_t found = first_normal;
      while (found < out.normals.size() && !(out.normals[found] == n)) ++found;
      if (found == out.normals.size()) out.normals.push_back(n);
      target.normal = int32_t(found);
    }
  }
  return out;
}

}  // namespace mjray
