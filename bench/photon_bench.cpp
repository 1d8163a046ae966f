// mjray-photon-bench: the neighbour searches photon mapping makes, on the photon maps of a real
// scene, through the kd-tree mjray uses and through a hashed uniform grid, to choose between them.
// Prints one JSON line per structure (build seconds, queries per second, checksum).
//
//   mjray-photon-bench SCENE.lua --caustics N | --gi N [--cell F]... [--repeat K]
//
// --caustics: the k-nearest caustic estimate (mjray's k) at the first surface each pixel
// centre sees. --gi: the nearest precomputed irradiance (k = 1) where a gather ray from each pixel's
// surface lands. Each --cell F is one grid, cells F times the estimate's largest radius
// (caustics) or F times the mean spacing of the samples (irradiance). One thread; queries are
// timed in thread CPU time, the fastest of K passes; builds in wall time.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "mjray/geometry/spawn_ray.h"
#include "mjray/integrator/closest_surface.h"
#include "mjray/integrator/photon/density_estimate.h"
#include "mjray/job/prepared_job.h"
#include "mjray/lua/scene_loader.h"

namespace {

using namespace mjray;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// This thread's CPU time: on a machine shared with other work it counts only this work.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

/// A hashed uniform grid of cells `cell` wide: each item's cell coordinates hash to a bucket,
/// and a bucket's items are contiguous, each with its cell, so cells sharing a bucket are told
/// apart (Jensen's and most GPU photon mappers' alternative to a kd-tree).
template <class Item>
class HashGrid {
 public:
  HashGrid(std::vector<Item> items, float cell) : cell_(cell) {
    buckets_ = 1;
    while (buckets_ < 2 * items.size()) buckets_ *= 2;
    std::vector<uint32_t> counts(buckets_, 0);
    for (const Item& item : items) ++counts[bucket_of(cell_of(item.position))];
    starts_.assign(buckets_ + 1, 0);
    for (size_t b = 0; b < buckets_; ++b) starts_[b + 1] = starts_[b] + counts[b];
    items_.resize(items.size());
    cells_.resize(items.size());
    std::vector<uint32_t> fill(starts_.begin(), starts_.end() - 1);
    for (const Item& item : items) {
      const auto c = cell_of(item.position);
      const uint32_t at = fill[bucket_of(c)]++;
      items_[at] = item;
      cells_[at] = c;
    }
  }

  /// The k nearest accepted items within √max_distance2, by rings of cells around p's cell.
  template <class Accept>
  Neighbourhood nearest(const Point3& p, float max_distance2, Accept&& accept, std::span<Neighbour> out) const {
    size_t count = 0;
    float radius2 = max_distance2;
    const std::array<int, 3> centre = cell_of(p);
    const int rings = int(std::ceil(std::sqrt(max_distance2) / cell_));
    for (int ring = 0; ring <= rings; ++ring) {
      // Every item closer than (ring − 1)·cell is in the rings already searched.
      if (ring > 0 && count == out.size() && radius2 <= float(ring - 1) * cell_ * float(ring - 1) * cell_) break;
      for (int dz = -ring; dz <= ring; ++dz)
        for (int dy = -ring; dy <= ring; ++dy)
          for (int dx = -ring; dx <= ring; ++dx) {
            if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring) continue;
            const std::array<int, 3> c{centre[0] + dx, centre[1] + dy, centre[2] + dz};
            const size_t b = bucket_of(c);
            for (uint32_t i = starts_[b]; i < starts_[b + 1]; ++i) {
              if (cells_[i] != c) continue;
              const Vector3 d = items_[i].position - p;
              const float distance2 = dot(d, d);
              if (distance2 >= radius2 || !accept(items_[i].normal)) continue;
              if (count < out.size()) {
                out[count++] = {distance2, i};
                std::push_heap(out.begin(), out.begin() + ptrdiff_t(count));
              } else {
                std::pop_heap(out.begin(), out.end());
                out.back() = {distance2, i};
                std::push_heap(out.begin(), out.end());
              }
              if (count == out.size()) radius2 = out[0].distance2;
            }
          }
    }
    return {out.first(count), count == out.size() ? out[0].distance2 : max_distance2};
  }
  std::span<const Item> items() const { return items_; }

 private:
  std::array<int, 3> cell_of(const Point3& p) const {
    return {int(std::floor(p.x / cell_)), int(std::floor(p.y / cell_)), int(std::floor(p.z / cell_))};
  }
  size_t bucket_of(const std::array<int, 3>& c) const {
    const uint64_t h = uint64_t(uint32_t(c[0])) * 73856093ULL ^ uint64_t(uint32_t(c[1])) * 19349663ULL ^
                       uint64_t(uint32_t(c[2])) * 83492791ULL;
    return size_t(mix64(h) & (buckets_ - 1));
  }

  float cell_;
  size_t buckets_ = 1;
  std::vector<uint32_t> starts_;
  std::vector<Item> items_;
  std::vector<std::array<int, 3>> cells_;
};

/// A query point on a surface, with the normal facing the way it was seen.
struct Query {
  Point3 p;
  Normal3 n;
};

/// What one structure answered over all queries.
struct Timing {
  double build = 0, seconds = 0, checksum = 0;
};

