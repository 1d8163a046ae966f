#pragma once
/// The default accelerator: a bounding volume hierarchy built with the binned surface area
/// heuristic, collapsed to eight children per node so that a few SIMD slab tests cover all
/// of a node's boxes and a ray visits few nodes.

#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "mjray/accel/accelerator.h"
#include "mjray/core/large_pages.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// Children per node of the traversed hierarchy.
constexpr int kBvhWidth = 8;

/// A node with up to kBvhWidth children, bounds stored axis by axis (structure of arrays) so
/// that SIMD slab tests cover several children at once. A child is an inner node or a leaf:
/// a LeafRun. Unused slots have empty bounds, which every ray misses. 224 bytes:
/// a leaf's run is packed into its child word, so a node is its boxes and eight words.
struct alignas(32) BvhWideNode {
  /// Leaf words have the top bit set (so one SIMD movemask finds a node's leaves), then the
  /// run's first primitive (in leaf order), then the count in the low bits.
  static constexpr uint32_t kLeafFlag = 0x80000000u;
  static constexpr int kCountBits = 3;
  /// The most primitives a BVH can index.
  static constexpr uint32_t kMaxLeafPrimitives = kLeafFlag >> kCountBits;

  /// bounds[k][i]: k = 0..2 lower x, y, z; k = 3..5 upper x, y, z of child i (world space).
  std::array<std::array<float, kBvhWidth>, 6> bounds;
  /// Child i: an inner node's index, or a leaf (leaf_word); 0 in unused slots.
  std::array<uint32_t, kBvhWidth> child;

  /// A node with no children yet: every slot's box is empty, which every ray misses.
  static BvhWideNode without_children() {
    BvhWideNode node{};
    for (size_t k = 0; k < 3; ++k) {
      node.bounds[k].fill(kInfinity);
      node.bounds[k + 3].fill(-kInfinity);
    }
    return node;
  }
  /// Sets slot i's box.
  void set_bounds(size_t i, const Bounds3& box) {
    for (size_t k = 0; k < 3; ++k) {
      bounds[k][i] = box.lo[int(k)];
      bounds[k + 3][i] = box.hi[int(k)];
    }
  }

  /// The word of a leaf of `count` (1..7) primitives from `first`.
  static constexpr uint32_t leaf_word(uint32_t first, uint32_t count) { return kLeafFlag | first << kCountBits | count; }
  bool is_leaf(size_t i) const { return (child[i] & kLeafFlag) != 0; }
  /// A leaf's first primitive and count, from its word or its slot.
  static constexpr uint32_t first_of(uint32_t word) { return (word & ~kLeafFlag) >> kCountBits; }
  static constexpr uint32_t count_of(uint32_t word) { return word & ((1u << kCountBits) - 1); }
  uint32_t first(size_t i) const { return first_of(child[i]); }
  uint32_t count(size_t i) const { return count_of(child[i]); }
};
static_assert(sizeof(BvhWideNode) == 224);

/// Wide nodes as the BVH keeps them: on large pages, which rays read at random.
using BvhWideNodes = std::vector<BvhWideNode, LargePageAllocator<BvhWideNode>>;

/// A leaf's run of primitives as the BVH stores it: kLeafFloats floats per primitive, in rows
/// of `count` (p0.x of each primitive, then p0.y, … p2.z, then the primitive ids), so that one
/// unaligned SIMD load gives a coordinate of up to four triangles with no transposing. Shapes
/// store zero corners. Runs lie end to end in leaf order; the array has kLeafPadding floats
/// more so that a row's load may read past the last run.
struct LeafRun {
  static constexpr uint32_t kLeafFloats = 10;  ///< nine corner coordinates and the id
  static constexpr uint32_t kIdRow = 9;
  static constexpr size_t kLeafPadding = 3;

  const float* data;  ///< the run's first float
  uint32_t count;     ///< primitives in the run

  /// The run a leaf's child word (BvhWideNode::leaf_word) names in the BVH's leaf data.
  static LeafRun of(const float* leaf_data, uint32_t word) {
    return {leaf_data + size_t(BvhWideNode::first_of(word)) * kLeafFloats, BvhWideNode::count_of(word)};
  }

