#include "mjray/accel/uniform_grid.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "mjray/core/float_steps.h"
#include "mjray/geometry/triangle.h"

namespace mjray {

namespace {

// 256³ ≈ 16.8M voxels (64 MiB of offsets) bounds memory for -g 4096 and huge -o scenes.
constexpr int kMaxResolution = 256;
// References beyond max(kMinReferenceBudget, kReferencesPerPrimitive·N) (≥ 64 MiB) halve the
// resolution: large shapes in a fine grid would otherwise fill gigabytes.
constexpr uint64_t kMinReferenceBudget = uint64_t(1) << 24;
constexpr uint64_t kReferencesPerPrimitive = 16;
// Voxel boxes are grown by this fraction of a voxel (plus a few ulps of the coordinates) when
// listing primitives, so that DDA rounding near voxel faces, edges and corners never skips a
// primitive: a ray whose computed path grazes a neighbouring voxel still finds it.
constexpr double kMembershipPad = 1e-3;

struct Double3 {
  double x = 0, y = 0, z = 0;
};

Double3 operator-(const Double3& a, const Double3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const Double3& a, const Double3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Double3 cross(const Double3& a, const Double3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// A triangle prepared for many box tests against equal-sized boxes: the separating-axis test
// of Akenine-Möller (2001) with the triangle's projections onto the 10 non-box axes (face
// normal and the 9 edge × box-axis crosses) computed once. The 3 box axes are covered by the
// voxel range of the triangle's AABB.
class TriangleBoxTester {
 public:
  TriangleBoxTester(const std::array<Point3, 3>& p, const Double3& half) {
    const Double3 v[3] = {{p[0].x, p[0].y, p[0].z}, {p[1].x, p[1].y, p[1].z}, {p[2].x, p[2].y, p[2].z}};
    const Double3 e[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    const Double3 unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    axes_[0] = cross(e[0], e[1]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) axes_[1 + 3 * i + j] = cross(e[i], unit[j]);
    for (int k = 0; k < kAxes; ++k) {
      const Double3& a = axes_[k];
      const double d0 = dot(v[0], a), d1 = dot(v[1], a), d2 = dot(v[2], a);
      lo_[k] = std::min({d0, d1, d2});
      hi_[k] = std::max({d0, d1, d2});
      radius_[k] = half.x * std::abs(a.x) + half.y * std::abs(a.y) + half.z * std::abs(a.z);
    }
  }

  /// Whether the triangle meets the box of the given centre (and the constructor's half size).
  bool overlaps(const Double3& centre) const {
    for (int k = 0; k < kAxes; ++k) {
      const double c = dot(centre, axes_[k]);
      if (lo_[k] - c > radius_[k] || hi_[k] - c < -radius_[k]) return false;
    }
    return true;
  }

 private:
  static constexpr int kAxes = 10;
  std::array<Double3, kAxes> axes_;
  std::array<double, kAxes> lo_, hi_, radius_;
};

bool is_finite(const Bounds3& b) { return is_finite(b.lo) && is_finite(b.hi); }

}  // namespace

std::string UniformGrid::resolution_note() const {
  if (resolution_ >= requested_resolution_) return "";
  const int capped = std::min(requested_resolution_, kMaxResolution);
  std::string note = "grid resolution " + std::to_string(requested_resolution_);
  if (requested_resolution_ > kMaxResolution) note += " is above the limit of " + std::to_string(kMaxResolution) + " voxels per axis";
  if (resolution_ < capped) {
    note += requested_resolution_ > kMaxResolution ? ", and " : " ";
    note += std::to_string(2 * resolution_) + "³ voxels would list more than " + std::to_string(reference_budget_) +
            " primitive references (the memory budget)";
  }
  return note + "; the grid uses " + std::to_string(resolution_) + "³ voxels";
}

int optimal_grid_resolution(size_t primitive_count) {
  return std::max(1, int(std::lround(3 * std::cbrt(double(primitive_count)))));
}

UniformGrid::UniformGrid(const PrimitiveSet& prims, int resolution)
    : primitives_(prims), triangle_count_(uint32_t(prims.triangles.size())) {
  // Copy triangle corners into one array, so voxel tests read them without indirection.
  corners_.reserve(triangle_count_);
  for (uint32_t prim = 0; prim < triangle_count_; ++prim) {
    const auto v = prims.triangle_vertices(prim);
    using Floats = std::array<float, 3>;
    corners_.push_back({std::bit_cast<Floats>(v[0]), std::bit_cast<Floats>(v[1]), std::bit_cast<Floats>(v[2])});
  }

  // Compute primitive bounds; primitives without finite bounds cannot be placed in voxels.
  const uint32_t n = prims.size();
  std::vector<Bounds3> prim_bounds(n);
  for (uint32_t prim = 0; prim < n; ++prim) {
    prim_bounds[prim] = prims.primitive_bounds(prim);
    if (is_finite(prim_bounds[prim]))
      bounds_.expand(prim_bounds[prim]);
    else
      unbounded_.push_back(prim);
  }
  const size_t bounded = n - unbounded_.size();
  if (resolution == 0) resolution = optimal_grid_resolution(n);
  requested_resolution_ = std::max(resolution, 1);
  resolution_ = std::clamp(resolution, 1, kMaxResolution);
  if (bounded == 0) {
    voxel_begin_.assign(2, 0);
    return;
  }

  // Compute the grid box: flat axes widened so voxels have volume, then padded so that
  // primitives on the scene boundary lie strictly inside.
  Vector3 extent = bounds_.diagonal();
  const float magnitude = std::max(max_component(abs(bounds_.lo)), max_component(abs(bounds_.hi)));
  const float min_extent = std::max({1e-3f * max_component(extent), 1e-5f * magnitude, 1e-12f});
  Point3 lo = bounds_.lo, hi = bounds_.hi;
  for (int a = 0; a < 3; ++a) {
    if (extent[a] < min_extent) {
      const float centre = 0.5f * (lo[a] + hi[a]);
      lo[a] = centre - 0.5f * min_extent;
      hi[a] = centre + 0.5f * min_extent;
    }
  }
  extent = hi - lo;
  const float box_pad = 1e-4f * max_component(extent) + 1e-6f * magnitude;
  grid_lo_ = lo - Vector3(box_pad, box_pad, box_pad);
  grid_hi_ = hi + Vector3(box_pad, box_pad, box_pad);
  const double coordinate_pad = 1e-6 * std::max(max_component(abs(grid_lo_)), max_component(abs(grid_hi_)));

  const uint64_t budget = std::min<uint64_t>(std::max(kMinReferenceBudget, kReferencesPerPrimitive * bounded),
                                             std::numeric_limits<uint32_t>::max());  // offsets are 32-bit
  reference_budget_ = budget;
  for (;;) {
    const int r = resolution_;
    for (int a = 0; a < 3; ++a) {
      voxel_size_[a] = (grid_hi_[a] - grid_lo_[a]) / float(r);
      inv_voxel_size_[a] = 1 / voxel_size_[a];
    }
    double pad[3];
    for (int a = 0; a < 3; ++a) pad[a] = kMembershipPad * voxel_size_[a] + coordinate_pad;
    const Double3 half{0.5 * voxel_size_.x + pad[0], 0.5 * voxel_size_.y + pad[1], 0.5 * voxel_size_.z + pad[2]};

    // Visits the voxels primitive `prim` overlaps; returns false as soon as `visit` does.
    const auto for_each_voxel = [&](uint32_t prim, auto&& visit) {
      const Bounds3& b = prim_bounds[prim];
      int first[3], last[3], spanning = 0;
      for (int a = 0; a < 3; ++a) {
        const double lo_cell = (double(b.lo[a]) - pad[a] - grid_lo_[a]) * inv_voxel_size_[a];
        const double hi_cell = (double(b.hi[a]) + pad[a] - grid_lo_[a]) * inv_voxel_size_[a];
        first[a] = int(std::clamp(std::floor(lo_cell), 0.0, double(r - 1)));
        last[a] = int(std::clamp(std::floor(hi_cell), 0.0, double(r - 1)));
        spanning += last[a] > first[a];
      }
      // A triangle spanning voxels along at most one axis meets every voxel of that run.
      const bool test_each = prims.is_triangle(prim) && spanning >= 2;
      std::optional<TriangleBoxTester> tester;
      if (test_each) tester.emplace(prims.triangle_vertices(prim), half);
      for (int z = first[2]; z <= last[2]; ++z)
        for (int y = first[1]; y <= last[1]; ++y)
          for (int x = first[0]; x <= last[0]; ++x) {
            if (test_each) {
              const Double3 centre{grid_lo_.x + (x + 0.5) * double(voxel_size_.x),
                                   grid_lo_.y + (y + 0.5) * double(voxel_size_.y),
                                   grid_lo_.z + (z + 0.5) * double(voxel_size_.z)};
              if (!tester->overlaps(centre)) continue;
            }
            if (!visit(uint32_t(x + r * (y + r * z)))) return false;
          }
      return true;
    };

    // Pass 1: count each voxel's primitives (in the slot after it), giving up on the budget.
    const size_t voxels = size_t(r) * r * r;
    voxel_begin_.assign(voxels + 1, 0);
    uint64_t total = 0;
    bool within_budget = true;
    for (uint32_t prim = 0; prim < n && within_budget; ++prim) {
      if (!is_finite(prim_bounds[prim])) continue;
      within_budget = for_each_voxel(prim, [&](uint32_t v) {
        ++voxel_begin_[v + 1];
        return ++total <= budget;
      });
    }
    if (!within_budget && r > 1) {
      resolution_ = std::max(1, r / 2);
      continue;
    }

    // Pass 2: prefix sums give each voxel's range; fill the ranges in primitive order.
    occupied_.assign((voxels + 63) / 64, 0);
    for (size_t v = 0; v < voxels; ++v) {
      if (voxel_begin_[v + 1]) occupied_[v / 64] |= uint64_t(1) << (v % 64);
      voxel_begin_[v + 1] += voxel_begin_[v];
    }
    prims_.resize(total);
    std::vector<uint32_t> cursor(voxel_begin_.begin(), voxel_begin_.end() - 1);
    for (uint32_t prim = 0; prim < n; ++prim) {
      if (!is_finite(prim_bounds[prim])) continue;
      for_each_voxel(prim, [&](uint32_t v) {
        prims_[cursor[v]++] = prim;
        return true;
      });
    }
    break;
  }
}

size_t UniformGrid::memory_bytes() const {
  return sizeof(*this) + (voxel_begin_.capacity() + prims_.capacity() + unbounded_.capacity()) * sizeof(uint32_t) +
         occupied_.capacity() * sizeof(uint64_t) + corners_.capacity() * sizeof(corners_[0]);
}

std::optional<Hit> UniformGrid::intersect(const Ray& ray, Interval t_range) const {
  return traverse<false>(ray, t_range);
}

bool UniformGrid::occluded(const Ray& ray, float t_max) const {
  return traverse<true>(ray, {0, t_max}).has_value();
}

bool UniformGrid::occluded(const Ray& ray, Interval t_range, HitFilter& filter) const {
  return traverse<true>(ray, t_range, &filter).has_value();
}

template <bool kAnyHit>
std::optional<Hit> UniformGrid::traverse(const Ray& ray, Interval t_range, HitFilter* filter) const {
  std::optional<Hit> nearest;
  const float t_min = t_range.min;
  float t_max = t_range.max;
  if (!(t_max > t_min) || !is_finite(ray.origin) || !is_finite(ray.direction)) return nearest;

  // A hit ends an any-hit query unless the filter lets the ray pass a transmissive primitive.
  const auto blocks = [&](const Hit& hit) {
    return !filter || !primitives_.filtered(hit.prim, filter->sees_opaque) || filter->blocks(hit);
  };
  // A closest hit at exactly the nearest t so far wins only with a lower primitive id, as
  // with every accelerator; so the range reaches one float past that t once one is found.
  const auto reach = [&] { return nearest ? next_float(t_max, true) : t_max; };
  const auto nearer = [&](const Hit& hit) {
    return !nearest || hit.t < t_max || (hit.t == t_max && hit.prim < nearest->prim);
  };
  // Test the primitives that live outside the voxels.
  for (const uint32_t prim : unbounded_) {
    if (auto hit = primitives_.intersect(prim, ray, {t_min, reach()})) {
      if constexpr (kAnyHit) {
        if (blocks(*hit)) return hit;
        continue;
      }
      if (!nearer(*hit)) continue;
      t_max = hit->t;
      nearest = hit;
    }
  }
  if (prims_.empty()) return nearest;

  // Clip the ray to the grid box; a direction component too small to invert makes the ray
  // parallel to that axis's slabs.
  float inv_dir[3];
  float t_enter = t_min, t_exit = t_max;
  for (int a = 0; a < 3; ++a) {
    inv_dir[a] = 1 / ray.direction[a];
    if (!std::isfinite(inv_dir[a])) {
      inv_dir[a] = kInfinity;
      if (ray.origin[a] < grid_lo_[a] || ray.origin[a] > grid_hi_[a]) return nearest;
      continue;
    }
    float t_near = (grid_lo_[a] - ray.origin[a]) * inv_dir[a];
    float t_far = (grid_hi_[a] - ray.origin[a]) * inv_dir[a];
    if (t_near > t_far) std::swap(t_near, t_far);
    t_enter = std::max(t_enter, t_near);
    t_exit = std::min(t_exit, t_far);
  }
  if (!(t_enter <= t_exit)) return nearest;

  // Set up the 3-D DDA (Amanatides and Woo 1987) from the voxel holding the entry point.
  // Crossing distances are recomputed from the origin at each step rather than accumulated,
  // so they stay accurate to a few ulps however many voxels the ray crosses.
  const int r = resolution_;
  const Point3 entry = ray.at(t_enter);
  int cell[3], step[3], out[3], voxel_step[3];
  float from_origin[3], t_next[3];  // grid_lo − origin; distance to the next plane per axis
  const int stride[3] = {1, r, r * r};
  const auto plane_t = [&](int a) {
    return (from_origin[a] + float(cell[a] + (step[a] > 0)) * voxel_size_[a]) * inv_dir[a];
  };
  for (int a = 0; a < 3; ++a) {
    const float c = std::floor((entry[a] - grid_lo_[a]) * inv_voxel_size_[a]);
    cell[a] = int(std::clamp(c, 0.f, float(r - 1)));
    from_origin[a] = grid_lo_[a] - ray.origin[a];
    step[a] = inv_dir[a] == kInfinity ? 0 : (ray.direction[a] > 0 ? 1 : -1);
    out[a] = step[a] > 0 ? r : -1;
    voxel_step[a] = step[a] * stride[a];
    t_next[a] = step[a] ? plane_t(a) : kInfinity;
  }
  int voxel = cell[0] + r * (cell[1] + r * cell[2]);

  // Walk voxel to voxel. Hits beyond the current voxel are kept (the primitive may span it),
  // but only a hit no farther than the voxel's exit ends the walk. A small ray-local mailbox
  // skips most re-tests of primitives that span several voxels.
  constexpr uint32_t kMailboxSize = 8;
  uint32_t mailbox[kMailboxSize];
  std::fill_n(mailbox, kMailboxSize, std::numeric_limits<uint32_t>::max());
  const WatertightRay watertight(ray);
  const uint64_t* occupied = occupied_.data();
  float t_stop = t_exit;
  for (;;) {
    if (occupied[voxel >> 6] & (uint64_t(1) << (voxel & 63))) {
      for (uint32_t i = voxel_begin_[voxel], end = voxel_begin_[voxel + 1]; i < end; ++i) {
        const uint32_t prim = prims_[i];
        uint32_t& slot = mailbox[prim % kMailboxSize];
        if (slot == prim) continue;
        slot = prim;
        // Triangles use World's watertight test on the packed corners (the same arithmetic).
        std::optional<Hit> hit;
        if (prim < triangle_count_) {
          const auto& c = corners_[prim];
          if (const auto h = intersect_triangle(watertight, {t_min, reach()}, c[0], c[1], c[2]))
            hit = Hit{h->t, prim, h->b1, h->b2};
        } else {
          hit = primitives_.intersect_shape(prim, ray, {t_min, reach()});
        }
        if (hit) {
          if constexpr (kAnyHit) {
            if (blocks(*hit)) return hit;
            continue;
          }
          if (!nearer(*hit)) continue;
          t_max = hit->t;
          t_stop = std::min(t_stop, t_max);
          nearest = hit;
        }
      }
    }
    const int axis = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    if (t_next[axis] >= t_stop) break;
    cell[axis] += step[axis];
    if (cell[axis] == out[axis]) break;
    voxel += voxel_step[axis];
    t_next[axis] = plane_t(axis);
  }
  return nearest;
}

}  // namespace mjray
