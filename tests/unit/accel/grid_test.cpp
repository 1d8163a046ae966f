#include "mjray/accel/uniform_grid.h"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/accel/make_accelerator.h"
#include "support/scene_builder.h"
#include "unit/accel/accel_oracle.h"

namespace mjray {
namespace {

using test::add_mesh;
using test::expect_agreement;
using test::OracleCase;
using test::Query;

// The sizes every agreement test runs: single voxel, coarse, odd, fine, and optimal (0).
constexpr int kSizes[] = {1, 2, 7, 32, 0};

void expect_grids_agree(const std::string& name) {
  const OracleCase* c = test::oracle_case(name);
  if (!c) GTEST_SKIP() << "../shared (models) is absent; set MJRAY_SHARED_DIR to run this test";
  for (const int size : kSizes) {
    SCOPED_TRACE("grid size " + std::to_string(size));
    const UniformGrid grid(*c->prims, size);
    // 1³ and 2³ grids test nearly every primitive per ray: a quarter of the rays will do.
    expect_agreement(*c, grid, 0, size == 1 || size == 2 ? 4 : 1);
  }
}

TEST(GridAgreement, TeapotLow) { expect_grids_agree("teapot_low"); }
TEST(GridAgreement, BunnyLow) { expect_grids_agree("bunny_low"); }
TEST(GridAgreement, CornellBox) { expect_grids_agree("cornell"); }
TEST(GridAgreement, Suzanne) { expect_grids_agree("suzanne"); }
TEST(GridAgreement, SpotControlMesh) { expect_grids_agree("spot"); }
TEST(GridAgreement, TransformedSpheresAndCubes) { expect_grids_agree("shapes"); }
TEST(GridAgreement, MeshesAmongShapes) { expect_grids_agree("mixed"); }

// A mesh of one triangle per entry of `corners`.
TriangleMesh triangle_soup(const std::vector<std::array<Point3, 3>>& corners) {
  TriangleMesh m;
  for (const auto& tri : corners) {
    const int32_t base = int32_t(m.positions.size());
    m.positions.insert(m.positions.end(), tri.begin(), tri.end());
    m.triangles.push_back({MeshCorner{base}, MeshCorner{base + 1}, MeshCorner{base + 2}});
  }
  return m;
}

// `count` random triangles with corners in [0, 10]³ and edges up to `size` long.
std::vector<std::array<Point3, 3>> random_triangles(int count, float size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> where(0, 10), offset(-size, size);
  std::vector<std::array<Point3, 3>> result;
  for (int i = 0; i < count; ++i) {
    const Point3 p{where(rng), where(rng), where(rng)};
    result.push_back({p, p + Vector3{offset(rng), offset(rng), offset(rng)},
                      p + Vector3{offset(rng), offset(rng), offset(rng)}});
  }
  return result;
}

// Random queries over `world`, solved by brute force.
OracleCase random_case(std::unique_ptr<PrimitiveSet> world, int rays, uint32_t seed) {
  OracleCase c;
  c.prims = std::move(world);
  test::add_random_queries(c, rays, seed);
  test::add_camera_queries(c, 20);
  test::solve_with_brute_force(c);
  return c;
}

TEST(GridBuild, OptimalResolutionIsThreeCubeRoots) {
  EXPECT_EQ(optimal_grid_resolution(0), 1);
  EXPECT_EQ(optimal_grid_resolution(1), 3);
  EXPECT_EQ(optimal_grid_resolution(1000), 30);
  EXPECT_EQ(optimal_grid_resolution(69451), 123);  // the full Stanford bunny
}

TEST(GridBuild, ResolutionIsClampedAndCapped) {
  PrimitiveSet world;
  add_mesh(world, triangle_soup(random_triangles(1000, 1, 1)));
  EXPECT_EQ(UniformGrid(world, 0).resolution(), 30);
  EXPECT_EQ(UniformGrid(world, 5).resolution(), 5);
  EXPECT_EQ(UniformGrid(world, -3).resolution(), 1);
  const UniformGrid capped(world, 4096);
  EXPECT_EQ(capped.resolution(), 256);
  EXPECT_EQ(capped.resolution_note(),
            "grid resolution 4096 is above the limit of 256 voxels per axis; the grid uses 256³ voxels");
  EXPECT_EQ(UniformGrid(world, 5).resolution_note(), "");
  EXPECT_EQ(UniformGrid(world, 0).resolution_note(), "");
}

TEST(GridBuild, HugeShapesInAFineGridStayWithinTheMemoryBudget) {
  PrimitiveSet world;
  for (int i = 0; i < 4; ++i)
    world.add_shape(UnitSphere{}, Transform::translate({0.01f * i, 0, 0}) * Transform::scale(5, 5, 5));
  OracleCase c = random_case(std::make_unique<PrimitiveSet>(world), 2000, 3);
  const UniformGrid grid(*c.prims, 256);
  EXPECT_LT(grid.resolution(), 256);
  EXPECT_EQ(grid.resolution_note(), "grid resolution 256 " + std::to_string(2 * grid.resolution()) +
                                        "³ voxels would list more than 16777216 primitive references (the memory "
                                        "budget); the grid uses " + std::to_string(grid.resolution()) + "³ voxels");
  EXPECT_LE(grid.reference_count(), size_t(1) << 24);
  EXPECT_LT(grid.memory_bytes(), size_t(200) << 20);
  expect_agreement(c, grid);
}

TEST(GridBuild, ThinDiagonalTriangleIsListedOnlyWhereItPasses) {
  // A long sliver along the main diagonal: its AABB covers the whole grid.
  auto world = std::make_unique<PrimitiveSet>();
  add_mesh(*world, triangle_soup({{Point3{0, 0, 0}, Point3{10, 10, 10}, Point3{10, 10.1f, 10}}}));
  OracleCase c = random_case(std::move(world), 3000, 4);
  const UniformGrid grid(*c.prims, 32);
  EXPECT_GE(grid.reference_count(), 32u);
  EXPECT_LT(grid.reference_count(), 32u * 32 * 2);  // a thin band, not 32³
  expect_agreement(c, grid);
}

TEST(GridBuild, MakeAcceleratorBuildsTheRequestedGrid) {
  PrimitiveSet world;
  add_mesh(world, triangle_soup(random_triangles(1000, 1, 2)));
  const auto sized = make_accelerator(world, {.kind = "grid", .grid_size = 7});
  EXPECT_EQ(sized->name(), "grid");
  ASSERT_NE(dynamic_cast<const UniformGrid*>(sized.get()), nullptr);
  EXPECT_EQ(dynamic_cast<const UniformGrid&>(*sized).resolution(), 7);
  const auto optimal = make_accelerator(world, {.kind = "grid", .grid_size = 0});
  EXPECT_EQ(dynamic_cast<const UniformGrid&>(*optimal).resolution(), 30);
  EXPECT_NE(accelerator_names().find("grid"), std::string::npos);
  EXPECT_GT(optimal->memory_bytes(), 30u * 30 * 30 * sizeof(uint32_t));
}

TEST(GridEdgeCases, EmptyWorld) {
  const PrimitiveSet world;
  for (const int size : kSizes) {
    const UniformGrid grid(world, size);
    EXPECT_TRUE(grid.bounds().empty());
    const Ray ray{{0, 0, -5}, {0, 0, 1}};
    EXPECT_FALSE(grid.intersect(ray, {}));
    EXPECT_FALSE(grid.occluded(ray, kInfinity));
  }
}

TEST(GridEdgeCases, OnePrimitive) {
  // A lone triangle gives a flat grid box; a lone sphere a cubic one.
  auto triangle = std::make_unique<PrimitiveSet>();
  add_mesh(*triangle, triangle_soup({{Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}}}));
  auto sphere = std::make_unique<PrimitiveSet>();
  sphere->add_shape(UnitSphere{}, Transform::translate({1, 2, 3}) * Transform::scale(1, 2, 0.5f));
  for (auto* world : {&triangle, &sphere}) {
    OracleCase c = random_case(std::move(*world), 3000, 5);
    for (const int size : kSizes) {
      SCOPED_TRACE("grid size " + std::to_string(size));
      expect_agreement(c, UniformGrid(*c.prims, size));
    }
  }
}

TEST(GridEdgeCases, AllPrimitivesInOneVoxel) {
  // A tight cluster plus one far triangle that stretches the grid: the cluster shares a voxel.
  auto world = std::make_unique<PrimitiveSet>();
  std::vector<std::array<Point3, 3>> tris;
  for (const auto& t : random_triangles(200, 0.01f, 6))
    tris.push_back({Point3{t[0].x * 0.001f, t[0].y * 0.001f, t[0].z * 0.001f},
                    Point3{t[1].x * 0.001f, t[1].y * 0.001f, t[1].z * 0.001f},
                    Point3{t[2].x * 0.001f, t[2].y * 0.001f, t[2].z * 0.001f}});
  tris.push_back({Point3{100, 100, 100}, Point3{101, 100, 100}, Point3{100, 101, 100}});
  add_mesh(*world, triangle_soup(tris));
  OracleCase c = random_case(std::move(world), 2000, 7);
  // Aim extra rays at the cluster, which random rays over the big box rarely meet.
  std::mt19937 rng(8);
  for (int i = 0; i < 2000; ++i) {
    const Point3 eye{50, 30, -20};
    const Point3 target{0.01f * float(rng() % 1000) / 1000, 0.01f * float(rng() % 1000) / 1000, 0.005f};
    c.queries.push_back({{eye, target - eye}});
  }
  test::solve_with_brute_force(c);
  for (const int size : kSizes) {
    SCOPED_TRACE("grid size " + std::to_string(size));
    expect_agreement(c, UniformGrid(*c.prims, size));
  }
}

TEST(GridEdgeCases, RaysFromInsideAClosedMeshAlwaysHit) {
  PrimitiveSet world;
  add_mesh(world, test::uv_sphere(16, 32), Transform::scale(3, 2, 1));
  OracleCase c;
  c.prims = std::make_unique<PrimitiveSet>(world);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> inside(-0.5f, 0.5f);
  for (int i = 0; i < 3000; ++i)
    c.queries.push_back({{{inside(rng), inside(rng), inside(rng)}, test::random_direction(rng)}});
  test::solve_with_brute_force(c);
  for (const int size : kSizes) {
    SCOPED_TRACE("grid size " + std::to_string(size));
    const UniformGrid grid(*c.prims, size);
    expect_agreement(c, grid);
    int misses = 0;
    for (const Query& q : c.queries) misses += !grid.intersect(q.ray, {0, q.t_max});
    EXPECT_EQ(misses, 0);
  }
}

TEST(GridEdgeCases, AxisParallelRays) {
  auto world = std::make_unique<PrimitiveSet>();
  add_mesh(*world, triangle_soup(random_triangles(500, 1.5f, 10)));
  test::add_random_shapes(*world, 10, 5, 11);
  OracleCase c;
  c.prims = std::move(world);
  std::mt19937 rng(12);
  std::uniform_real_distribution<float> where(-2, 12);
  for (int i = 0; i < 6000; ++i) {
    Vector3 d;
    d[i % 3] = (i / 3) % 2 ? 1.f : -1.f;
    c.queries.push_back({{{where(rng), where(rng), where(rng)}, d}});
  }
  test::solve_with_brute_force(c);
  for (const int size : kSizes) {
    SCOPED_TRACE("grid size " + std::to_string(size));
    expect_agreement(c, UniformGrid(*c.prims, size));
  }
}

TEST(GridEdgeCases, RaysAlongVoxelBoundariesAndGeometryOnThem) {
  for (const int size : {2, 7, 32}) {
    SCOPED_TRACE("grid size " + std::to_string(size));
    // Find the voxel planes of a triangle soup...
    auto tris = random_triangles(300, 2, 13);
    PrimitiveSet probe;
    add_mesh(probe, triangle_soup(tris));
    const Bounds3 box = UniformGrid(probe, size).grid_bounds();
    std::vector<float> planes[3];
    for (int a = 0; a < 3; ++a) {
      const float voxel = (box.hi[a] - box.lo[a]) / float(size);
      for (int i = 0; i <= size; ++i) planes[a].push_back(box.lo[a] + float(i) * voxel);
    }
    // ...then add squares lying exactly in interior voxel planes (the box is unchanged).
    for (int a = 0; a < 3; ++a)
      for (int i = 1; i < size; i += std::max(1, size / 4)) {
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        Point3 p0, p1, p2, p3;
        p0[a] = p1[a] = p2[a] = p3[a] = planes[a][i];
        p0[u] = 2, p0[v] = 2, p1[u] = 8, p1[v] = 2, p2[u] = 8, p2[v] = 8, p3[u] = 2, p3[v] = 8;
        tris.push_back({p0, p1, p2});
        tris.push_back({p0, p2, p3});
      }
    OracleCase c;
    c.prims = std::make_unique<PrimitiveSet>();
    add_mesh(*c.prims, triangle_soup(tris));
    ASSERT_EQ(UniformGrid(*c.prims, size).grid_bounds().lo, box.lo);
    ASSERT_EQ(UniformGrid(*c.prims, size).grid_bounds().hi, box.hi);

    // Rays along voxel edges (two coordinates on planes), within voxel faces (one coordinate
    // on a plane, direction in it), and through voxel corners.
    std::mt19937 rng(14);
    std::uniform_real_distribution<float> where(-1, 11);
    std::normal_distribution<float> normal;
    for (int a = 0; a < 3; ++a) {
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      for (size_t i = 0; i < planes[u].size(); ++i)
        for (size_t j = 0; j < planes[v].size(); ++j)
          for (const float sign : {1.f, -1.f}) {
            Point3 o;
            o[a] = sign > 0 ? -5.f : 15.f;
            o[u] = planes[u][i];
            o[v] = planes[v][j];
            Vector3 d;
            d[a] = sign;
            c.queries.push_back({{o, d}});
          }
      for (int k = 0; k < 1000; ++k) {
        Point3 o{where(rng), where(rng), where(rng)};
        o[a] = planes[a][rng() % planes[a].size()];
        Vector3 d{normal(rng), normal(rng), normal(rng)};
        d[a] = 0;
        c.queries.push_back({{o, d}});
      }
    }
    for (int k = 0; k < 500; ++k) {
      const Point3 o{planes[0][rng() % planes[0].size()], planes[1][rng() % planes[1].size()],
                     planes[2][rng() % planes[2].size()]};
      const Vector3 d{float(int(rng() % 3) - 1), float(int(rng() % 3) - 1), float(int(rng() % 3) - 1)};
      c.queries.push_back({{o, d}});
    }
    test::solve_with_brute_force(c);
    expect_agreement(c, UniformGrid(*c.prims, size));
  }
}

TEST(GridEdgeCases, DegenerateTriangles) {
  auto tris = random_triangles(200, 1.5f, 15);
  std::mt19937 rng(16);
  std::uniform_real_distribution<float> where(0, 10);
  for (int i = 0; i < 100; ++i) {
    const Point3 p{where(rng), where(rng), where(rng)}, q{where(rng), where(rng), where(rng)};
    tris.push_back({p, p, q});                    // repeated corner
    tris.push_back({p, q, p + (q - p) * 0.25f});  // collinear
    tris.push_back({p, p, p});                    // a point
  }
  auto world = std::make_unique<PrimitiveSet>();
  add_mesh(*world, triangle_soup(tris));
  OracleCase c = random_case(std::move(world), 4000, 17);
  for (const int size : kSizes) {
    SCOPED_TRACE("grid size " + std::to_string(size));
    expect_agreement(c, UniformGrid(*c.prims, size));
  }
}

TEST(GridEdgeCases, NonFiniteRaysMissWithoutHanging) {
  PrimitiveSet world;
  add_mesh(world, triangle_soup(random_triangles(300, 2, 18)));
  test::add_random_shapes(world, 10, 5, 19);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = kInfinity;
  const std::vector<Query> queries = {
      {{{nan, 5, 5}, {0, 0, 1}}},       {{{5, 5, 5}, {nan, 0, 1}}},
      {{{5, 5, 5}, {nan, nan, nan}}},   {{{-inf, 5, 5}, {1, 0, 0}}},
      {{{5, 5, 5}, {inf, 0, 0}}},       {{{5, 5, 5}, {inf, -inf, 1}}},
      {{{5, 5, 5}, {0, 0, 0}}},         {{{5, 5, 5}, {0, 0, 1}}, nan},
      {{{5, 5, 5}, {0, 0, 1}}, 0},      {{{5, 5, 5}, {0, 0, 1}}, -1},
      {{{5, 5, 5}, {1e-40f, 1e-40f, 1e-40f}}},
      {{{5, 5, 5}, {1e30f, -1e30f, 1e30f}}, inf},
  };
  for (const int size : kSizes) {
    const UniformGrid grid(world, size);
    for (size_t i = 0; i < queries.size(); ++i) {
      SCOPED_TRACE("grid size " + std::to_string(size) + ", query " + std::to_string(i));
      const auto hit = grid.intersect(queries[i].ray, {0, queries[i].t_max});
      EXPECT_EQ(grid.occluded(queries[i].ray, queries[i].t_max), hit.has_value());
      if (i < 10) {
        EXPECT_FALSE(hit);  // the others are finite, if extreme
      }
    }
  }
}

}  // namespace
}  // namespace mjray
