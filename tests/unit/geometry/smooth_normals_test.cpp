// mesh:set_smooth_normals: angle-weighted vertex normals, creases kept, welded positions.

#include "mjray/geometry/smooth_normals.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace mjray {
namespace {

/// The unit cube [0,1]³ as 12 triangles over 8 shared positions, faces wound outward.
TriangleMesh cube() {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.positions.push_back({float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({MeshCorner{q[0]}, MeshCorner{q[1]}, MeshCorner{q[2]}});
    m.triangles.push_back({MeshCorner{q[0]}, MeshCorner{q[2]}, MeshCorner{q[3]}});
  }
  return m;
}

Vector3 normal_at(const TriangleMesh& m, size_t face, int corner) {
  const int32_t n = m.triangles[face][size_t(corner)].normal;
  EXPECT_GE(n, 0) << "face " << face << " corner " << corner;
  return n < 0 ? Vector3{} : Vector3(m.normals[size_t(n)]);
}

Vector3 face_normal(const TriangleMesh& m, size_t face) {
  const auto& t = m.triangles[face];
  return normalize(cross(m.positions[size_t(t[1].position)] - m.positions[size_t(t[0].position)],
                         m.positions[size_t(t[2].position)] - m.positions[size_t(t[0].position)]));
}

TEST(SmoothNormals, ACubeKeepsItsRightAngleCreasesBelow90Degrees) {
  const TriangleMesh m = with_smooth_normals(cube(), 60);
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vector3 n = normal_at(m, f, k), expected = face_normal(m, f);
      EXPECT_NEAR(n.x, expected.x, 1e-6f) << f << "," << k;
      EXPECT_NEAR(n.y, expected.y, 1e-6f) << f << "," << k;
      EXPECT_NEAR(n.z, expected.z, 1e-6f) << f << "," << k;
    }
  EXPECT_EQ(m.normals.size(), 24u);  // each corner of the cube, once per face around it
  EXPECT_EQ(m.positions, cube().positions);
}

TEST(SmoothNormals, AtEveryAngleACubeCornerPointsAlongItsDiagonalWhateverTheTriangulation) {
  // Each face meets a corner at 90° in all, whether one triangle or two touch it there: with
  // weights by angle, the corner's normal is the diagonal; by count or area it would lean.
  const TriangleMesh m = with_smooth_normals(cube(), 180);
  ASSERT_EQ(m.normals.size(), 8u);
  for (size_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Point3& p = m.positions[size_t(m.triangles[f][size_t(k)].position)];
      const Vector3 expected = normalize(Vector3(p.x - 0.5f, p.y - 0.5f, p.z - 0.5f));
      const Vector3 n = normal_at(m, f, k);
      EXPECT_NEAR(n.x, expected.x, 1e-6f);
      EXPECT_NEAR(n.y, expected.y, 1e-6f);
      EXPECT_NEAR(n.z, expected.z, 1e-6f);
    }
}

TEST(SmoothNormals, ATessellatedSpherePointsOutwardAndTrianglesWrittenApartAreWelded) {
  // A UV sphere of radius 1 written as separate triangles (no shared indices, as an STL).
  TriangleMesh m;
  constexpr int kRings = 12, kSegments = 24;
  const auto at = [](int ring, int segment) {
    if (ring == 0 || ring == kRings) return Point3(0, ring == 0 ? 1.f : -1.f, 0);  // exact poles
    const float theta = float(ring) * std::numbers::pi_v<float> / kRings;
    const float phi = float(segment % kSegments) * 2 * std::numbers::pi_v<float> / kSegments;
    return Point3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  const auto add = [&](Point3 a, Point3 b, Point3 c) {
    const int32_t first = int32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {a, b, c});
    m.triangles.push_back({MeshCorner{first}, MeshCorner{first + 1}, MeshCorner{first + 2}});
  };
  for (int r = 0; r < kRings; ++r)
    for (int s = 0; s < kSegments; ++s) {
      if (r > 0) add(at(r, s), at(r, s + 1), at(r + 1, s));
      if (r + 1 < kRings) add(at(r, s + 1), at(r + 1, s + 1), at(r + 1, s));
    }
  const TriangleMesh smooth = with_smooth_normals(m, 45);
  float worst = 1;
  for (size_t f = 0; f < smooth.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vector3 radial = smooth.positions[size_t(smooth.triangles[f][size_t(k)].position)] - Point3{};
      worst = std::min(worst, dot(normal_at(smooth, f, k), normalize(radial)));
    }
  // Facets are 15° apart; a welded vertex's normal is within a degree or two of the radius.
  EXPECT_GT(worst, std::cos(2.5f * std::numbers::pi_v<float> / 180));
  // One normal per welded vertex: the sphere's (kRings − 1) × kSegments + 2 points.
  EXPECT_EQ(smooth.normals.size(), size_t((kRings - 1) * kSegments + 2));
}

TEST(SmoothNormals, TheTipOfAFanOfManyFacesTakesTheirMeanWithoutComparingEveryPair) {
  // A low cone of 100,000 faces: its tip's corners share the axis; a pairwise comparison
  // would take 10^10 steps.
  TriangleMesh m;
  constexpr int kFaces = 100000;
  m.positions.push_back({0, 0.1f, 0});
  for (int i = 0; i < kFaces; ++i) {
    const float a = 2 * std::numbers::pi_v<float> * float(i) / kFaces;
    m.positions.push_back({std::cos(a), 0, -std::sin(a)});
  }
  for (int i = 0; i < kFaces; ++i) m.triangles.push_back({MeshCorner{0}, MeshCorner{1 + i}, MeshCorner{1 + (i + 1) % kFaces}});
  const TriangleMesh smooth = with_smooth_normals(m, 30);
  const Vector3 tip = normal_at(smooth, 0, 0);
  EXPECT_NEAR(tip.y, 1, 1e-5f);
  EXPECT_EQ(smooth.triangles[kFaces / 2][0].normal, smooth.triangles[0][0].normal);  // one shared normal
}

TEST(SmoothNormals, AFaceWithoutAreaIsLeftFlatAndTakesNoPartInItsNeighbours) {
  TriangleMesh m = cube();
  m.positions.push_back({2, 2, 2});
  m.triangles.push_back({MeshCorner{0}, MeshCorner{8}, MeshCorner{8}});
  const TriangleMesh smooth = with_smooth_normals(m, 180);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(smooth.triangles.back()[size_t(k)].normal, -1);
  const Vector3 n = normal_at(smooth, 0, 0);  // the cube's corner 0 as before
  EXPECT_NEAR(n.x, -1 / std::sqrt(3.f), 1e-6f);
}

}  // namespace
}  // namespace mjray
