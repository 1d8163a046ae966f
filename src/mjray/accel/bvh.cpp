#include "mjray/accel/bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cmath>
#include <cstring>
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
#include "mjray/accel/bvh_traversal.h"
#include "mjray/core/error.h"
#include "mjray/core/float_steps.h"
#include "mjray/core/parallel_for.h"
#include "mjray/geometry/triangle.h"

namespace mjray {

namespace {

using namespace bvh_traversal;

constexpr size_t round_up(size_t n, size_t multiple) { return (n + multiple - 1) / multiple * multiple; }

bool is_valid_ray(const Ray& ray, Interval t_range) {
  return is_finite(ray.origin) && is_finite(ray.direction) && t_range.max > t_range.min;
}

/// The bytes a node takes in a layout, with its leaves' runs.
size_t bytes_with_runs(const BvhWideNode& node) {
  size_t bytes = sizeof(BvhWideNode);
  for (size_t c = 0; c < size_t(kBvhWidth); ++c)
    if (node.is_leaf(c)) bytes += node.count(c) * LeafRun::kBytesPerPrimitive;
  return bytes;
}

// Trees of at least kPrefetchFrom bytes load a pushed child's memory ahead (kPrefetchBytes).
constexpr size_t kPrefetchFrom = size_t(256) << 10;

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

/// mjray's own tree: binned SAH, gathered into wide nodes as it is built.
BvhTree built_tree(const PrimitiveSet& prims, int threads) {
  return build_bvh(prims.size(), [&](uint32_t prim) { return prims.primitive_bounds(prim); },
                   {.threads = threads, .shapes_from = uint32_t(prims.triangles.size())});
}

}  // namespace

Bvh::Bvh(const PrimitiveSet& prims, int threads, BvhSimd simd) : Bvh(prims, built_tree(prims, threads), threads, simd) {}

Bvh::Bvh(const PrimitiveSet& prims, BvhTree tree, int threads, BvhSimd simd)
    : prims_(prims),
      triangle_count_(uint32_t(prims.triangles.size())),
      use_avx_(simd == BvhSimd::kBest && cpu_has_avx()),
      node_count_(tree.nodes.size()),
      bounds_(tree.bounds) {
  if (tree.nodes.empty()) return;
  // Compute each node's place: in the tree's order, each node followed by its leaves' runs.
  std::vector<uint32_t> place(tree.nodes.size() + 1);
  size_t bytes = 0;
  for (size_t n = 0; n < tree.nodes.size(); ++n) {
    place[n] = uint32_t(bytes / BvhLayout::kPlaceBytes);
    const BvhWideNode& node = tree.nodes[n];
    bytes = round_up(bytes + bytes_with_runs(node), BvhLayout::kNodeAlignment);
    for (size_t c = 0; c < size_t(kBvhWidth); ++c) leaf_primitive_count_ += node.is_leaf(c) ? node.count(c) : 0;
    if (bytes > BvhLayout::kMaxBytes)
      throw std::length_error("the BVH holds at most " + std::to_string(BvhLayout::kMaxBytes >> 30) +
                              " GiB of nodes and triangles; use --accel embree for this scene");
  }
  place.back() = uint32_t(bytes / BvhLayout::kPlaceBytes);
  layout_size_ = bytes + BvhLayout::kPadding;

  // Move the nodes to their places, last first: a node's place is never before its index in
  // the array, so each lands where only nodes already moved were. The array grows in place
  // where its producer reserved room for the layout (build_bvh does).
  layout_ = std::move(tree.nodes);
  layout_.resize((layout_size_ + sizeof(BvhWideNode) - 1) / sizeof(BvhWideNode));
  std::byte* layout = layout_bytes();
  for (size_t n = node_count_; n-- > 0;) {
    const BvhWideNode node = layout_[n];
    std::memcpy(layout + size_t(place[n]) * BvhLayout::kPlaceBytes, &node, sizeof node);
  }

  // Write each node's runs after it and turn its child words into places, in chunks of nodes
  // on all the build's threads.
  constexpr int kChunks = 64;
  parallel_for(kChunks, resolve_thread_count(threads), [&](int chunk, int) {
    for (auto [n, end] = chunk_range(node_count_, chunk, kChunks); n < end; ++n) {
      std::byte* at_node = layout + size_t(place[n]) * BvhLayout::kPlaceBytes;
      BvhWideNode node;
      std::memcpy(&node, at_node, sizeof node);
      size_t at = size_t(place[n]) * BvhLayout::kPlaceBytes + sizeof(BvhWideNode);
      for (size_t c = 0; c < size_t(kBvhWidth); ++c) {
        if (node.is_leaf(c)) {
          write_leaf_run(at, node.first(c), node.count(c), tree.order);
          node.child[c] = BvhWideNode::leaf_word(uint32_t(at / BvhLayout::kPlaceBytes), node.count(c));
          at += node.count(c) * LeafRun::kBytesPerPrimitive;
        } else {
          // A tree from elsewhere must name only its own nodes.
          MJRAY_CHECK(node.child[c] < node_count_);
          node.child[c] = place[node.child[c]];
        }
      }
      std::memcpy(at_node, &node, sizeof node);
      // Clear what the move left between the runs and the next node (or the end).
      const size_t next = n + 1 < node_count_ ? size_t(place[n + 1]) * BvhLayout::kPlaceBytes : layout_.size() * sizeof(BvhWideNode);
      std::memset(layout + at, 0, next - at);
    }
  });
}

const BvhWideNode& Bvh::node_at(uint32_t place) const { return node_in(layout_bytes(), place); }

template <class F>
void Bvh::for_each_node(F&& f) const {
  size_t at = 0;
  for (size_t n = 0; n < node_count_; ++n) {
    const BvhWideNode& node = node_at(uint32_t(at / BvhLayout::kPlaceBytes));
    f(node);
    at = round_up(at + bytes_with_runs(node), BvhLayout::kNodeAlignment);
  }
}

void Bvh::write_leaf_run(size_t at, uint32_t first, uint32_t count, std::span<const uint32_t> order) {
  // A tree from elsewhere must name only its own order's entries and the set's primitives.
  MJRAY_CHECK(size_t(first) + count <= order.size());
  std::array<float, LeafRun::kLeafFloats << BvhWideNode::kCountBits> run{};
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t prim = order[first + i];
    MJRAY_CHECK(prim < prims_.size());
    run[LeafRun::kIdRow * count + i] = std::bit_cast<float>(prim);
    if (!prims_.is_triangle(prim)) continue;  // a shape keeps zero corners
    const auto v = prims_.triangle_vertices(prim);
    for (uint32_t k = 0; k < 3; ++k)
      for (uint32_t axis = 0; axis < 3; ++axis) run[(3 * k + axis) * count + i] = v[k][int(axis)];
  }
  std::memcpy(layout_bytes() + at, run.data(), count * LeafRun::kBytesPerPrimitive);
}

