// mjray-bench: builds one accelerator over one OBJ mesh and traces a fixed, seeded set of rays
// through it, printing one JSON line (build time, memory, rays per second). Every accelerator
// sees exactly the same rays, so lines from different --accel runs compare like for like.
//
//   mjray-bench --mesh FILE.obj --accel none|grid|bvh|embree --rays primary|incoherent|shadow
//               [--threads N] [--build-threads N] [--grid N | --grid-optimal] [--repeat K]
//               [--max-rays N] [--ray-count N] [--seed N] [--min-ms N] [--closest]
//               [--embree-flags robust|default]
//
// Build: K builds, median. Trace: one warm-up pass, then K timed samples, each as many passes
// over the rays as make it last ≥ --min-ms milliseconds (default 250); the median per-pass time is
// trace_seconds. --closest traces the shadow rays with intersect() instead of occluded(), to
// see what the any-hit path gains over a closest-hit query on the same rays.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "mjray/accel/bvh.h"
#include "mjray/accel/bvh_builder.h"
#include "mjray/accel/make_accelerator.h"
#include "mjray/accel/uniform_grid.h"
#ifdef MJRAY_HAVE_EMBREE
#include "mjray/accel/embree_bvh_builder.h"
#endif
#include "mjray/core/large_page_heap.h"
#include "mjray/core/rng.h"
#include "mjray/geometry/spawn_ray.h"
#include "mjray/io/obj_loader.h"
#include "mjray/core/parallel_for.h"
#include "mjray/scene/world.h"

namespace {

using namespace mjray;
using Clock = std::chrono::steady_clock;

constexpr int kPrimaryResolution = 1024;  ///< primary rays: a 1024×1024 pinhole image
constexpr int kChunk = 1024;              ///< rays per parallel_for item
constexpr float kFovyDegrees = 40;

/// What the command line asked for.
struct Options {
  std::string mesh;
  std::string accel = "bvh";
  std::string rays = "primary";
  int threads = 1;
  int build_threads = -1;     ///< -1 = same as threads
  int grid = 0;               ///< 0 = optimal (for --accel grid)
  int repeat = 3;
  size_t max_rays = 0;        ///< 0 = all; otherwise an evenly strided subset
  size_t ray_count = 1 << 20; ///< incoherent rays
  uint64_t seed = 1;
  double min_seconds = 0.25;  ///< shortest timed trace sample
  bool closest = false;       ///< shadow rays as closest-hit queries (to compare with occluded)
  /// Embree's scene flags: "robust" (what mjray renders with) or its faster "default".
  std::string embree_flags = "robust";
  /// With --accel bvh, whose builder makes the tree: "mjray", or Embree's ("embree", and
  /// "embree-splits" with its spatial splits), with mjray's cost model and leaf size.
  std::string tree = "mjray";
};

/// One query: a ray and its range (shadow rays stop short of the light).
struct Query {
  Ray ray;
  float t_max;
};

constexpr const char* kUsage =
    "usage: mjray-bench --mesh FILE.obj --accel none|grid|bvh|embree --rays primary|incoherent|shadow\n"
    "                   [--threads N] [--build-threads N] [--grid N | --grid-optimal] [--repeat K]\n"
    "                   [--max-rays N] [--ray-count N] [--seed N] [--min-ms N] [--closest]\n"
    "                   [--embree-flags robust|default] [--tree mjray|embree|embree-splits]\n";

/// Prints the problem and the usage to stderr and exits 2 (as mjray does for a bad command line).
[[noreturn]] void usage(const std::string& problem) {
  std::fprintf(stderr, "mjray-bench: %s\n%s", problem.c_str(), kUsage);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage("missing value after " + a);
      return argv[++i];
    };
    auto number = [&]() -> long long {
      const std::string v = value();
      try {
        size_t used = 0;
        const long long n = std::stoll(v, &used);
        if (used != v.size() || n < 0) throw std::invalid_argument(v);
        return n;
      } catch (const std::exception&) {
        usage("'" + v + "' after " + a + " is not a non-negative integer");
      }
    };
    if (a == "--mesh") o.mesh = value();
    else if (a == "--accel") o.accel = value();
    else if (a == "--rays") o.rays = value();
    else if (a == "--threads" || a == "-j") o.threads = int(number());
    else if (a == "--build-threads") o.build_threads = int(number());
    else if (a == "--grid" || a == "-g") o.grid = int(number());
    else if (a == "--grid-optimal" || a == "-o") o.grid = 0;
    else if (a == "--repeat") o.repeat = int(number());
    else if (a == "--max-rays") o.max_rays = size_t(number());
    else if (a == "--ray-count") o.ray_count = size_t(number());
    else if (a == "--seed") o.seed = uint64_t(number());
    else if (a == "--min-ms") o.min_seconds = double(number()) / 1000;
    else if (a == "--closest") o.closest = true;
    else if (a == "--embree-flags") {
      o.embree_flags = value();
      if (o.embree_flags != "robust" && o.embree_flags != "default") usage("--embree-flags takes robust or default");
    }
    else if (a == "--tree") {
      o.tree = value();
      if (o.tree != "mjray" && o.tree != "embree" && o.tree != "embree-splits")
        usage("--tree takes mjray, embree or embree-splits");
    }
    else if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    else usage("unknown option " + a);
  }
  if (o.mesh.empty()) usage("--mesh is required");
  if (o.rays != "primary" && o.rays != "incoherent" && o.rays != "shadow") usage("unknown --rays " + o.rays);
  if (o.threads < 1) o.threads = 1;
  if (o.build_threads < 0) o.build_threads = o.threads;
  if (o.repeat < 1) o.repeat = 1;
  if (o.tree != "mjray" && o.accel != "bvh") usage("--tree is for --accel bvh");
