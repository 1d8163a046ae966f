#pragma once
/// Test primitive sets, ray sets and the brute-force oracle every accelerator must agree with
/// (after mitsuba3's test_kdtrees.py): real meshes from ../shared/models, transformed spheres
/// and cubes, random rays from inside and around the scene, and camera-like ray fans.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/accel/accelerator.h"
#include "mjray/accel/brute_force.h"
#include "mjray/io/obj_loader.h"
#include "mjray/geometry/primitive_set.h"
#include "support/test_paths.h"

namespace mjray::test {

/// One query: a ray and its t_max.
struct Query {
  Ray ray;
  float t_max = kInfinity;
};

/// Primitives, queries over them, and what brute force answers for each.
struct OracleCase {
  std::unique_ptr<PrimitiveSet> prims = std::make_unique<PrimitiveSet>();  // accelerators keep a reference
  std::vector<Query> queries;
  std::vector<std::optional<Hit>> expected;
};

/// Appends `mesh` to `prims` as world-space triangles, each vertex mapped by `world_from_mesh`.
inline void add_mesh(PrimitiveSet& prims, const TriangleMesh& mesh, const Transform& world_from_mesh = {}) {
  std::vector<Point3> positions;
  for (const Point3& p : mesh.positions) positions.push_back(world_from_mesh(p));
  std::vector<std::array<uint32_t, 3>> faces;
  for (const auto& t : mesh.triangles)
    faces.push_back({uint32_t(t[0].position), uint32_t(t[1].position), uint32_t(t[2].position)});
  prims.add_triangles(positions, faces);
}

/// Appends `count` unit spheres and cubes under random rotations, non-uniform scales and
/// translations within [-extent, extent]³.
inline void add_random_shapes(PrimitiveSet& prims, int count, float extent, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> position(-extent, extent), scale(0.05f * extent, 0.3f * extent),
      angle(0, 360);
  for (int i = 0; i < count; ++i) {
    const Transform t = Transform::translate({position(rng), position(rng), position(rng)}) *
                        Transform::rotate(int(rng() % 3), angle(rng)) *
                        Transform::rotate(int(rng() % 3), angle(rng)) *
                        Transform::scale(scale(rng), scale(rng), scale(rng));
    prims.add_shape(i % 2 ? Shape(UnitCube{}) : Shape(UnitSphere{}), t);
  }
}

/// A direction: mostly uniform on the sphere, with some exactly axis-parallel (two zero
/// components) and some in an axis plane (one zero component).
inline Vector3 random_direction(std::mt19937& rng) {
  std::normal_distribution<float> normal;
  const uint32_t kind = rng() % 20;
  Vector3 d{normal(rng), normal(rng), normal(rng)};
  if (kind == 0) {
    d = {};
    d[int(rng() % 3)] = rng() % 2 ? 1.f : -1.f;
  } else if (kind == 1) {
    d[int(rng() % 3)] = 0;
  }
  return length(d) > 0 ? normalize(d) : Vector3{0, 0, 1};
}

/// `count` random queries: origins in the world's box grown by half its size on each side
/// (many inside it), random directions, and a finite t_max for a quarter of them.
inline void add_random_queries(OracleCase& c, int count, uint32_t seed) {
  std::mt19937 rng(seed);
  const Bounds3 b = c.prims->bounds();
  const Vector3 d = b.diagonal();
  std::uniform_real_distribution<float> unit(0, 1);
  for (int i = 0; i < count; ++i) {
    Point3 o;
    for (int a = 0; a < 3; ++a) o[a] = b.lo[a] - 0.5f * d[a] + 2 * d[a] * unit(rng);
    const float t_max = rng() % 4 == 0 ? unit(rng) * length(d) : kInfinity;
    c.queries.push_back({{o, random_direction(rng)}, t_max});
  }
}

/// Camera-like fans: from 3 eyes outside the box, a width×width grid of rays aimed across it.
inline void add_camera_queries(OracleCase& c, int width) {
  const Bounds3 b = c.prims->bounds();
  const Point3 centre = b.centre();
  const float size = length(b.diagonal());
  const Vector3 views[3] = {normalize(Vector3{0.3f, 0.2f, 1}), normalize(Vector3{-1, 0.5f, -0.2f}),
                            normalize(Vector3{0.1f, -1, 0.4f})};
  for (const Vector3& view : views) {
    const Point3 eye = centre + view * (1.2f * size);
    const Vector3 forward = -view;
    const Vector3 right = normalize(cross(forward, std::abs(forward.y) < 0.9f ? Vector3{0, 1, 0} : Vector3{1, 0, 0}));
    const Vector3 up = cross(right, forward);
    for (int y = 0; y < width; ++y)
      for (int x = 0; x < width; ++x) {
        const float sx = (x + 0.5f) / width - 0.5f, sy = (y + 0.5f) / width - 0.5f;
        const Point3 target = centre + right * (sx * 0.8f * size) + up * (sy * 0.8f * size);
        c.queries.push_back({{eye, target - eye}});
      }
  }
}

/// A grid of `n`×`n` quads (two triangles each) over [-half, half]² in the plane y = `y`.
inline TriangleMesh flat_grid(int n, float half, float y) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({-half + 2 * half * i / n, y, -half + 2 * half * j / n});
  const auto corner = [&](int i, int j) { return MeshCorner{int32_t(j * (n + 1) + i)}; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({corner(i, j), corner(i + 1, j), corner(i + 1, j + 1)});
      m.triangles.push_back({corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)});
    }
  return m;
}

