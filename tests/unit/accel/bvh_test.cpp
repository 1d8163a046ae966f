#include "mjray/accel/bvh.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <algorithm>
#include <bit>
#include <span>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/accel/brute_force.h"
#include "mjray/accel/bvh_builder.h"
#include "mjray/accel/primitive_list.h"
#include "mjray/geometry/light_pyramid.h"
#include "mjray/accel/make_accelerator.h"
#include "mjray/geometry/primitive_set.h"
#include "mjray/io/obj_loader.h"
#include "support/test_paths.h"
#include "unit/accel/accel_oracle.h"

namespace mjray {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Primitives of one mesh, as flatten makes them.
PrimitiveSet mesh_world(const std::vector<Point3>& positions, const std::vector<std::array<int, 3>>& faces) {
  PrimitiveSet world;
  std::vector<std::array<uint32_t, 3>> indices;
  for (const auto& f : faces) indices.push_back({uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])});
  world.add_triangles(positions, indices);
  return world;
}

PrimitiveSet obj_world(const std::filesystem::path& path) {
  const TriangleMesh obj = load_obj(path);
  std::vector<std::array<int, 3>> faces;
  for (const auto& t : obj.triangles) faces.push_back({t[0].position, t[1].position, t[2].position});
  return mesh_world(obj.positions, faces);
}

// Spheres and cubes under rotations, non-uniform scales and translations, some overlapping.
void add_shapes(PrimitiveSet& world, int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0, 1);
  for (int i = 0; i < count; ++i) {
    const Transform placed =
        Transform::translate({unit(rng) * 10 - 5, unit(rng) * 10 - 5, unit(rng) * 10 - 5}) *
        Transform::rotate(0, unit(rng) * 360) * Transform::rotate(1, unit(rng) * 360) *
        Transform::rotate(2, unit(rng) * 360) *
        Transform::scale(0.2f + unit(rng) * 1.5f, 0.2f + unit(rng) * 0.8f, 0.1f + unit(rng) * 2);
    world.add_shape(i % 2 == 0 ? Shape(UnitSphere{}) : Shape(UnitCube{}), placed);
  }
}

Point3 lerp(const Bounds3& b, float x, float y, float z) {
  const Vector3 d = b.diagonal();
  return {b.lo.x + d.x * x, b.lo.y + d.y * y, b.lo.z + d.z * z};
}

// Rays from outside the (enlarged) bounds through random points inside them, plus rays
// that start inside the bounds in random directions.
std::vector<Ray> random_rays(const Bounds3& bounds, int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0, 1), signed_unit(-1, 1);
  const float radius = length(bounds.diagonal());
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const Point3 target = lerp(bounds, unit(rng), unit(rng), unit(rng));
    if (i % 3 == 2) {
      Vector3 d{signed_unit(rng), signed_unit(rng), signed_unit(rng)};
      rays.push_back({target, d});
      continue;
    }
    Vector3 offset = normalize(Vector3(signed_unit(rng), signed_unit(rng), signed_unit(rng)));
    const Point3 origin = bounds.centre() + offset * radius;
    rays.push_back({origin, (target - origin) * (0.5f + unit(rng))});  // not unit length
  }
  return rays;
}

// Rays that leave the surface where random rays hit it, from exactly the hit point (no
// offset) in random directions: the watertight test's decisions at t near 0 (the own triangle
// and its neighbours, rejected or not by the error bound) are where a leaf's SIMD pre-test
// could first differ from the full test.
std::vector<Ray> surface_rays(const PrimitiveSet& world, int count, uint32_t seed) {
  const BruteForce oracle(world);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> signed_unit(-1, 1);
  std::vector<Ray> rays;
  for (const Ray& ray : random_rays(world.bounds(), count, seed)) {
    const auto hit = oracle.intersect(ray, {});
    if (!hit) continue;
    rays.push_back({ray.origin + ray.direction * hit->t, Vector3(signed_unit(rng), signed_unit(rng), signed_unit(rng))});
  }
  return rays;
}

// A pinhole camera's rays, eye in front of the bounds, looking at their centre.
std::vector<Ray> camera_rays(const Bounds3& bounds, int width, int height) {
  const float radius = length(bounds.diagonal()) * 0.5f;
  const Point3 eye = bounds.centre() + Vector3(0.4f, 0.3f, 2.0f) * radius;
  const Vector3 forward = normalize(bounds.centre() - eye);
  const Vector3 right = normalize(cross(forward, {0, 1, 0}));
  const Vector3 up = cross(right, forward);
  std::vector<Ray> rays;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float px = ((x + 0.5f) / width * 2 - 1) * 0.5f, py = (1 - (y + 0.5f) / height * 2) * 0.5f;
      rays.push_back({eye, normalize(forward + right * px + up * py)});
    }
  return rays;
}

// Rays along ±x, ±y, ±z (other components exactly zero), some from origins on vertex
// coordinates so that they run exactly in bounding planes.
std::vector<Ray> axis_rays(const PrimitiveSet& world, int count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0, 1);
  const Bounds3 b = world.bounds();
  const Vector3 pad = b.diagonal() * 0.1f;
  const Bounds3 outer{b.lo - pad, b.hi + pad};
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const int axis = i % 3;
    const bool negative = (i / 3) % 2 == 1;
    Point3 origin = lerp(outer, unit(rng), unit(rng), unit(rng));
    if (i % 4 == 0 && !world.vertices.empty()) {
      const auto& positions = world.vertices;
      const Point3& v = positions[size_t(unit(rng) * float(positions.size() - 1))];
      origin[(axis + 1) % 3] = v[(axis + 1) % 3];
    }
    origin[axis] = negative ? outer.hi[axis] : outer.lo[axis];
    Vector3 d;
    d[axis] = negative ? -1.f : 1.f;
    rays.push_back({origin, d});
  }
  return rays;
}