#ifndef MJRAY_HAVE_EMBREE
  if (o.tree != "mjray") usage("--tree " + o.tree + " needs a build with Embree");
#endif
  return o;
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The accelerator asked for; with --tree embree*, mjray's BVH traversal over Embree's tree.
std::unique_ptr<Accelerator> make_bench_accelerator(const PrimitiveSet& prims, const AcceleratorOptions& options,
                                                    const std::string& tree) {
#ifdef MJRAY_HAVE_EMBREE
  if (tree != "mjray") {
    EmbreeTreeOptions embree{.spatial_splits = tree == "embree-splits", .threads = options.threads};
    return std::make_unique<Bvh>(prims, embree_built_tree(prims, embree), options.threads);
  }
#endif
  (void)tree;
  return make_accelerator(prims, options);
}

/// A World holding the OBJ as one mesh, one primitive per triangle, no shapes.
World world_from_obj(TriangleMesh obj) {
  World world;
  world.materials.push_back(PhongMaterial{});
  WorldMesh mesh;
  std::vector<std::array<uint32_t, 3>> faces;
  faces.reserve(obj.triangles.size());
  for (const auto& t : obj.triangles)
    faces.push_back({uint32_t(t[0].position), uint32_t(t[1].position), uint32_t(t[2].position)});
  world.primitives.add_triangles(obj.positions, faces);
  // Normals and uvs are dropped (no corners): hits need positions only.
  mesh.triangle_count = uint32_t(faces.size());
  world.meshes.push_back(std::move(mesh));
  return world;
}

/// The scene's bounding sphere.
struct Sphere {
  Point3 centre;
  float radius;
};

Sphere bounding_sphere(const Bounds3& b) { return {b.centre(), 0.5f * length(b.diagonal())}; }

/// 1024×1024 pixel-centre rays of a pinhole camera looking at the box centre from a fixed
/// diagonal direction, far enough back that the bounding sphere fills the vertical field.
std::vector<Query> primary_rays(const Bounds3& box) {
  const Sphere s = bounding_sphere(box);
  const float half_fov = 0.5f * kFovyDegrees * std::numbers::pi_v<float> / 180;
  const Vector3 back = normalize(Vector3(0.55f, 0.45f, 1.0f));  // from the centre toward the eye
  const Point3 eye = s.centre + back * (s.radius / std::sin(half_fov));
  const Vector3 forward = -back;
  const Vector3 right = normalize(cross(forward, Vector3(0, 1, 0)));
  const Vector3 up = cross(right, forward);
  const float h = std::tan(half_fov);
  std::vector<Query> rays;
  rays.reserve(size_t(kPrimaryResolution) * kPrimaryResolution);
  for (int y = 0; y < kPrimaryResolution; ++y)
    for (int x = 0; x < kPrimaryResolution; ++x) {
      const float sx = (2 * (x + 0.5f) / kPrimaryResolution - 1) * h;
      const float sy = (1 - 2 * (y + 0.5f) / kPrimaryResolution) * h;
      rays.push_back({{eye, normalize(forward + right * sx + up * sy)}, kInfinity});
    }
  return rays;
}