/// For each of the first `count` queries that hit (per c.expected), a query leaving the hit
/// point o + t·d in a random direction: rays that start on a surface, as every secondary ray does.
inline void add_queries_from_hits(OracleCase& c, size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  const size_t existing = c.queries.size();
  for (size_t i = 0; i < existing && i < count; ++i)
    if (const auto& hit = c.expected[i]) {
      const Ray& ray = c.queries[i].ray;
      c.queries.push_back({{ray.origin + ray.direction * hit->t, random_direction(rng)}});
    }
}

/// Fills c.expected from brute force, on all cores (it dominates the tests' run time).
inline void solve_with_brute_force(OracleCase& c) {
  const BruteForce oracle(*c.prims);
  c.expected.assign(c.queries.size(), std::nullopt);
  const size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
  std::vector<std::thread> workers;
  for (size_t w = 0; w < threads; ++w)
    workers.emplace_back([&, w] {
      for (size_t i = w; i < c.queries.size(); i += threads)
        c.expected[i] = oracle.intersect(c.queries[i].ray, {0, c.queries[i].t_max});
    });
  for (std::thread& worker : workers) worker.join();
}

/// The named cases, built once per test run and shared by every accelerator's tests; null
/// when ../shared is absent. Names: teapot_low, bunny_low, cornell, suzanne, spot, shapes,
/// mixed, surfaces; over 100k queries on real meshes in all, sized so brute force stays around a second.
inline const OracleCase* oracle_case(const std::string& name) {
  static std::map<std::string, std::unique_ptr<OracleCase>> cache;
  if (auto it = cache.find(name); it != cache.end()) return it->second.get();
  const auto shared = shared_dir();
  if (!shared) return nullptr;
  const auto models = *shared / "models";
  auto c = std::make_unique<OracleCase>();
  PrimitiveSet& w = *c->prims;
  int random = 0, camera = 0;
  if (name == "teapot_low") {
    add_mesh(w, load_obj(models / "small/teapot_low_npm.obj"));
    random = 12000, camera = 40;
  } else if (name == "bunny_low") {
    add_mesh(w, load_obj(models / "small/bunny_low_npm.obj"));
    random = 4000, camera = 25;
  } else if (name == "cornell") {
    add_mesh(w, load_obj(models / "small/cornell/CornellBox-Original.obj"));
    random = 30000, camera = 60;
  } else if (name == "suzanne") {
    add_mesh(w, load_obj(models / "medium/suzanne.obj"));
    random = 6000, camera = 30;
  } else if (name == "spot") {
    add_mesh(w, load_obj(models / "small/spot/spot_control_mesh.obj"));  // fan-triangulated n-gons
    random = 20000, camera = 50;
  } else if (name == "shapes") {
    add_random_shapes(w, 60, 5, 7);
    random = 15000, camera = 50;
  } else if (name == "mixed") {
    // Two meshes (so vertex numbering restarts per mesh) among shapes.
    const TriangleMesh teapot = load_obj(models / "small/teapot_low_npm.obj");
    const TriangleMesh bunny = load_obj(models / "small/bunny_low_npm.obj");
    add_mesh(w, teapot, Transform::translate({-2, 0, 0}) * Transform::scale(0.3f, 0.3f, 0.3f));
    add_mesh(w, bunny, Transform::translate({2, 0, 0}) * Transform::rotate(1, 30) * Transform::scale(0.2f, 0.3f, 0.2f));
    add_random_shapes(w, 20, 3, 11);
    random = 3000, camera = 20;
  } else if (name == "surfaces") {
    // Surfaces that touch: a grid of triangles lying on a box's top face, a sphere resting on
    // both, so that two primitives are often hit an ulp or two apart, and many shared edges.
    add_mesh(w, flat_grid(12, 0.8f, 0));
    w.add_shape(Shape(UnitCube{}), Transform::translate({-1, -1, -1}) * Transform::scale(2, 1, 2));
    w.add_shape(Shape(UnitSphere{}), Transform::translate({0.1f, 0.5f, 0}) * Transform::scale(0.5f, 0.5f, 0.5f));
    random = 40000, camera = 60;
  } else {
    ADD_FAILURE() << "no oracle case '" << name << "'";
    return nullptr;
  }
  add_random_queries(*c, random, uint32_t(std::hash<std::string>{}(name)));
  add_camera_queries(*c, camera);
  solve_with_brute_force(*c);
  if (name == "surfaces") {
    add_queries_from_hits(*c, c->queries.size(), 5);
    solve_with_brute_force(*c);
  }
  return cache.emplace(name, std::move(c)).first->second.get();
}