  /// Row `row` (coordinate 3·corner + axis, or kIdRow): `count` floats.
  const float* row(uint32_t row) const { return data + row * count; }
  uint32_t prim(uint32_t i) const { return std::bit_cast<uint32_t>(row(kIdRow)[i]); }
  /// Corner k (0..2) of primitive i.
  std::array<float, 3> corner(uint32_t k, uint32_t i) const {
    return {row(3 * k)[i], row(3 * k + 1)[i], row(3 * k + 2)[i]};
  }
};

/// What a traversal looks for.
enum class BvhQuery {
  kClosest,   ///< the nearest hit
  kAny,       ///< any hit
  kFiltered,  ///< a hit on an opaque primitive, or one a HitFilter says blocks
};

/// Which SIMD instructions traversal may use.
enum class BvhSimd {
  kBest,      ///< 8-wide AVX slab tests where the CPU has AVX, else the baseline
  kBaseline,  ///< what the build targets (4-wide SSE2 on x86-64); for tests and comparisons
};

/// A wide tree over a PrimitiveSet, before its leaves' triangles are copied: the nodes (root
/// first; leaf words index `order`), the primitive ids in leaf order (an id may appear in more
/// than one leaf, as after spatial splits), and the bounds of the root.
struct BvhTree {
  BvhWideNodes nodes;
  std::vector<uint32_t> order;
  Bounds3 bounds;
};

/// Binned-SAH BVH over all of a PrimitiveSet's primitives (triangles and shapes). Primitives
/// whose bounds are not finite are left out: the intersection tests never hit them.
class Bvh final : public Accelerator {
 public:
  /// Builds over `prims` (which must outlive the Bvh) with `threads` threads (0 = all cores).
  Bvh(const PrimitiveSet& prims, int threads, BvhSimd simd = BvhSimd::kBest);
  /// Traverses a tree built elsewhere (by another builder, to compare trees under the same
  /// traversal); every leaf must hold 1..7 of `prims`' primitives, every primitive whose bounds
  /// are finite must be in some leaf, and the depth must stay under 64.
  Bvh(const PrimitiveSet& prims, BvhTree tree, int threads, BvhSimd simd = BvhSimd::kBest);

  std::optional<Hit> intersect(const Ray& ray, Interval t_range) const override;
  bool occluded(const Ray& ray, float t_max) const override;
  bool occluded(const Ray& ray, Interval t_range, HitFilter& filter) const override;
  std::optional<size_t> region_primitives(const LightPyramid& region, uint32_t ignore,
                                          std::span<uint32_t> out) const override;
  Bounds3 bounds() const override { return bounds_; }
  std::string_view name() const override { return "bvh"; }
  size_t memory_bytes() const override;

  /// The nodes, root first (none for an empty world); exposed for tests and statistics.
  std::span<const BvhWideNode> nodes() const { return nodes_; }
  /// The leaves' runs end to end (LeafRun), without the padding; exposed for tests.
  std::span<const float> leaf_data() const { return {leaf_data_.data(), leaf_data_.size() - LeafRun::kLeafPadding}; }
  /// The number of primitives in the leaves.
  size_t leaf_primitive_count() const { return (leaf_data_.size() - LeafRun::kLeafPadding) / LeafRun::kLeafFloats; }
  /// The surface area heuristic's estimate of a ray's cost through the tree: `node_cost` per
  /// node box entered and `primitive_cost` per primitive of a leaf box entered, each weighted
  /// by the box's area over the root's (the root's own visit counts one node_cost).
  double sah_cost(double node_cost, double primitive_cost) const;
  /// Whether traversal runs the 8-wide AVX slab test (chosen at construction).
  bool uses_avx() const { return use_avx_; }

 private:
  /// Writes the LeafRun of order[first, first + count).
  void write_leaf_run(uint32_t first, uint32_t count, std::span<const uint32_t> order);
  template <BvhQuery kQuery>
  bool trace(const Ray& ray, Interval t_range, Hit* hit, HitFilter* filter) const;

  const PrimitiveSet& prims_;
  uint32_t triangle_count_ = 0;
  bool use_avx_ = false;
  BvhWideNodes nodes_;
  std::vector<float, LargePageAllocator<float>> leaf_data_;  // LeafRuns, then kLeafPadding floats
  Bounds3 bounds_;
};

}  // namespace mjray