/// `count` rays from uniform points on the bounding sphere toward uniform points in the box.
std::vector<Query> incoherent_rays(const Bounds3& box, size_t count, uint64_t seed) {
  const Sphere s = bounding_sphere(box);
  const Vector3 d = box.diagonal();
  std::vector<Query> rays;
  rays.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    RandomStream rng(seed, i, 0);
    const float z = 1 - 2 * rng.uniform();
    const float phi = 2 * std::numbers::pi_v<float> * rng.uniform();
    const float r = std::sqrt(std::max(0.f, 1 - z * z));
    const Point3 origin = s.centre + Vector3(r * std::cos(phi), r * std::sin(phi), z) * s.radius;
    const Point3 target = box.lo + Vector3(d.x * rng.uniform(), d.y * rng.uniform(), d.z * rng.uniform());
    rays.push_back({{origin, normalize(target - origin)}, kInfinity});
  }
  return rays;
}

/// Shadow queries from every primary hit (found by `reference`) toward a point light above and
/// beside the mesh, spawned as the integrator spawns them.
std::vector<Query> shadow_rays(const World& world, const Accelerator& reference, const Bounds3& box, int threads) {
  const Sphere s = bounding_sphere(box);
  const Point3 light = s.centre + Vector3(0.6f, 2.0f, 0.3f) * s.radius;
  const std::vector<Query> primary = primary_rays(box);
  std::vector<std::optional<Query>> found(primary.size());
  const int chunks = int((primary.size() + kChunk - 1) / kChunk);
  parallel_for(chunks, threads, [&](int c, int) {
    const size_t end = std::min(primary.size(), size_t(c + 1) * kChunk);
    for (size_t i = size_t(c) * kChunk; i < end; ++i) {
      const auto hit = reference.intersect(primary[i].ray, {0, primary[i].t_max});
      if (!hit) continue;
      const SurfaceInteraction si = world.interaction(primary[i].ray, *hit);
      found[i] = Query{spawn_ray_to(si, light), kShadowTMax};
    }
  });
  std::vector<Query> rays;
  for (const auto& q : found)
    if (q) rays.push_back(*q);
  return rays;
}

/// `max` rays evenly strided over `rays` (all of them when max is 0 or large enough).
std::vector<Query> subset(std::vector<Query> rays, size_t max) {
  if (max == 0 || max >= rays.size()) return rays;
  std::vector<Query> out;
  out.reserve(max);
  for (size_t i = 0; i < max; ++i) out.push_back(rays[i * rays.size() / max]);
  return out;
}

/// Traces every query once on `threads` threads; returns the number that hit (or were occluded).
size_t trace(const Accelerator& accel, const std::vector<Query>& rays, bool shadow, int threads) {
  const int chunks = int((rays.size() + kChunk - 1) / kChunk);
  std::vector<size_t> hits(size_t(chunks), 0);
  parallel_for(chunks, threads, [&](int c, int) {
    const size_t end = std::min(rays.size(), size_t(c + 1) * kChunk);
    size_t n = 0;
    for (size_t i = size_t(c) * kChunk; i < end; ++i)
      n += shadow ? accel.occluded(rays[i].ray, rays[i].t_max) : accel.intersect(rays[i].ray, {0, rays[i].t_max}).has_value();
    hits[size_t(c)] = n;
  });
  size_t total = 0;
  for (size_t n : hits) total += n;
  return total;
}