inline std::string describe(const Query& q) {
  char text[200];
  std::snprintf(text, sizeof text, "ray o=(%.9g, %.9g, %.9g) d=(%.9g, %.9g, %.9g) t_max=%.9g",
                q.ray.origin.x, q.ray.origin.y, q.ray.origin.z, q.ray.direction.x, q.ray.direction.y,
                q.ray.direction.z, q.t_max);
  return text;
}

inline std::string describe(const std::optional<Hit>& h) {
  if (!h) return "no hit";
  char text[120];
  std::snprintf(text, sizeof text, "prim %u at t=%.9g (u=%.6g, v=%.6g)", h->prim, h->t, h->u, h->v);
  return text;
}

/// Whether two answers agree: both miss, or both hit at t within 1e-4 relative — the same
/// primitive, or (a tie, e.g. a shared edge) another one at the same distance. `t_floor` is
/// an absolute allowance for hits very near the origin, where float positions limit t.
inline bool same_answer(const std::optional<Hit>& a, const std::optional<Hit>& b, float t_floor = 0) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  return std::abs(a->t - b->t) <= 1e-4f * std::max(a->t, b->t) + t_floor;
}

/// A few ulps of the coordinates `q` works with, as a distance along its ray: how far apart
/// two correct intersection routines may place a hit.
inline float coordinate_precision_t(const Query& q, const Bounds3& scene) {
  const float magnitude = std::max({max_component(abs(q.ray.origin)), max_component(abs(scene.lo)),
                                    max_component(abs(scene.hi))});
  return 1e-6f * magnitude / length(q.ray.direction);
}

/// Checks `accel` against the case's oracle on every query: the nearest hit, occluded() against
/// its own intersect() at t_max, and nothing found before half the hit distance. Fails the test
/// when more than `allowed` queries disagree, printing the first few; returns the count.
/// A `stride` above 1 checks only every stride-th query (for near-brute-force structures).
inline size_t expect_agreement(const OracleCase& c, const Accelerator& accel, size_t allowed = 0,
                               size_t stride = 1) {
  size_t bad = 0;
  std::vector<std::string> messages;
  const Bounds3 scene = c.prims->bounds();
  for (size_t i = 0; i < c.queries.size(); i += stride) {
    const Query& q = c.queries[i];
    const auto got = accel.intersect(q.ray, {0, q.t_max});
    std::string problem;
    const float t_floor = coordinate_precision_t(q, scene);
    if (!same_answer(c.expected[i], got, t_floor))
      problem = "expected " + describe(c.expected[i]) + ", got " + describe(got);
    else if (got && !same_answer(got, c.prims->intersect(got->prim, q.ray, {}), t_floor))
      problem = "reported " + describe(got) + " but that primitive alone is hit elsewhere";
    else if (accel.occluded(q.ray, q.t_max) != got.has_value())
      problem = "occluded() disagrees with intersect() = " + describe(got);
    else if (got && (accel.occluded(q.ray, 0.5f * got->t) || accel.intersect(q.ray, {0, 0.5f * got->t})))
      problem = "something found before half the nearest hit " + describe(got);
    if (problem.empty()) continue;
    if (++bad <= 5) messages.push_back(describe(q) + ": " + problem);
  }
  EXPECT_LE(bad, allowed) << accel.name() << " disagrees with brute force on " << bad << " of "
                          << c.queries.size() << " queries, e.g.\n"
                          << [&] {
                               std::string all;
                               for (const auto& m : messages) all += "  " + m + "\n";
                               return all;
                             }();
  return bad;
}

/// Checks that `accel` answers every query of the case exactly as brute force does: the same
/// primitive at the same float t with the same (u, v), or no hit; and occluded() the same.
/// Returns how many queries differ.
inline size_t expect_identical_hits(const OracleCase& c, const Accelerator& accel) {
  size_t bad = 0;
  std::string first;
  for (size_t i = 0; i < c.queries.size(); ++i) {
    const Query& q = c.queries[i];
    const auto got = accel.intersect(q.ray, {0, q.t_max});
    const auto& want = c.expected[i];
    const bool same = got.has_value() == want.has_value() &&
                      (!got || (got->prim == want->prim && got->t == want->t && got->u == want->u && got->v == want->v));
    if (same && accel.occluded(q.ray, q.t_max) == want.has_value()) continue;
    if (++bad == 1) first = describe(q) + ": expected " + describe(want) + ", got " + describe(got);
  }
  EXPECT_EQ(bad, 0u) << accel.name() << " differs from brute force on " << bad << " of " << c.queries.size()
                     << " queries, e.g. " << first;
  return bad;
}

}  // namespace mjray::test