/// The fastest of `repeat` passes of `pass()` in CPU time (the least disturbed by other work
/// on a shared machine), which returns its checksum.
template <class Pass>
Timing time_queries(int repeat, Pass&& pass) {
  std::vector<double> times;
  Timing t;
  for (int r = 0; r < repeat; ++r) {
    const double start = thread_seconds();
    t.checksum = pass();
    times.push_back(thread_seconds() - start);
  }
  t.seconds = *std::min_element(times.begin(), times.end());
  return t;
}

/// The sum of the k nearest accepted items' first colour channel at every query.
template <class Map, class Value>
double sum_nearest(const Map& map, const std::vector<Query>& queries, int k, float radius, Value value) {
  std::array<Neighbour, kMaxNeighbours> scratch;
  double sum = 0;
  for (const Query& q : queries) {
    const auto near = map.nearest(q.p, radius * radius, [&](const PackedNormal& normal) { return faces_alike(normal, q.n); },
                                  std::span(scratch).first(size_t(k)));
    for (const Neighbour& found : near.found) sum += value(map.items()[found.index]);
  }
  return sum;
}

void print(const char* what, const char* structure, double cell, size_t items, size_t queries, const Timing& t) {
  std::printf("{\"queries\": \"%s\", \"structure\": \"%s\", \"cell\": %.3f, \"items\": %zu, \"query_count\": %zu, "
              "\"build_seconds\": %.4f, \"queries_per_second\": %.0f, \"checksum\": %.6g}\n",
              what, structure, cell, items, queries, t.build, double(queries) / t.seconds, t.checksum);
}

/// Times the k-nearest queries on a kd-tree rebuilt from `tree`'s items and on a hashed grid
/// for each cell size (`cells` × `unit`), printing a line for each.
template <class Item, class Value>
void compare(const char* what, const KdTree<Item>& tree, const std::vector<Query>& queries, int k, float radius,
             float unit, const std::vector<float>& cells, int repeat, Value value) {
  const std::vector<Item> items(tree.items().begin(), tree.items().end());
  auto start = Clock::now();
  const KdTree<Item> rebuilt(items, 1);
  const double build = seconds_since(start);
  Timing t = time_queries(repeat, [&] { return sum_nearest(rebuilt, queries, k, radius, value); });
  t.build = build;
  print(what, "kd-tree", 0, items.size(), queries.size(), t);
  for (const float f : cells) {
    start = Clock::now();
    const HashGrid<Item> grid(items, unit * f);
    const double grid_build = seconds_since(start);
    Timing g = time_queries(repeat, [&] { return sum_nearest(grid, queries, k, radius, value); });
    g.build = grid_build;
    print(what, "grid", f, items.size(), queries.size(), g);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: mjray-photon-bench SCENE.lua --caustics N | --gi N [--cell F]... [--repeat K]\n");
    return 2;
  }
  JobOptions options;
  options.render.threads = 1;
  std::vector<float> cells;
  int repeat = 3;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--caustics") options.photons.caustic_photons = uint64_t(std::atof(argv[i + 1]));
    else if (a == "--gi") options.photons.global_photons = uint64_t(std::atof(argv[i + 1]));
    else if (a == "--cell") cells.push_back(float(std::atof(argv[i + 1])));
    else if (a == "--repeat") repeat = std::atoi(argv[i + 1]);
  }
  const SceneDescription scene = load_scene(argv[1], {});
  const PreparedJob job(scene, 0, options);
  const World& world = job.world();
  // Compute the query points: each pixel centre's first surface, or where a gather ray from it lands.
  const bool caustics = options.photons.caustics();
  std::vector<Query> queries;
  RandomStream random(1, 0, 0);
  for (int y = 0; y < job.height(); ++y)
    for (int x = 0; x < job.width(); ++x) {
      Ray ray = job.camera().generate_ray(float(x) + 0.5f, float(y) + 0.5f);
      auto hit = closest_surface(world, job.accelerator(), ray);
      if (hit && !caustics) {
        const Normal3 n = face_forward(hit->shading_normal, -ray.direction);
        const float u1 = random.uniform(), u2 = random.uniform();
        ray = spawn_ray(*hit, sample_cosine_hemisphere(Vector3(n), u1, u2));
        hit = closest_surface(world, job.accelerator(), ray);
      }
      if (hit) queries.push_back({hit->point, face_forward(hit->shading_normal, -ray.direction)});
    }
  const PhotonStatistics& stats = *job.photon_statistics();
  std::fprintf(stderr, "photon pass %.3fs, %zu queries\n", stats.seconds(), queries.size());

  // The photon maps again, owned here, to build every structure over the same items.
  const PhotonMaps own(world, job.accelerator(), options.photons, 0, 1);
  if (caustics) {
    compare("caustic k-nearest", own.caustic(), queries, own.caustic_query().neighbours, own.caustic_query().max_radius,
            own.caustic_query().max_radius, cells, repeat, [](const Photon& p) { return double(p.power.g); });
  } else {
    // Cells in units of the mean spacing of samples on the surfaces: √(area per sample), the
    // area from the map's box.
    const Vector3 d = own.irradiance().bounds().diagonal();
    const float spacing = std::sqrt(2 * (d.x * d.y + d.y * d.z + d.z * d.x) / float(own.irradiance().size()));
    compare("irradiance nearest", own.irradiance(), queries, 1, own.global_query().max_radius, spacing, cells, repeat,
            [](const IrradianceSample& s) { return double(s.irradiance.g); });
  }
  return 0;
}