std::string json_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  // The heap on large pages, as the renderer has it (core/large_page_heap.h).
  back_heap_with_large_pages(size_t(256) << 20);
  const Options o = parse(argc, argv);
  try {
    // Load the mesh.
    auto start = Clock::now();
    const World world = world_from_obj(load_obj(o.mesh));
    const double load_seconds = seconds_since(start);
    const Bounds3 box = world.primitives.bounds();

    // Compute the rays: the same for every accelerator (shadow rays start at hits found by a
    // fixed reference structure, built untimed).
    std::vector<Query> rays;
    if (o.rays == "primary") {
      rays = primary_rays(box);
    } else if (o.rays == "incoherent") {
      rays = incoherent_rays(box, o.ray_count, o.seed);
    } else {
#ifdef MJRAY_HAVE_EMBREE
      const auto reference = make_accelerator(world.primitives, {"embree", 0, 0});
#else
      const auto reference = make_accelerator(world.primitives, {"bvh", 0, 0});
#endif
      rays = shadow_rays(world, *reference, box, std::max(o.threads, 2));
    }
    rays = subset(std::move(rays), o.max_rays);
    const bool shadow = o.rays == "shadow" && !o.closest;

    // Build K times; keep the last structure.
    // Embree is timed alone: its hits are not refined with mjray's triangle test.
    AcceleratorOptions accel_options{o.accel, o.grid, o.build_threads};
    accel_options.embree_exact_hits = false;
    accel_options.embree_robust = o.embree_flags == "robust";
    std::vector<double> builds;
    std::unique_ptr<Accelerator> accel;
    for (int k = 0; k < o.repeat; ++k) {
      accel.reset();
      start = Clock::now();
      accel = make_bench_accelerator(world.primitives, accel_options, o.tree);
      builds.push_back(seconds_since(start));
    }
    // The SAH cost in mjray's cost model (a node 2 primitive tests), for comparing trees.
    const auto* bvh = dynamic_cast<const Bvh*>(accel.get());
    const double sah_cost = bvh ? bvh->sah_cost(BvhBuildOptions{}.traversal_cost, 1) : 0;
    int grid_resolution = 0;
    if (const auto* grid = dynamic_cast<const UniformGrid*>(accel.get())) grid_resolution = grid->resolution();

    // Trace once to warm caches and to choose how many passes over the rays make one timed
    // sample last at least --min-ms (short samples are mostly noise on a busy machine);
    // a warm-up that is already that long counts as the first sample.
    std::vector<double> traces;
    start = Clock::now();
    size_t hits = trace(*accel, rays, shadow, o.threads);
    const double warm_up = seconds_since(start);
    const int passes = warm_up >= o.min_seconds ? 1 : int(std::ceil(o.min_seconds / std::max(warm_up, 1e-6)));
    if (warm_up >= o.min_seconds) traces.push_back(warm_up);

    // Trace K samples (seconds per pass over the rays).
    while (int(traces.size()) < o.repeat) {
      start = Clock::now();
      for (int p = 0; p < passes; ++p) hits = trace(*accel, rays, shadow, o.threads);
      traces.push_back(seconds_since(start) / passes);
    }
    const double trace_seconds = median(traces);

    std::printf("{\"mesh\": \"%s\", \"triangles\": %zu, \"accel\": \"%s\", \"grid\": %d, \"threads\": %d, "
                "\"ray_kind\": \"%s\", \"query\": \"%s\", \"rays\": %zu, \"hits\": %zu, \"repeat\": %d, \"load_seconds\": %.6f, "
                "\"build_seconds\": %.6f, \"build_seconds_min\": %.6f, \"accel_bytes\": %zu, "
                "\"bytes_per_triangle\": %.2f, \"trace_seconds\": %.6f, \"trace_seconds_min\": %.6f, "
                "\"rays_per_second\": %.1f, \"passes\": %d, \"build_threads\": %d, \"embree_flags\": \"%s\", "
                "\"tree\": \"%s\", \"sah_cost\": %.4f}\n",
                json_escape(o.mesh).c_str(), world.primitives.triangles.size(), std::string(accel->name()).c_str(),
                grid_resolution, o.threads, o.rays.c_str(), shadow ? "occluded" : "intersect", rays.size(), hits, o.repeat, load_seconds,
                median(builds), *std::min_element(builds.begin(), builds.end()), accel->memory_bytes(),
                world.primitives.triangles.empty() ? 0.0 : double(accel->memory_bytes()) / double(world.primitives.triangles.size()),
                trace_seconds, *std::min_element(traces.begin(), traces.end()),
                trace_seconds > 0 ? double(rays.size()) / trace_seconds : 0.0, passes, o.build_threads,
                o.accel == "embree" ? o.embree_flags.c_str() : "", o.accel == "bvh" ? o.tree.c_str() : "", sah_cost);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mjray-bench: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
