#include "mjray/accel/bvh.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
// GCC on x86 compiles an AVX variant of traversal beside the baseline one (#pragma GCC
// target), picked at run time, so the default build needs no -march flag.
#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__) && !defined(__clang__)
#define MJRAY_BVH_HAS_AVX 1
#include <immintrin.h>
#else
#define MJRAY_BVH_HAS_AVX 0
#endif

#include "mjray/accel/bvh_builder.h"
#include "mjray/core/float_steps.h"
#include "mjray/core/parallel_for.h"
#include "mjray/geometry/triangle.h"

namespace mjray {

namespace {

// The builder's binary depth stays under 64 and collapsing never deepens it; each wide
// node pushes at most kBvhWidth − 1 entries.
constexpr int kStackSize = (kBvhWidth - 1) * 64 + 1;

// Widens the far slab distance by 2γ₃ (pbrt-v4) so rounding never culls a box the ray
// actually touches.
constexpr float kGamma3 = 3 * std::numeric_limits<float>::epsilon() * 0.5f /
                          (1 - 3 * std::numeric_limits<float>::epsilon() * 0.5f);
constexpr float kFarScale = 1 + 2 * kGamma3;

bool is_valid_ray(const Ray& ray, Interval t_range) {
  return is_finite(ray.origin) && is_finite(ray.direction) && t_range.max > t_range.min;
}

/// A pending child: a node (count 0) or a leaf, and where the ray enters its box.
struct StackEntry {
  uint32_t child;
  uint32_t count;
  float t_enter;
};

/// What traversal reads of a Bvh.
struct TraversalView {
  const BvhWideNode* nodes;
  const LeafPrimitive* leaves;
  const PrimitiveSet* prims;
  uint32_t triangle_count;
  bool only_triangles;  // no shapes: a leaf's entries need no check of their kind
};

namespace baseline {
#define MJRAY_BVH_AVX 0
#include "mjray/accel/bvh_traversal_impl.h"
#undef MJRAY_BVH_AVX
}  // namespace baseline

#if MJRAY_BVH_HAS_AVX
#pragma GCC push_options
#pragma GCC target("avx")
namespace avx {
#define MJRAY_BVH_AVX 1
#include "mjray/accel/bvh_traversal_impl.h"
#undef MJRAY_BVH_AVX
}  // namespace avx
#pragma GCC pop_options
#endif

bool cpu_has_avx() {
#if MJRAY_BVH_HAS_AVX
  return __builtin_cpu_supports("avx");
#else
  return false;
#endif
}

}  // namespace

Bvh::Bvh(const PrimitiveSet& prims, int threads, BvhSimd simd)
    : prims_(prims),
      triangle_count_(uint32_t(prims.triangles.size())),
      use_avx_(simd == BvhSimd::kBest && cpu_has_avx()) {
  // Build the binary tree over the primitives' bounds, widen it, then copy the triangles into
  // leaf order.
  if (prims.size() > BvhWideNode::kMaxLeafPrimitives)
    throw std::length_error("the BVH indexes at most " + std::to_string(BvhWideNode::kMaxLeafPrimitives) +
                            " primitives; use --accel embree for this scene");
  static_assert(BvhBuildOptions{}.max_leaf_size < (1 << BvhWideNode::kCountBits));
  // Each structure is released as soon as the next is made: the build's peak memory is the
  // mesh scene's peak.
  BvhBuildResult built = build_bvh(prims.size(), [&](uint32_t prim) { return prims.primitive_bounds(prim); },
                                   {.threads = threads});
  nodes_ = collapse_to_wide(built.nodes);
  if (!built.nodes.empty()) {
    const BvhNode& root = built.nodes.front();
    bounds_ = {{root.lo[0], root.lo[1], root.lo[2]}, {root.hi[0], root.hi[1], root.hi[2]}};
  }
  BvhNodes().swap(built.nodes);
  leaf_prims_.resize(built.order.size());
  // The copy in chunks on all the build's threads.
  constexpr int kChunks = 64;
  parallel_for(kChunks, resolve_thread_count(threads), [&](int chunk, int) {
    for (auto [i, end] = chunk_range(built.order.size(), chunk, kChunks); i < end; ++i) {
      LeafPrimitive& leaf = leaf_prims_[i];
      leaf.prim = built.order[i];
      if (prims.is_triangle(leaf.prim)) {
        const auto v = prims.triangle_vertices(leaf.prim);
        leaf.p0 = std::bit_cast<std::array<float, 3>>(v[0]);
        leaf.p1 = std::bit_cast<std::array<float, 3>>(v[1]);
        leaf.p2 = std::bit_cast<std::array<float, 3>>(v[2]);
      } else {
        leaf.p0 = leaf.p1 = leaf.p2 = {0, 0, 0};
      }
    }
  });
}

size_t Bvh::memory_bytes() const {
  return nodes_.size() * sizeof(BvhWideNode) + leaf_prims_.size() * sizeof(LeafPrimitive);
}

template <BvhQuery kQuery>
bool Bvh::trace(const Ray& ray, Interval t_range, Hit* hit, HitFilter* filter) const {
  if (nodes_.empty() || !is_valid_ray(ray, t_range)) return false;
  const TraversalView view{nodes_.data(), leaf_prims_.data(), &prims_, triangle_count_, prims_.shapes.empty()};
  constexpr bool kFiltered = kQuery == BvhQuery::kFiltered;
#if MJRAY_BVH_HAS_AVX
  if (use_avx_) {
    if constexpr (kQuery == BvhQuery::kClosest) return avx::traverse<kQuery>(view, ray, t_range, hit, filter);
    else return avx::traverse_any<kFiltered>(view, ray, t_range, filter);
  }
#endif
  if constexpr (kQuery == BvhQuery::kClosest) return baseline::traverse<kQuery>(view, ray, t_range, hit, filter);
  else return baseline::traverse_any<kFiltered>(view, ray, t_range, filter);
}

std::optional<Hit> Bvh::intersect(const Ray& ray, Interval t_range) const {
  Hit hit{};
  if (!trace<BvhQuery::kClosest>(ray, t_range, &hit, nullptr)) return std::nullopt;
  return hit;
}

bool Bvh::occluded(const Ray& ray, float t_max) const {
  return trace<BvhQuery::kAny>(ray, {0, t_max}, nullptr, nullptr);
}

std::optional<size_t> Bvh::region_primitives(const LightPyramid& region, uint32_t ignore,
                                             std::span<uint32_t> out) const {
  if (nodes_.empty()) return 0;
  // Past this many nodes the search is not worth its cost: the rays are traced instead.
  constexpr int kNodeBudget = 48;
  uint32_t stack[kStackSize];
  int top = 0, visited = 0;
  size_t found = 0;
  stack[top++] = 0;
  while (top > 0) {
    if (++visited > kNodeBudget) return std::nullopt;
    const BvhWideNode& node = nodes_[stack[--top]];
    // Unused slots have empty boxes, which are outside.
    for (unsigned touching = ~region.outside(node.bounds) & 0xffu; touching != 0; touching &= touching - 1) {
      const size_t i = size_t(std::countr_zero(touching));
      if (!node.is_leaf(i)) {
        stack[top++] = node.child[i];
        continue;
      }
      // A leaf: each primitive not surely outside is a candidate.
      for (uint32_t k = node.first(i), end = k + node.count(i); k < end; ++k) {
        const LeafPrimitive& leaf = leaf_prims_[k];
        if (leaf.prim == ignore) continue;
        const bool outside = leaf.prim < triangle_count_
                                 ? region.outside(std::bit_cast<Point3>(leaf.p0), std::bit_cast<Point3>(leaf.p1),
                                                  std::bit_cast<Point3>(leaf.p2))
                                 : region.outside(prims_.primitive_bounds(leaf.prim));
        if (outside) continue;
        if (found == out.size()) return std::nullopt;
        out[found++] = leaf.prim;
      }
    }
  }
  return found;
}

bool Bvh::occluded(const Ray& ray, Interval t_range, HitFilter& filter) const {
  return trace<BvhQuery::kFiltered>(ray, t_range, nullptr, &filter);
}

}  // namespace mjray