// Checks the BVH against the brute-force oracle on every ray: same primitive and t, with the
// exact barycentrics PrimitiveSet::intersect_primitive gives, and occluded() consistent with
// intersect() both unbounded and cut off before the hit. Where two primitives tie (a ray
// through an edge they share, or coplanar faces) the watertight test's rounding decides,
// and its outcome depends on the order of the tests: either primitive is accepted when the
// two t agree to a few ulps and the BVH's hit is exactly what its primitive reports.
void expect_agrees(const PrimitiveSet& world, std::initializer_list<const Bvh*> bvhs, const std::vector<Ray>& rays,
                   const std::string& what) {
  const BruteForce oracle(world);
  int mismatches = 0;
  for (size_t i = 0; i < rays.size() && mismatches < 5; ++i) {
    const Ray& ray = rays[i];
    const auto expected = oracle.intersect(ray, {});
    const float cut = expected ? expected->t * 0.5f : 1.f;
    const bool expected_cut = oracle.occluded(ray, cut);
    for (const Bvh* bvh : bvhs) {
      const auto actual = bvh->intersect(ray, {});
      const std::string where = what + (bvh->uses_avx() ? " (avx)" : " (baseline)") + " ray " + std::to_string(i);
      if (expected.has_value() != actual.has_value()) {
        ADD_FAILURE() << where << ": oracle " << (expected ? "hits" : "misses") << ", bvh "
                      << (actual ? "hits" : "misses");
        ++mismatches;
        continue;
      }
      EXPECT_EQ(bvh->occluded(ray, kInfinity), actual.has_value()) << where;
      EXPECT_EQ(bvh->occluded(ray, cut), expected_cut) << where;
      EXPECT_EQ(bvh->occluded(ray, cut), bvh->intersect(ray, {0, cut}).has_value()) << where;
      if (!expected) continue;
      EXPECT_NEAR(actual->t, expected->t, 1e-4f * expected->t) << where;
      if (expected->prim == actual->prim) {
        EXPECT_EQ(actual->u, expected->u) << where;
        EXPECT_EQ(actual->v, expected->v) << where;
      } else if (std::abs(actual->t - expected->t) > 1e-6f * expected->t) {
        ADD_FAILURE() << where << ": prim " << actual->prim << " at t " << actual->t << ", oracle prim "
                      << expected->prim << " at t " << expected->t;
        ++mismatches;
      } else {
        const auto own = world.intersect(actual->prim, ray, {});
        ASSERT_TRUE(own.has_value()) << where;
        EXPECT_EQ(own->t, actual->t) << where;
        EXPECT_EQ(own->u, actual->u) << where;
        EXPECT_EQ(own->v, actual->v) << where;
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << what;
}

void expect_agrees(const PrimitiveSet& world, const Bvh& bvh, const std::vector<Ray>& rays, const std::string& what) {
  expect_agrees(world, {&bvh}, rays, what);
}

void expect_agrees_all_kinds(const PrimitiveSet& world, int random_count, int camera_side, const std::string& what) {
  // Both traversal variants where the CPU has AVX; the baseline twice otherwise.
  const Bvh best(world, 0), baseline(world, 0, BvhSimd::kBaseline);
  const Bounds3 b = world.bounds();
  expect_agrees(world, {&best, &baseline}, random_rays(b, random_count, 7), what + " random");
  expect_agrees(world, {&best, &baseline}, camera_rays(b, camera_side, camera_side), what + " camera");
  expect_agrees(world, {&best, &baseline}, axis_rays(world, random_count / 4, 11), what + " axis-parallel");
  expect_agrees(world, {&best, &baseline}, surface_rays(world, random_count / 2, 13), what + " from surfaces");
}

TEST(BvhOracle, AgreesWithBruteForceOnRealMeshes) {
  MJRAY_REQUIRE_SHARED(shared);
  // About 80k rays over four meshes (130k with the tests below), sized so the oracle stays fast.
  expect_agrees_all_kinds(obj_world(shared / "models/small/teapot_low_npm.obj"), 12000, 80, "teapot");
  expect_agrees_all_kinds(obj_world(shared / "models/small/bunny_low_npm.obj"), 4000, 50, "bunny");
  expect_agrees_all_kinds(obj_world(shared / "models/medium/suzanne.obj"), 10000, 80, "suzanne");
  expect_agrees_all_kinds(obj_world(shared / "models/small/cornell/cornell_box.obj"), 20000, 100, "cornell");
}

TEST(BvhOracle, AgreesWithBruteForceOnTransformedShapes) {
  PrimitiveSet world;
  add_shapes(world, 120, 3);
  expect_agrees_all_kinds(world, 16000, 100, "shapes");
}

TEST(BvhOracle, AgreesWithBruteForceOnMeshesMixedWithShapes) {
  MJRAY_REQUIRE_SHARED(shared);
  PrimitiveSet world = obj_world(shared / "models/small/teapot_low_npm.obj");
  add_shapes(world, 40, 5);
  expect_agrees_all_kinds(world, 12000, 60, "teapot+shapes");
}

TEST(BvhOracle, AgreesWithBruteForceOnALargerMesh) {
  MJRAY_REQUIRE_SHARED(shared);
  const PrimitiveSet world = obj_world(shared / "models/medium/dragon_vrip_res4.obj");
  const Bvh bvh(world, 2);
  expect_agrees(world, bvh, random_rays(world.bounds(), 1500, 13), "dragon random");
}

// Not only near: the same primitive at the same float t, as brute force, wherever two surfaces
// touch or a ray leaves one; images must not depend on the accelerator.
TEST(BvhOracle, EveryHitIsBruteForcesBitForBit) {
  for (const std::string name : {"surfaces", "cornell", "mixed", "shapes", "teapot_low", "bunny_low", "suzanne", "spot"}) {
    SCOPED_TRACE(name);
    const test::OracleCase* c = test::oracle_case(name);
    if (!c) GTEST_SKIP() << "../shared (models) is absent; set MJRAY_SHARED_DIR to run this test";
    test::expect_identical_hits(*c, Bvh(*c->prims, 0));
    test::expect_identical_hits(*c, Bvh(*c->prims, 0, BvhSimd::kBaseline));
  }
}

TEST(BvhBuild, ParallelBuildEqualsSerialBuild) {
  MJRAY_REQUIRE_SHARED(shared);
  // 203k triangles: large enough for forked subtrees and for binning shared among threads.
  const PrimitiveSet world = obj_world(shared / "models/large/dragon_vrip_res2.obj");
  const Bvh serial(world, 1);
  for (int threads : {2, 3, 8}) {
    const Bvh parallel(world, threads);
    EXPECT_EQ(serial.node_count(), parallel.node_count()) << threads;
    ASSERT_EQ(serial.layout().size(), parallel.layout().size()) << threads;
    EXPECT_EQ(std::memcmp(serial.layout().data(), parallel.layout().data(), serial.layout().size()), 0) << threads;
  }
}

// Unit boxes on a lattice with gaps: the kind of scene where a leaf's box holds much empty space.
std::vector<Bounds3> lattice_of_boxes(int n) {
  std::vector<Bounds3> boxes;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Point3 lo{1.5f * float(i), 1.5f * float(j), 1.5f * float(k)};
        boxes.push_back({lo, {lo.x + 1, lo.y + 1, lo.z + 1}});
      }
  return boxes;
}

BvhTree build_over(const std::vector<Bounds3>& boxes, const BvhBuildOptions& options) {
  return build_bvh(uint32_t(boxes.size()), [&](uint32_t prim) { return boxes[prim]; }, options);
}

double mean_leaf_size(const BvhTree& built, uint32_t from, uint32_t to) {
  double primitives = 0, leaves = 0;
  for (const BvhWideNode& node : built.nodes)
    for (size_t i = 0; i < size_t(kBvhWidth); ++i) {
      if (!node.is_leaf(i) || built.order[node.first(i)] < from || built.order[node.first(i)] >= to) continue;
      primitives += node.count(i);
      ++leaves;
    }
  return primitives / leaves;
}

TEST(BvhBuild, ShapesCostlierThanTrianglesGetSmallerLeaves) {
  const std::vector<Bounds3> boxes = lattice_of_boxes(12);
  const uint32_t n = uint32_t(boxes.size());
  const BvhTree as_triangles = build_over(boxes, {.threads = 1});
  const BvhTree as_shapes = build_over(boxes, {.threads = 1, .shapes_from = 0});
  EXPECT_GT(mean_leaf_size(as_triangles, 0, n), 2.0);
  EXPECT_LT(mean_leaf_size(as_shapes, 0, n), 0.75 * mean_leaf_size(as_triangles, 0, n));

  // A shape costing one triangle test builds the triangles' tree exactly.
  const BvhTree unit_cost = build_over(boxes, {.threads = 1, .shapes_from = 0, .shape_cost = 1});
  ASSERT_EQ(unit_cost.nodes.size(), as_triangles.nodes.size());
  EXPECT_EQ(std::memcmp(unit_cost.nodes.data(), as_triangles.nodes.data(), unit_cost.nodes.size() * sizeof(BvhWideNode)), 0);
  EXPECT_EQ(unit_cost.order, as_triangles.order);

  // Mixed: a second lattice beside the first is of shapes; only its leaves shrink.
  std::vector<Bounds3> mixed = boxes;
  for (const Bounds3& b : boxes) mixed.push_back({b.lo + Vector3(100, 0, 0), b.hi + Vector3(100, 0, 0)});
  const BvhTree both = build_over(mixed, {.threads = 1, .shapes_from = n});
  EXPECT_LT(mean_leaf_size(both, n, 2 * n), mean_leaf_size(both, 0, n));
}

// Random small triangles and a few shapes: a tree several levels deep with leaves of all sizes.
PrimitiveSet scattered_world(int triangles, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0, 1);
  std::vector<Point3> positions;
  std::vector<std::array<int, 3>> faces;
  for (int i = 0; i < triangles; ++i) {
    const Point3 p{unit(rng) * 10, unit(rng) * 10, unit(rng) * 10};
    const int base = int(positions.size());
    positions.insert(positions.end(), {p, p + Vector3(unit(rng), 0, unit(rng)), p + Vector3(0, unit(rng), unit(rng))});
    faces.push_back({base, base + 1, base + 2});
  }
  PrimitiveSet world = mesh_world(positions, faces);
  add_shapes(world, 12, seed + 1);
  return world;
}

// The trees' surface-area cost (a node 2, a primitive 1) may fall as the builder improves, never
// rise: a change that makes worse trees shows here before it shows in rays per second. The
// bounds are the builder's costs when this test was written (bench/results/HISTORY.md, "Trees").
TEST(BvhBuild, TreesCostNoMoreThanTheBinnedSahTreesOfRecord) {
  MJRAY_REQUIRE_SHARED(shared);
  for (const auto& [mesh, cost] : {std::pair{"small/teapot.obj", 18.6806}, std::pair{"small/bunny.obj", 23.9357}}) {
    const PrimitiveSet world = obj_world(shared / "models" / mesh);
    for (int threads : {1, 2}) EXPECT_LE(Bvh(world, threads).sah_cost(2, 1), cost) << mesh << " " << threads;
  }
}

// 70k triangles without ../shared: subtrees forked and spliced, binning shared among threads.
TEST(BvhBuild, ParallelBuildOfAScatteredWorldEqualsSerialBuild) {
  const PrimitiveSet world = scattered_world(70000, 11);
  const Bvh serial(world, 1);
  for (int threads : {2, 3}) {
    const Bvh parallel(world, threads);
    ASSERT_EQ(serial.layout().size(), parallel.layout().size()) << threads;
    EXPECT_EQ(std::memcmp(serial.layout().data(), parallel.layout().data(), serial.layout().size()), 0) << threads;
  }
}

// More primitives than a leaf word can index are refused before any is asked for.
TEST(BvhBuild, TooManyPrimitivesAreRefusedBeforeAnyWork) {
  const auto never = [](uint32_t) -> Bounds3 {
    ADD_FAILURE() << "a primitive's bounds were asked for";
    return {};
  };
  for (const size_t count : {size_t(BvhWideNode::kMaxLeafPrimitives) + 1, (size_t(1) << 32) + 1})
    EXPECT_THROW(build_bvh(count, never, {}), std::length_error) << count;
}

TEST(BvhBuild, OnePrimitiveIsALeafUnderARootAndNoneIsNoNode) {
  const PrimitiveSet world = scattered_world(1, 3);
  const BvhTree one = build_bvh(1, [&](uint32_t prim) { return world.primitive_bounds(prim); }, {.threads = 2});
  ASSERT_EQ(one.nodes.size(), 1u);
  EXPECT_EQ(one.nodes[0].child[0], BvhWideNode::leaf_word(0, 1));
  EXPECT_EQ(one.bounds.lo, world.primitive_bounds(0).lo);
  EXPECT_EQ(one.bounds.hi, world.primitive_bounds(0).hi);
  for (size_t i = 1; i < size_t(kBvhWidth); ++i) {
    EXPECT_EQ(one.nodes[0].child[i], 0u) << i;  // unused: word 0 and an empty box
    EXPECT_GT(one.nodes[0].bounds[0][i], one.nodes[0].bounds[3][i]) << i;
  }
  EXPECT_EQ(one.order, std::vector<uint32_t>{0});
  EXPECT_TRUE(build_bvh(0, [&](uint32_t prim) { return world.primitive_bounds(prim); }, {}).nodes.empty());
}

TEST(BvhLayout, EachNodeIsFollowedByItsLeavesRunsInDepthFirstOrder) {
  const PrimitiveSet world = scattered_world(3000, 43);
  const Bvh bvh(world, 2);
  ASSERT_GT(bvh.node_count(), 20u);
  const std::span<const std::byte> layout = bvh.layout();
  std::vector<size_t> node_starts;
  std::vector<uint32_t> inner_children;
  std::vector<int> seen(world.size(), 0);
  size_t at = 0;
  for (size_t n = 0; n < bvh.node_count(); ++n) {
    // A node starts on a 32-byte boundary, right after the previous node's runs.
    ASSERT_EQ(at % BvhLayout::kNodeAlignment, 0u);
    node_starts.push_back(at);
    BvhWideNode node;
    std::memcpy(&node, layout.data() + at, sizeof node);
    at += sizeof node;
    for (size_t c = 0; c < size_t(kBvhWidth); ++c) {
      if (!node.is_leaf(c)) {
        if (node.bounds[0][c] <= node.bounds[3][c]) inner_children.push_back(node.child[c]);
        continue;
      }
      // Its leaves' runs follow it, in slot order, end to end.
      ASSERT_EQ(size_t(node.first(c)) * BvhLayout::kPlaceBytes, at) << "node " << n << " slot " << c;
      const LeafRun run = LeafRun::of(layout.data(), node.child[c]);
      for (uint32_t i = 0; i < run.count; ++i) {
        const uint32_t prim = run.prim(i);
        ASSERT_LT(prim, world.size());
        ++seen[prim];
        if (!world.is_triangle(prim)) continue;
        const auto v = world.triangle_vertices(prim);
        for (uint32_t k = 0; k < 3; ++k) EXPECT_EQ(std::bit_cast<Point3>(run.corner(k, i)), v[k]);
      }
      at += run.count * LeafRun::kBytesPerPrimitive;
    }
    at = (at + BvhLayout::kNodeAlignment - 1) / BvhLayout::kNodeAlignment * BvhLayout::kNodeAlignment;
  }
  EXPECT_EQ(at + BvhLayout::kPadding, layout.size());
  EXPECT_EQ(bvh.memory_bytes(), layout.size());
  // Every primitive is in exactly one leaf, and every inner child names a node's start that
  // comes after its parent's (depth first: the root is first, and a child follows its parent).
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int count) { return count == 1; }));
  for (uint32_t child : inner_children) {
    const size_t place = size_t(child) * BvhLayout::kPlaceBytes;
    EXPECT_TRUE(std::binary_search(node_starts.begin(), node_starts.end(), place)) << place;
    EXPECT_GT(place, 0u);
  }
  EXPECT_EQ(inner_children.size(), bvh.node_count() - 1);
}

