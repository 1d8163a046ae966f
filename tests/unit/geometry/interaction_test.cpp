// Shading data at hits: interpolated normals and UVs on triangles, UVs on spheres and cubes.

#include <gtest/gtest.h>

#include <memory>

#include "mjray/geometry/box.h"
#include "mjray/scene/flatten.h"
#include "support/scene_builder.h"

namespace mjray {
namespace {

/// The default material with a texture: shading computes texture coordinates only for such.
Material textured_material() {
  PhongMaterial m = std::get<PhongMaterial>(default_material());
  m.texture = std::make_shared<const Texture>(CheckerboardTexture{{1, 1, 1}, {0, 0, 0}, 1});
  return m;
}

/// One triangle with distinct vertex normals and UVs, placed by a transform.
World triangle_world(const Transform& placement, const Material& material = textured_material()) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals = {normalize(Normal3(0, 0, 1)), normalize(Normal3(1, 0, 1)), normalize(Normal3(0, 1, 1))};
  m.uvs = {{0.1f, 0.2f}, {0.9f, 0.3f}, {0.4f, 0.8f}};
  m.triangles = {{MeshCorner{0, 0, 0}, MeshCorner{1, 1, 1}, MeshCorner{2, 2, 2}}};
  RenderJob job;
  job.root = test::mesh(m, material, placement);
  return flatten(job);
}

TEST(Interaction, InterpolatedNormalEqualsTheVertexNormalAtAVertex) {
  const World world = triangle_world({});
  // Barycentrics (b1, b2) = (1, 0) is vertex 1, (0, 1) vertex 2, (0, 0) vertex 0.
  const Ray ray{{0, 0, 5}, {0, 0, -1}};
  const Normal3 expected[] = {normalize(Normal3(0, 0, 1)), normalize(Normal3(1, 0, 1)), normalize(Normal3(0, 1, 1))};
  const float b[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (int v = 0; v < 3; ++v) {
    const SurfaceInteraction si = world.interaction(ray, Hit{5, 0, b[v][0], b[v][1]});
    EXPECT_NEAR(si.shading_normal.x, expected[v].x, 1e-6f) << v;
    EXPECT_NEAR(si.shading_normal.y, expected[v].y, 1e-6f) << v;
    EXPECT_NEAR(si.shading_normal.z, expected[v].z, 1e-6f) << v;
    EXPECT_NEAR(si.geometric_normal.z, 1, 1e-6f);
  }
}

TEST(Interaction, InterpolatedUvsAtVerticesAndCentroid) {
  const World world = triangle_world({});
  const Ray ray{{0, 0, 5}, {0, 0, -1}};
  const SurfaceInteraction at1 = world.interaction(ray, Hit{5, 0, 1, 0});
  EXPECT_FLOAT_EQ(at1.uv.u, 0.9f);
  EXPECT_FLOAT_EQ(at1.uv.v, 0.3f);
  const SurfaceInteraction centroid = world.interaction(ray, Hit{5, 0, 1.f / 3, 1.f / 3});
  EXPECT_NEAR(centroid.uv.u, (0.1f + 0.9f + 0.4f) / 3, 1e-6f);
  EXPECT_NEAR(centroid.uv.v, (0.2f + 0.3f + 0.8f) / 3, 1e-6f);
  EXPECT_NEAR(centroid.point.x, 1.f / 3, 1e-6f);
  EXPECT_NEAR(centroid.point.y, 1.f / 3, 1e-6f);
}

TEST(Interaction, NormalsFollowNonUniformScaleAndMirroring) {
  // Scaling x by −2 mirrors the triangle: the geometric normal must still be the transformed
  // +z, and vertex normals transform by the inverse transpose.
  const World world = triangle_world(Transform::scale(-2, 1, 1));
  // Mirroring swaps two corners to keep the winding; find the vertex that was (1, 0, 0).
  SurfaceInteraction si = world.interaction({{0, 0, 5}, {0, 0, -1}}, Hit{5, 0, 1, 0});
  if (si.point.x > -1) si = world.interaction({{0, 0, 5}, {0, 0, -1}}, Hit{5, 0, 0, 1});
  EXPECT_NEAR(si.point.x, -2, 1e-6f);
  EXPECT_NEAR(si.geometric_normal.z, 1, 1e-6f);
  const Normal3 n1 = normalize(Normal3(-0.5f, 0, 1));  // (1,0,1) under diag(−2,1,1)^−T
  EXPECT_NEAR(si.shading_normal.x, n1.x, 1e-6f);
  EXPECT_NEAR(si.shading_normal.z, n1.z, 1e-6f);
}

TEST(Interaction, AMeshOfPositionsOnlyKeepsNoCornersAndShadesWithItsFaceNormal) {
  // Two triangles, the second in a mirroring placement: its winding is swapped like the
  // corners of a mesh with normals, so both face +z.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{MeshCorner{0}, MeshCorner{1}, MeshCorner{2}}};
  RenderJob job;
  job.root = test::group({test::mesh(m, textured_material()), test::mesh(m, textured_material(), Transform::scale(-2, 1, 1))});
  const World world = flatten(job);
  ASSERT_EQ(world.meshes.size(), 2u);
  for (uint32_t t = 0; t < 2; ++t) {
    const WorldMesh& mesh = world.meshes[t];
    EXPECT_EQ(mesh.first_triangle, t);
    EXPECT_EQ(mesh.triangle_count, 1u);
    EXPECT_TRUE(mesh.corners.empty());
    const SurfaceInteraction si = world.interaction({{-0.1f, 0.1f, 5}, {0, 0, -1}}, Hit{5, t, 0.25f, 0.5f});
    EXPECT_EQ(si.geometric_normal, Normal3(0, 0, 1)) << t;
    EXPECT_EQ(si.shading_normal, si.geometric_normal) << t;
    EXPECT_EQ(si.uv, (Point2{})) << t;
  }
  const auto [p0, p1, p2] = world.primitives.triangle_vertices(1);
  EXPECT_EQ(p0, Point3(0, 0, 0));
  EXPECT_EQ(p1, Point3(0, 1, 0));  // the corners (1, 0, 0) and (0, 1, 0) in swapped order
  EXPECT_EQ(p2, Point3(-2, 0, 0));
}

TEST(Interaction, CubeFacesMapRightAndUpAsSeenFromOutsideToUv) {
  EXPECT_EQ(unit_cube_uv({1, 0.25f, 0.75f}), (Point2{0.25f, 0.25f}));  // +x face: right is −z, up +y
  EXPECT_EQ(unit_cube_uv({0, 0.25f, 0.75f}), (Point2{0.75f, 0.25f}));  // −x face: right is +z
  EXPECT_EQ(unit_cube_uv({0.5f, 0, 0.125f}), (Point2{0.5f, 0.125f}));  // −y face: right +x, up +z
  EXPECT_EQ(unit_cube_uv({0.5f, 1, 0.125f}), (Point2{0.5f, 0.875f}));  // +y face: right +x, up −z
  EXPECT_EQ(unit_cube_uv({0.3f, 0.6f, 1}), (Point2{0.3f, 0.6f}));      // +z face: (x, y)
  EXPECT_EQ(unit_cube_uv({0.25f, 0.6f, 0}), (Point2{0.75f, 0.6f}));    // −z face: right is −x
  EXPECT_EQ(unit_cube_normal({0.3f, 0.6f, 1}), Normal3(0, 0, 1));
  EXPECT_EQ(unit_cube_normal({0, 0.6f, 0.2f}), Normal3(-1, 0, 0));
}

TEST(Interaction, WithoutATextureTheHitIsTheSameButHasNoTextureCoordinates) {
  const World textured = triangle_world({}), plain = triangle_world({}, default_material());
  const Ray ray{{0, 0, 5}, {0, 0, -1}};
  const SurfaceInteraction a = textured.interaction(ray, Hit{5, 0, 0.25f, 0.5f});
  const SurfaceInteraction b = plain.interaction(ray, Hit{5, 0, 0.25f, 0.5f});
  EXPECT_EQ(a.point, b.point);
  EXPECT_EQ(a.point_error, b.point_error);
  EXPECT_EQ(a.geometric_normal, b.geometric_normal);
  EXPECT_EQ(a.shading_normal, b.shading_normal);
  EXPECT_NE(a.uv, (Point2{}));
  EXPECT_EQ(b.uv, (Point2{}));  // never read: no texture
}

TEST(Interaction, SphereHitGivesSphericalUvAndOutwardNormal) {
  RenderJob job;
  job.root = test::sphere({2, 0, 0}, 3, textured_material());
  const World world = flatten(job);
  // Hit the top of the sphere from above: θ = 0 → v = 1; the normal points up.
  const Ray ray{{2, 10, 0}, {0, -1, 0}};
  const SurfaceInteraction si = world.interaction(ray, Hit{7, world.primitive_count() - 1});
  EXPECT_NEAR(si.point.y, 3, 1e-5f);
  EXPECT_NEAR(si.geometric_normal.y, 1, 1e-6f);
  EXPECT_NEAR(si.uv.v, 1, 1e-4f);
  // A hit on the +z side, at the equator: u = 0.75, v = 0.5.
  const SurfaceInteraction side = world.interaction({{2, 0, 10}, {0, 0, -1}}, Hit{7, 0});
  EXPECT_NEAR(side.uv.u, 0.75f, 1e-5f);
  EXPECT_NEAR(side.uv.v, 0.5f, 1e-5f);
}

}  // namespace
}  // namespace mjray
