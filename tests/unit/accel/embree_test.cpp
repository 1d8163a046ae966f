// The Embree adapter against the brute-force oracle; in a build without Embree, only the
// error that --accel embree gives.

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/accel/make_accelerator.h"
#include "mjray/core/error.h"
#include "support/scene_builder.h"
#include "unit/accel/accel_oracle.h"

#ifdef MJRAY_HAVE_EMBREE
#include "mjray/accel/bvh.h"
#include "mjray/accel/embree_accelerator.h"
#include "mjray/accel/embree_bvh_builder.h"
#endif

namespace mjray {
namespace {

#ifdef MJRAY_HAVE_EMBREE

using test::OracleCase;
using test::Query;

TriangleMesh one_triangle(const Point3& p0, const Point3& p1, const Point3& p2) {
  TriangleMesh m;
  m.positions = {p0, p1, p2};
  m.triangles = {{MeshCorner{0}, MeshCorner{1}, MeshCorner{2}}};
  return m;
}

void expect_embree_agrees(const std::string& name) {
  const OracleCase* c = test::oracle_case(name);
  if (!c) GTEST_SKIP() << "../shared (models) is absent; set MJRAY_SHARED_DIR to run this test";
  const EmbreeAccelerator embree(*c->prims);
  test::expect_agreement(*c, embree);
  // Embree's (u, v) must be mjray's (b1, b2) wherever both name the same triangle.
  size_t bad_uv = 0;
  for (size_t i = 0; i < c->queries.size(); ++i) {
    const auto& want = c->expected[i];
    if (!want || !c->prims->is_triangle(want->prim)) continue;
    const auto got = embree.intersect(c->queries[i].ray, {0, c->queries[i].t_max});
    if (got && got->prim == want->prim)
      bad_uv += std::abs(got->u - want->u) > 1e-3f || std::abs(got->v - want->v) > 1e-3f;
  }
  EXPECT_EQ(bad_uv, 0u);
}

TEST(EmbreeAgreement, TeapotLow) { expect_embree_agrees("teapot_low"); }
TEST(EmbreeAgreement, BunnyLow) { expect_embree_agrees("bunny_low"); }
TEST(EmbreeAgreement, CornellBox) { expect_embree_agrees("cornell"); }
TEST(EmbreeAgreement, Suzanne) { expect_embree_agrees("suzanne"); }
TEST(EmbreeAgreement, SpotControlMesh) { expect_embree_agrees("spot"); }
TEST(EmbreeAgreement, TransformedSpheresAndCubes) { expect_embree_agrees("shapes"); }
TEST(EmbreeAgreement, MeshesAmongShapes) { expect_embree_agrees("mixed"); }

TEST(EmbreeAgreement, TouchingSurfacesAndRaysLeavingThem) { expect_embree_agrees("surfaces"); }

// Embree traverses; mjray's own tests decide: every hit is brute force's, bit for bit, so that
// images do not depend on the accelerator. Embree's native triangle test orders two hits an ulp
// apart its own way, and at an edge may pick the other triangle.
TEST(EmbreeExactHits, EveryHitIsBruteForcesBitForBit) {
  for (const std::string name : {"surfaces", "cornell", "mixed", "shapes", "teapot_low", "bunny_low", "suzanne", "spot"}) {
    SCOPED_TRACE(name);
    const OracleCase* c = test::oracle_case(name);
    if (!c) GTEST_SKIP() << "../shared (models) is absent; set MJRAY_SHARED_DIR to run this test";
    test::expect_identical_hits(*c, EmbreeAccelerator(*c->prims));
  }
}

// mjray's traversal over a tree from Embree's builder (mjray-bench --tree): a tree built
// elsewhere, with or without split references, still gives brute force's hits bit for bit.
TEST(EmbreeBuiltTree, MjraysTraversalOfItIsBruteForceBitForBit) {
  for (const bool splits : {false, true}) {
    for (const std::string name : {"surfaces", "cornell", "mixed", "shapes", "bunny_low", "spot"}) {
      SCOPED_TRACE(name + (splits ? " with spatial splits" : ""));
      const OracleCase* c = test::oracle_case(name);
      if (!c) GTEST_SKIP() << "../shared (models) is absent; set MJRAY_SHARED_DIR to run this test";
      BvhTree tree = embree_built_tree(*c->prims, {.spatial_splits = splits, .threads = 2});
      // Every primitive is in some leaf, splits or not, and leaves respect the size asked for.
      std::vector<uint32_t> in_leaves = tree.order;
      std::sort(in_leaves.begin(), in_leaves.end());
      in_leaves.erase(std::unique(in_leaves.begin(), in_leaves.end()), in_leaves.end());
      EXPECT_EQ(in_leaves.size(), c->prims->size());
      for (const BvhWideNode& node : tree.nodes)
        for (size_t i = 0; i < size_t(kBvhWidth); ++i)
          if (node.is_leaf(i)) {
            EXPECT_LE(node.count(i), 4u);
          }
      test::expect_identical_hits(*c, Bvh(*c->prims, std::move(tree), 2));
    }
  }
}

TEST(EmbreeBuiltTree, LeavesLargerThanALeafWordHoldsAreRefused) {
  PrimitiveSet world;
  test::add_mesh(world, one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  EXPECT_THROW(embree_built_tree(world, {.max_leaf_size = 8}), SceneError);
  EXPECT_THROW(embree_built_tree(world, {.max_leaf_size = 0}), SceneError);
  const BvhTree tree = embree_built_tree(world, {});
  ASSERT_EQ(tree.nodes.size(), 1u);
  EXPECT_EQ(tree.order, std::vector<uint32_t>{0});
}

TEST(EmbreeAdapter, BarycentricsAreMjrays) {
  PrimitiveSet world;
  test::add_mesh(world, one_triangle({1, 0, 0}, {3, 1, 0}, {1, 4, 1}));
  const EmbreeAccelerator embree(world);
  const Point3 p0{1, 0, 0}, p1{3, 1, 0}, p2{1, 4, 1};
  for (const auto& [b1, b2] : {std::pair{0.2f, 0.3f}, std::pair{0.7f, 0.1f}, std::pair{0.05f, 0.9f}}) {
    const Point3 target = p0 + (p1 - p0) * b1 + (p2 - p0) * b2;
    const Ray ray{{2, 1, -5}, target - Point3{2, 1, -5}};
    const auto hit = embree.intersect(ray, {});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->prim, 0u);
    EXPECT_NEAR(hit->t, 1, 1e-5);
    EXPECT_NEAR(hit->u, b1, 1e-5);
    EXPECT_NEAR(hit->v, b2, 1e-5);
  }
}

TEST(EmbreeAdapter, ShapeIdsFollowTriangles) {
  PrimitiveSet world;
  test::add_mesh(world, one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  world.add_shape(UnitSphere{}, Transform::translate({0, 0, 5}));
  world.add_shape(UnitCube{}, Transform::translate({0, 0, 10}));
  const EmbreeAccelerator embree(world);
  const auto sphere = embree.intersect({{0, 0, 2}, {0, 0, 1}}, {});
  ASSERT_TRUE(sphere);
  EXPECT_EQ(sphere->prim, 1u);
  EXPECT_NEAR(sphere->t, 2, 1e-5);
  const auto cube = embree.intersect({{0.5f, 0.5f, 7}, {0, 0, 1}}, {});
  ASSERT_TRUE(cube);
  EXPECT_EQ(cube->prim, 2u);
  EXPECT_NEAR(cube->t, 3, 1e-5);
  EXPECT_FALSE(embree.occluded({{0.5f, 0.5f, 7}, {0, 0, 1}}, 2.9f));
  EXPECT_TRUE(embree.occluded({{0.5f, 0.5f, 7}, {0, 0, 1}}, 3.1f));
}

TEST(EmbreeAdapter, OriginOnTheSurfaceIsNotAHitAtZero) {
  PrimitiveSet world;
  test::add_mesh(world, one_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  world.add_shape(UnitCube{}, Transform::translate({0, 0, 1}));
  const EmbreeAccelerator embree(world);
  const BruteForce oracle(world);
  const std::vector<Ray> rays = {{{0.25f, 0.25f, 0}, {0, 0, -1}}, {{0.25f, 0.25f, 0}, {0, 0, 1}},
                                 {{0, 0, 0}, {1, 1, 1}},          {{0.5f, 0.5f, 1}, {0, 0, -1}},
                                 {{0.5f, 0.5f, 1}, {0, 0, 1}}};
  for (const Ray& ray : rays) {
    const auto want = oracle.intersect(ray, {});
    const auto got = embree.intersect(ray, {});
    ASSERT_EQ(want.has_value(), got.has_value());
    if (want) {
      EXPECT_GT(got->t, 0);
      EXPECT_EQ(got->prim, want->prim);
      EXPECT_NEAR(got->t, want->t, 1e-5);
    }
  }
}

TEST(EmbreeAdapter, EmptyWorld) {
  const PrimitiveSet world;
  const EmbreeAccelerator embree(world);
  EXPECT_TRUE(embree.bounds().empty());
  EXPECT_FALSE(embree.intersect({{0, 0, -5}, {0, 0, 1}}, {}));
  EXPECT_FALSE(embree.occluded({{0, 0, -5}, {0, 0, 1}}, kInfinity));
}

TEST(EmbreeAdapter, NonFiniteRaysMiss) {
  PrimitiveSet world;
  test::add_mesh(world, one_triangle({-10, -10, 0}, {10, -10, 0}, {0, 10, 0}));
  test::add_random_shapes(world, 10, 5, 3);
  const EmbreeAccelerator embree(world);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = kInfinity;
  const std::vector<Query> queries = {
      {{{nan, 0, -5}, {0, 0, 1}}},   {{{0, 0, -5}, {nan, 0, 1}}}, {{{-inf, 0, -5}, {1, 0, 1}}},
      {{{0, 0, -5}, {inf, 0, 1}}},   {{{0, 0, -5}, {0, 0, 0}}},   {{{0, 0, -5}, {0, 0, 1}}, nan},
      {{{0, 0, -5}, {0, 0, 1}}, 0},  {{{0, 0, -5}, {0, 0, 1}}, -1}};
  for (const Query& q : queries) {
    EXPECT_FALSE(embree.intersect(q.ray, {0, q.t_max})) << test::describe(q);
    EXPECT_FALSE(embree.occluded(q.ray, q.t_max)) << test::describe(q);
  }
}

TEST(EmbreeAdapter, CountsItsMemoryAndIsMadeByName) {
  PrimitiveSet world;
  test::add_mesh(world, test::uv_sphere(32, 64));
  const auto accel = make_accelerator(world, {.kind = "embree"});
  EXPECT_EQ(accel->name(), "embree");
  EXPECT_NE(accelerator_names().find("embree"), std::string::npos);
  // At least the copied vertices and indices, well under a kilobyte per triangle.
  EXPECT_GT(accel->memory_bytes(), world.triangles.size() * 12);
  EXPECT_LT(accel->memory_bytes(), world.triangles.size() * 1024 + (size_t(64) << 20));
}

#else  // no Embree in this build

TEST(EmbreeAdapter, UnavailableBuildExplainsItself) {
  const PrimitiveSet world;
  EXPECT_EQ(accelerator_names().find("embree"), std::string::npos);
  try {
    make_accelerator(world, {.kind = "embree"});
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("not available"), std::string::npos) << e.what();
  }
}

#endif

}  // namespace
}  // namespace mjray