TEST(BvhBuild, MemoryStaysWithinBudgetPerTriangle) {
  MJRAY_REQUIRE_SHARED(shared);
  const PrimitiveSet world = obj_world(shared / "models/medium/dragon_vrip_res3.obj");
  const Bvh bvh(world, 0);
  EXPECT_EQ(bvh.leaf_primitive_count(), world.triangles.size());
  EXPECT_LE(double(bvh.memory_bytes()) / double(world.triangles.size()), 70.0);
  EXPECT_GT(bvh.memory_bytes(), world.triangles.size() * LeafRun::kLeafFloats * sizeof(float));
}

TEST(BvhBuild, BoundsMatchTheWorld) {
  MJRAY_REQUIRE_SHARED(shared);
  const PrimitiveSet world = obj_world(shared / "models/small/bunny_low_npm.obj");
  const Bvh bvh(world, 0);
  EXPECT_EQ(bvh.bounds().lo, world.bounds().lo);
  EXPECT_EQ(bvh.bounds().hi, world.bounds().hi);
  EXPECT_EQ(bvh.name(), "bvh");
}

TEST(BvhBuild, MakeAcceleratorBuildsTheBvh) {
  const PrimitiveSet world = mesh_world({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const auto accel = make_accelerator(world, {.kind = "bvh", .threads = 1});
  EXPECT_EQ(accel->name(), "bvh");
  EXPECT_TRUE(accel->intersect({{0.2f, 0.2f, 1}, {0, 0, -1}}, {}).has_value());
}

// A tree made by hand: a root with two leaves, one triangle each, in the two halves of a
// 2×1×1 box. Half-areas (xy + yz + zx): the root 5, each half 3.
BvhTree two_leaf_tree() {
  BvhTree tree;
  tree.bounds = {{0, 0, 0}, {2, 1, 1}};
  BvhWideNode root = BvhWideNode::without_children();
  for (size_t i = 0; i < 2; ++i) {
    root.set_bounds(i, {{float(i), 0, 0}, {float(i + 1), 1, 1}});
    root.child[i] = BvhWideNode::leaf_word(uint32_t(i), 1);
  }
  tree.nodes.push_back(root);
  tree.order = {0, 1};
  return tree;
}

TEST(BvhSahCost, IsTheAreaWeightedCostOfEveryBoxEntered) {
  const PrimitiveSet world = mesh_world({{0, 0, 0.5f}, {1, 0, 0.5f}, {0, 1, 0.5f}, {2, 0, 0.5f}, {1, 1, 0.5f}},
                                        {{0, 1, 2}, {1, 3, 4}});
  const Bvh bvh(world, two_leaf_tree(), 1);
  // The root's visit, then each leaf's one primitive with probability 3/5.
  EXPECT_DOUBLE_EQ(bvh.sah_cost(2, 1), 2 + 2 * (3.0 / 5));
  EXPECT_DOUBLE_EQ(bvh.sah_cost(1, 3), 1 + 3 * 2 * (3.0 / 5));
  // mjray's own build of one triangle: a root whose one leaf has the root's box.
  const PrimitiveSet one = mesh_world({{0, 0, 0}, {1, 0, 0}, {0, 1, 1}}, {{0, 1, 2}});
  EXPECT_DOUBLE_EQ(Bvh(one, 1).sah_cost(2, 1), 3);
}

TEST(BvhSahCost, EmptyTreeCostsNothing) {
  const PrimitiveSet empty;
  EXPECT_EQ(Bvh(empty, 1).sah_cost(2, 1), 0);
}

TEST(BvhPrebuiltTree, IsTraversedAsGiven) {
  const PrimitiveSet world = mesh_world({{0, 0, 0.5f}, {1, 0, 0.5f}, {0, 1, 0.5f}, {2, 0, 0.5f}, {1, 1, 0.5f}},
                                        {{0, 1, 2}, {1, 3, 4}});
  for (const BvhSimd simd : {BvhSimd::kBest, BvhSimd::kBaseline}) {
    const Bvh bvh(world, two_leaf_tree(), 1, simd);
    EXPECT_EQ(bvh.leaf_primitive_count(), 2u);
    EXPECT_EQ(bvh.bounds().hi, (Point3{2, 1, 1}));
    const auto a = bvh.intersect({{0.2f, 0.2f, -1}, {0, 0, 1}}, {0, kInfinity});
    const auto b = bvh.intersect({{1.2f, 0.2f, -1}, {0, 0, 1}}, {0, kInfinity});
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->prim, 0u);
    EXPECT_EQ(b->prim, 1u);
    EXPECT_EQ(a->t, BruteForce(world).intersect({{0.2f, 0.2f, -1}, {0, 0, 1}}, {0, kInfinity})->t);
    EXPECT_NEAR(a->t, 1.5f, 1e-6f);
    EXPECT_FALSE(bvh.intersect({{1.8f, 0.8f, -1}, {0, 0, 1}}, {0, kInfinity}));
  }
}

TEST(BvhLayout, ATreeFromElsewhereIsLaidOutAlike) {
  // The hand-made tree's array has no room reserved for the layout: it grows by a copy.
  const PrimitiveSet world = mesh_world({{0, 0, 0.5f}, {1, 0, 0.5f}, {0, 1, 0.5f}, {2, 0, 0.5f}, {1, 1, 0.5f}},
                                        {{0, 1, 2}, {1, 3, 4}});
  const Bvh bvh(world, two_leaf_tree(), 1);
  BvhWideNode root;
  std::memcpy(&root, bvh.layout().data(), sizeof root);
  EXPECT_EQ(root.child[0], BvhWideNode::leaf_word(sizeof(BvhWideNode) / BvhLayout::kPlaceBytes, 1));
  EXPECT_EQ(root.child[1],
            BvhWideNode::leaf_word((sizeof(BvhWideNode) + LeafRun::kBytesPerPrimitive) / BvhLayout::kPlaceBytes, 1));
  // 224 + 80 bytes, rounded up to 32, then the padding.
  EXPECT_EQ(bvh.layout().size(), 320 + BvhLayout::kPadding);
}

TEST(BvhEdgeCases, EmptyWorldHasNoHitsAndEmptyBounds) {
  const PrimitiveSet world;
  const Bvh bvh(world, 0);
  EXPECT_TRUE(bvh.bounds().empty());
  EXPECT_EQ(bvh.node_count(), 0u);
  EXPECT_TRUE(bvh.layout().empty());
  EXPECT_FALSE(bvh.intersect({{0, 0, 0}, {0, 0, 1}}, {}).has_value());
  EXPECT_FALSE(bvh.occluded({{0, 0, 0}, {0, 0, 1}}, kInfinity));
}

TEST(BvhEdgeCases, OneTriangle) {
  const PrimitiveSet world = mesh_world({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const Bvh bvh(world, 0);
  const auto hit = bvh.intersect({{0.25f, 0.5f, 2}, {0, 0, -1}}, {});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->prim, 0u);
  EXPECT_FLOAT_EQ(hit->t, 2);
  EXPECT_FLOAT_EQ(hit->u, 0.25f);
  EXPECT_FLOAT_EQ(hit->v, 0.5f);
  EXPECT_FALSE(bvh.intersect({{0.25f, 0.5f, 2}, {0, 0, -1}}, {0, 1.5f}).has_value());
  EXPECT_FALSE(bvh.intersect({{0.75f, 0.75f, 2}, {0, 0, -1}}, {}).has_value());
  EXPECT_TRUE(bvh.occluded({{0.25f, 0.25f, -1}, {0, 0, 1}}, kInfinity));
  expect_agrees(world, bvh, random_rays(world.bounds(), 2000, 17), "one triangle");
}

TEST(BvhEdgeCases, OneSphere) {
  PrimitiveSet world;
  world.add_shape(UnitSphere{}, Transform::translate({1, 2, 3}) * Transform::scale(2, 1, 0.5f));
  const Bvh bvh(world, 0);
  const auto hit = bvh.intersect({{1, 2, 10}, {0, 0, -1}}, {});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->prim, 0u);
  EXPECT_NEAR(hit->t, 6.5f, 1e-5f);
  expect_agrees(world, bvh, random_rays(world.bounds(), 2000, 19), "one sphere");
}

TEST(BvhEdgeCases, ManyIdenticalTriangles) {
  // All centroids equal: the build must fall back to splitting by count and terminate.
  const std::vector<Point3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<int, 3>> faces(5000, {0, 1, 2});
  const PrimitiveSet world = mesh_world(positions, faces);
  const Bvh bvh(world, 2);
  EXPECT_EQ(bvh.leaf_primitive_count(), faces.size());
  const auto hit = bvh.intersect({{0.2f, 0.2f, 1}, {0, 0, -1}}, {});
  ASSERT_TRUE(hit.has_value());
  EXPECT_FLOAT_EQ(hit->t, 1);
  EXPECT_LT(hit->prim, faces.size());
  expect_agrees(world, bvh, random_rays(world.bounds(), 300, 23), "identical triangles");
}

TEST(BvhEdgeCases, DegenerateTrianglesNeverHitAndDoNotDisturbOthers) {
  // Zero-area triangles (repeated and collinear corners) between ordinary ones.
  std::vector<Point3> positions;
  std::vector<std::array<int, 3>> faces;
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> unit(0, 1);
  for (int i = 0; i < 600; ++i) {
    const int base = int(positions.size());
    const Point3 p{unit(rng) * 4, unit(rng) * 4, unit(rng) * 4};
    const Vector3 a{unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f};
    const Vector3 b{unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f};
    positions.insert(positions.end(), {p, p + a, i % 3 == 0 ? p + a * 2 : (i % 3 == 1 ? p : p + b)});
    faces.push_back({base, base + 1, base + 2});
  }
  const PrimitiveSet world = mesh_world(positions, faces);
  const Bvh bvh(world, 0);
  const auto rays = random_rays(world.bounds(), 6000, 31);
  expect_agrees(world, bvh, rays, "degenerate");
  for (const Ray& ray : rays) {
    if (const auto hit = bvh.intersect(ray, {})) {
      EXPECT_EQ(hit->prim % 3, 2u);
    }
  }
}

TEST(BvhEdgeCases, NonFiniteTrianglesAreHarmless) {
  // Bounds3 drops NaN coordinates (min/max), so the NaN triangle keeps finite bounds and
  // stays in; the infinite one is left out. Neither can be hit.
  std::vector<Point3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                   {kNaN, 0, 0}, {1, 1, 0}, {0, 1, 1},
                                   {kInfinity, 0, 0}, {1, 0, 1}, {0, 1, -1}};
  const PrimitiveSet world = mesh_world(positions, {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
  const Bvh bvh(world, 0);
  EXPECT_EQ(bvh.leaf_primitive_count(), 2u);
  expect_agrees(world, bvh, random_rays({{-1, -1, -1}, {2, 2, 2}}, 2000, 37), "non-finite");
}

TEST(BvhEdgeCases, NanAndInfiniteRaysMissWithoutCrashing) {
  MJRAY_REQUIRE_SHARED(shared);
  PrimitiveSet world = obj_world(shared / "models/small/teapot_low_npm.obj");
  add_shapes(world, 10, 41);
  const Bvh best(world, 0), baseline(world, 0, BvhSimd::kBaseline);
  const Point3 c = world.bounds().centre();
  const std::vector<Ray> rays = {
      {{kNaN, 0, 0}, {0, 0, 1}},          {{c.x, c.y, c.z}, {kNaN, 0, 1}},
      {{c.x, c.y, c.z}, {kNaN, kNaN, kNaN}}, {{kInfinity, 0, 0}, {-1, 0, 0}},
      {{c.x, c.y, c.z}, {kInfinity, 1, 0}}, {{c.x, c.y, c.z}, {-kInfinity, kInfinity, kInfinity}},
      {{c.x, c.y, c.z}, {0, 0, 0}},
  };
  const Ray good{{c.x, c.y, c.z + 100}, {0, 0, -1}};
  // A tiny but finite direction is a valid ray: t scales up, the hit stays.
  const Ray tiny{good.origin, {0, 1e-32f, -1e-30f}};
  for (const Bvh* bvh : {&best, &baseline}) {
    for (const Ray& ray : rays) {
      EXPECT_FALSE(bvh->intersect(ray, {}).has_value());
      EXPECT_FALSE(bvh->occluded(ray, kInfinity));
    }
    EXPECT_TRUE(bvh->intersect(tiny, {}).has_value());
    EXPECT_FALSE(bvh->intersect(good, {0, kNaN}).has_value());
    EXPECT_FALSE(bvh->intersect(good, {0, 0}).has_value());
    EXPECT_FALSE(bvh->intersect(good, {0, -1}).has_value());
  }
  expect_agrees(world, {&best, &baseline}, {tiny, {good.origin, {0, 0, -1e-30f}}, good}, "tiny direction");
}

TEST(BvhEdgeCases, RaysFromInsideAClosedMeshAlwaysHit) {
  // A watertight cube of 12 triangles: rays from inside, including through edges and
  // corners, must hit.
  const PrimitiveSet world = mesh_world(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
      {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
       {3, 6, 2}, {3, 7, 6}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}});
  const Bvh bvh(world, 0);
  std::mt19937 rng(43);
  std::uniform_real_distribution<float> unit(0.01f, 0.99f), signed_unit(-1, 1);
  for (int i = 0; i < 5000; ++i) {
    const Point3 origin{unit(rng), unit(rng), unit(rng)};
    const Point3 target = i % 2 ? Point3(float(i % 3 == 0), float(i % 5 < 2), signed_unit(rng) > 0)
                                : Point3(unit(rng), 1, unit(rng));
    const Ray ray{origin, target - origin};
    EXPECT_TRUE(bvh.intersect(ray, {}).has_value()) << i;
    EXPECT_TRUE(bvh.occluded(ray, kInfinity)) << i;
  }
  expect_agrees(world, bvh, axis_rays(world, 2000, 47), "cube");
}

}  // namespace
}  // namespace mjray