double Bvh::sah_cost(double node_cost, double primitive_cost) const {
  if (node_count_ == 0) return 0;
  const auto area = [](float dx, float dy, float dz) { return double(dx) * dy + double(dy) * dz + double(dz) * dx; };
  const Vector3 d = bounds_.diagonal();
  const double root = area(d.x, d.y, d.z);
  if (!(root > 0)) return node_cost;
  double cost = node_cost;
  for_each_node([&](const BvhWideNode& node) {
    for (size_t i = 0; i < size_t(kBvhWidth); ++i) {
      const auto& b = node.bounds;
      if (b[0][i] > b[3][i]) continue;  // an unused slot
      const double share = area(b[3][i] - b[0][i], b[4][i] - b[1][i], b[5][i] - b[2][i]) / root;
      cost += share * (node.is_leaf(i) ? primitive_cost * node.count(i) : node_cost);
    }
  });
  return cost;
}

size_t Bvh::memory_bytes() const { return layout_size_; }

template <BvhQuery kQuery>
bool Bvh::trace(const Ray& ray, Interval t_range, Hit* hit, HitFilter* filter) const {
  if (node_count_ == 0 || !is_valid_ray(ray, t_range)) return false;
  const TraversalView view{layout_bytes(), &prims_, triangle_count_, prims_.shapes.empty(),
                           layout_size_ >= kPrefetchFrom};
  constexpr bool kFiltered = kQuery == BvhQuery::kFiltered;
#if MJRAY_BVH_HAS_AVX
  if (use_avx_) {
    if constexpr (kQuery != BvhQuery::kClosest) return avx::traverse_any<kFiltered>(view, ray, t_range, filter);
    else return avx::traverse_closest(view, ray, t_range, hit);
  }
#endif
  if constexpr (kQuery != BvhQuery::kClosest) return baseline::traverse_any<kFiltered>(view, ray, t_range, filter);
  else return baseline::traverse_closest(view, ray, t_range, hit);
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
  if (node_count_ == 0) return 0;
  // Past this many nodes the search is not worth its cost: the rays are traced instead.
  constexpr int kNodeBudget = 48;
  uint32_t stack[kStackSize];
  int top = 0, visited = 0;
  size_t found = 0;
  stack[top++] = 0;
  while (top > 0) {
    if (++visited > kNodeBudget) return std::nullopt;
    const BvhWideNode& node = node_at(stack[--top]);
    // Unused slots have empty boxes, which are outside.
    for (unsigned touching = ~region.outside(node.bounds) & 0xffu; touching != 0; touching &= touching - 1) {
      const size_t i = size_t(std::countr_zero(touching));
      if (!node.is_leaf(i)) {
        stack[top++] = node.child[i];
        continue;
      }
      // A leaf: each primitive not surely outside is a candidate.
      const LeafRun run = LeafRun::of(layout_bytes(), node.child[i]);
      for (uint32_t k = 0; k < run.count; ++k) {
        const uint32_t prim = run.prim(k);
        if (prim == ignore) continue;
        const bool outside = prim < triangle_count_
                                 ? region.outside(std::bit_cast<Point3>(run.corner(0, k)), std::bit_cast<Point3>(run.corner(1, k)),
                                                  std::bit_cast<Point3>(run.corner(2, k)))
                                 : region.outside(prims_.primitive_bounds(prim));
        if (outside) continue;
        if (found == out.size()) return std::nullopt;
        out[found++] = prim;
      }
    }
  }
  return found;
}

bool Bvh::occluded(const Ray& ray, Interval t_range, HitFilter& filter) const {
  return trace<BvhQuery::kFiltered>(ray, t_range, nullptr, &filter);
}

}  // namespace mjray