namespace mjray {
namespace {

TEST(BvhRegion, AClearRegionHasNoBlockedRayAndClearRegionsAreFound) {
  // Random light parallelograms over random points around a real mesh and shapes: wherever
  // the BVH calls a pyramid clear, brute force finds every ray through it unoccluded.
  MJRAY_REQUIRE_SHARED(shared);
  PrimitiveSet prims = obj_world(shared / "models/small/teapot_low_npm.obj");
  add_shapes(prims, 30, 9);
  const Bvh bvh(prims, 0);
  const BruteForce oracle(prims);
  const Bounds3 b = prims.bounds();
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0, 1);
  int clear = 0, rays = 0;
  for (int k = 0; k < 3000; ++k) {
    const Point3 apex = lerp(b, unit(rng) * 1.4f - 0.2f, unit(rng) * 1.4f - 0.2f, unit(rng) * 1.4f - 0.2f);
    const Point3 corner = lerp(b, unit(rng) * 1.6f - 0.3f, 1.2f + unit(rng), unit(rng) * 1.6f - 0.3f);
    const Vector3 e1(unit(rng) * 2, 0, unit(rng) * 0.5f), e2(unit(rng) * 0.5f, unit(rng) * 0.3f, unit(rng) * 2);
    const auto pyramid = LightPyramid::make(apex, {corner, corner + e1, corner + e1 + e2, corner + e2});
    if (!pyramid || bvh.region_primitives(*pyramid, ~0u, {}) != size_t(0)) continue;
    ++clear;
    for (int s = 0; s < 16; ++s) {
      const Point3 target = corner + e1 * unit(rng) + e2 * unit(rng);
      ++rays;
      ASSERT_FALSE(oracle.occluded({apex, target - apex}, 1 - 1e-4f)) << "pyramid " << k << " sample " << s;
    }
  }
  EXPECT_GT(clear, 100);  // the proof does find clear regions
}

}  // namespace
}  // namespace mjray

namespace mjray {
namespace {

/// Records every hit it is shown and blocks none: with `sees_opaque`, every hit of the ray.
class RecordingFilter final : public HitFilter {
 public:
  explicit RecordingFilter(bool sees_opaque_hits = false, bool ignores_transmissive_hits = false)
      : HitFilter(sees_opaque_hits, ignores_transmissive_hits) {}
  bool blocks(const Hit& hit) override {
    hits.push_back(hit);
    return false;
  }
  /// The hits in a fixed order, each once; only transmissive ones unless `all`.
  std::vector<std::pair<uint32_t, float>> sorted(const PrimitiveSet& prims, bool all) const {
    std::vector<std::pair<uint32_t, float>> out;
    for (const Hit& h : hits)
      if (all || prims.transmissive(h.prim)) out.emplace_back(h.prim, h.t);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  std::vector<Hit> hits;
};

// Adds 30 shapes to `prims` and makes every third primitive transmissive, as glass is.
void add_glass_shapes(PrimitiveSet& prims, uint32_t seed) {
  add_shapes(prims, 30, seed);
  prims.transmissive_flags.assign(prims.size(), 0);
  for (uint32_t p = 0; p < prims.size(); p += 3) prims.transmissive_flags[p] = 1;
}

// Whether any of a ray's hits is on an opaque primitive: then a shadow ray is blocked.
bool crosses_opaque(const PrimitiveSet& prims, const std::vector<Hit>& hits) {
  return std::any_of(hits.begin(), hits.end(), [&](const Hit& h) { return !prims.transmissive(h.prim); });
}

// The shadow rays of one light region, tested against the BVH's list of the region's
// primitives, answer as brute force over every primitive does: closest hit, any hit, and the
// transmissive crossings a filter sees. Over 100k rays per mesh, through lists of up to 24.
// Brute force runs once per ray, showing every hit to a filter; each answer is read from it.
void expect_region_lists_agree(PrimitiveSet prims, uint32_t seed) {
  add_glass_shapes(prims, seed);
  const Bvh bvh(prims, 0);
  const BruteForce oracle(prims);
  const Bounds3 b = prims.bounds();
  const float size = length(b.diagonal());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0, 1), signed_unit(-1, 1);
  int lists = 0, rays = 0, blocked = 0, crossed = 0;
  while (rays < 100000) {
    const Point3 apex = lerp(b, unit(rng), unit(rng), unit(rng));
    const Vector3 toward = normalize(Vector3(signed_unit(rng), signed_unit(rng), signed_unit(rng)));
    const Point3 corner = apex + toward * size * (0.05f + 0.5f * unit(rng));
    const float light = size * (0.01f + 0.1f * unit(rng));
    const Vector3 e1 = normalize(cross(toward, Vector3(0.3f, 1, 0.2f))) * light;
    const Vector3 e2 = normalize(cross(toward, e1)) * light;
    const auto pyramid = LightPyramid::make(apex, {corner, corner + e1, corner + e1 + e2, corner + e2});
    if (!pyramid) continue;
    std::array<uint32_t, 24> buffer;
    const auto found = bvh.region_primitives(*pyramid, ~0u, buffer);
    if (!found || *found == 0) continue;
    ++lists;
    const PrimitiveList list(prims, std::span<const uint32_t>(buffer.data(), *found));
    for (int s = 0; s < 16; ++s, ++rays) {
      const Ray ray{apex, corner + e1 * unit(rng) + e2 * unit(rng) - apex};
      const float t_max = 1 - 1e-4f;
      RecordingFilter every_hit(true);
      ASSERT_FALSE(oracle.occluded(ray, {0, t_max}, every_hit));
      const auto& all = every_hit.hits;
      const auto nearest = std::min_element(all.begin(), all.end(), [](const Hit& x, const Hit& y) {
        return x.t < y.t || (x.t == y.t && x.prim < y.prim);
      });
      const auto got = list.intersect(ray, {0, t_max});
      ASSERT_EQ(got.has_value(), !all.empty()) << "list " << lists << " ray " << s;
      if (got) {
        ASSERT_EQ(got->prim, nearest->prim);
        ASSERT_EQ(got->t, nearest->t);
        ASSERT_EQ(got->u, nearest->u);
        ASSERT_EQ(got->v, nearest->v);
      }
      ASSERT_EQ(list.occluded(ray, t_max), !all.empty());
      const bool opaque = crosses_opaque(prims, all);
      RecordingFilter crossings;
      ASSERT_EQ(list.occluded(ray, {0, t_max}, crossings), opaque);
      RecordingFilter every_hit_of_list(true);
      ASSERT_FALSE(list.occluded(ray, {0, t_max}, every_hit_of_list));
      ASSERT_EQ(every_hit_of_list.sorted(prims, true), every_hit.sorted(prims, true));
      if (!opaque) {
        ASSERT_EQ(crossings.sorted(prims, false), every_hit.sorted(prims, false));
      }
      blocked += opaque;
      crossed += !opaque && !all.empty();
    }
  }
  // Both kinds of answer were exercised.
  EXPECT_GT(blocked, 1000);
  EXPECT_GT(crossed, 1000);
}

// The BVH's filtered occlusion query (shadow rays through glass) answers as brute force does,
// through both traversals: blocked exactly when the ray crosses an opaque primitive, and
// otherwise every transmissive crossing shown to the filter; a filter that sees opaque hits is
// shown every crossing, and one that ignores transmissive hits is blocked by the opaque alone.
// 100k rays: half from outside and inside the bounds, half leaving surfaces from their hits.
void expect_filtered_queries_agree(PrimitiveSet prims, uint32_t seed) {
  add_glass_shapes(prims, seed);
  const Bvh best(prims, 0), baseline(prims, 0, BvhSimd::kBaseline);
  const BruteForce oracle(prims);
  std::vector<Ray> rays = random_rays(prims.bounds(), 50000, seed);
  for (uint32_t more = seed + 1; rays.size() < 100000; ++more)
    for (const Ray& ray : surface_rays(prims, 40000, more))
      if (rays.size() < 100000) rays.push_back(ray);
  const Interval range{0, kInfinity};
  int blocked = 0, crossed = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    RecordingFilter every_hit(true);
    ASSERT_FALSE(oracle.occluded(rays[i], range, every_hit));
    const auto& all = every_hit.hits;
    const bool opaque = crosses_opaque(prims, all);
    for (const Bvh* bvh : {&best, &baseline}) {
      SCOPED_TRACE(std::string(bvh->uses_avx() ? "avx" : "baseline") + " ray " + std::to_string(i));
      RecordingFilter crossings;
      ASSERT_EQ(bvh->occluded(rays[i], range, crossings), opaque);
      if (!opaque) {
        ASSERT_EQ(crossings.sorted(prims, false), every_hit.sorted(prims, false));
      }
      RecordingFilter every_hit_of_bvh(true);
      ASSERT_FALSE(bvh->occluded(rays[i], range, every_hit_of_bvh));
      ASSERT_EQ(every_hit_of_bvh.sorted(prims, true), every_hit.sorted(prims, true));
      RecordingFilter opaque_only(false, true);
      ASSERT_EQ(bvh->occluded(rays[i], range, opaque_only), opaque);
    }
    blocked += opaque;
    crossed += !opaque && !all.empty();
  }
  // Both kinds of answer were exercised.
  EXPECT_GT(blocked, 10000);
  EXPECT_GT(crossed, 1000);
}

TEST(BvhFiltered, ShadowQueriesThroughTransmissivePrimitivesAgreeWithBruteForceOnTheTeapot) {
  MJRAY_REQUIRE_SHARED(shared);
  expect_filtered_queries_agree(obj_world(shared / "models/small/teapot_low_npm.obj"), 21);
}

TEST(BvhFiltered, ShadowQueriesThroughTransmissivePrimitivesAgreeWithBruteForceAmongShapes) {
  PrimitiveSet world;
  add_shapes(world, 90, 22);
  expect_filtered_queries_agree(std::move(world), 23);
}

TEST(BvhRegion, ListsOfARegionsPrimitivesAnswerItsRaysAsBruteForceOnTheTeapot) {
  MJRAY_REQUIRE_SHARED(shared);
  expect_region_lists_agree(obj_world(shared / "models/small/teapot_low_npm.obj"), 11);
}

TEST(BvhRegion, ListsOfARegionsPrimitivesAnswerItsRaysAsBruteForceInTheCornellBox) {
  MJRAY_REQUIRE_SHARED(shared);
  expect_region_lists_agree(obj_world(shared / "models/small/cornell/CornellBox-Original.obj"), 12);
}

}  // namespace
}  // namespace mjray
