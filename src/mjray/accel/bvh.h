#pragma once
/// The default accelerator: a bounding volume hierarchy built with the binned surface area
/// heuristic, gathered into eight children per node so that a few SIMD slab tests cover all
/// of a node's boxes and a ray visits few nodes.

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mjray/accel/accelerator.h"
#include "mjray/accel/region_search.h"
#include "mjray/core/large_pages.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// Children per node of the traversed hierarchy.
constexpr int kBvhWidth = 8;

/// A node with up to kBvhWidth children, bounds stored axis by axis (structure of arrays) so
/// that SIMD slab tests cover several children at once. A child is an inner node or a leaf:
/// a LeafRun. Unused slots have empty bounds, which every ray misses. 224 bytes:
/// a leaf's run is packed into its child word, so a node is its boxes and eight words.
/// In a BvhTree a child word names an index into its nodes, or a leaf's range of its order;
/// in a Bvh's layout it names a place (BvhLayout), a node's or a run's.
struct alignas(32) BvhWideNode {
  /// Leaf words have the top bit set (so one SIMD movemask finds a node's leaves), then the
  /// run's first primitive (in a BvhTree's order) or its place (in a layout), then the count
  /// in the low bits.
  static constexpr uint32_t kLeafFlag = 0x80000000u;
  static constexpr int kCountBits = 3;
  /// The most primitives a BvhTree can index, and the most places a leaf word can name.
  static constexpr uint32_t kMaxLeafPrimitives = kLeafFlag >> kCountBits;

  /// bounds[k][i]: k = 0..2 lower x, y, z; k = 3..5 upper x, y, z of child i (world space).
  std::array<std::array<float, kBvhWidth>, 6> bounds;
  /// Child i: an inner node (its index or place), or a leaf (leaf_word); 0 in unused slots.
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

/// Where a Bvh keeps its tree: each wide node (aligned to 32 bytes) followed by the LeafRuns
/// of its leaf children, node after node in the tree's depth-first order, the root first. A ray
/// that enters a node mostly tests its leaves next, and finds them on the same page and in
/// the lines after the node, which the processor's prefetchers bring in with it. Child words
/// in the layout name places: offsets in units of kPlaceBytes.
struct BvhLayout {
  static constexpr size_t kPlaceBytes = 8;  ///< a LeafRun is a multiple of 8 bytes long
  static constexpr size_t kNodeAlignment = 32;
  /// Bytes after the last run, so that a row's load may read past its end.
  static constexpr size_t kPadding = 16;
  /// The most bytes a layout can hold: its leaf words name places below kMaxLeafPrimitives.
  static constexpr size_t kMaxBytes = size_t(BvhWideNode::kMaxLeafPrimitives) * kPlaceBytes;

  /// The most bytes the layout of at most `nodes` wide nodes over `primitives` leaf entries takes.
  static constexpr size_t bytes_bound(size_t nodes, size_t primitives) {
    return nodes * (sizeof(BvhWideNode) + kNodeAlignment - kPlaceBytes) + primitives * 10 * sizeof(float) + kPadding;
  }
};
static_assert(alignof(BvhWideNode) == BvhLayout::kNodeAlignment && sizeof(BvhWideNode) % BvhLayout::kNodeAlignment == 0);

/// A leaf's run of primitives as the BVH stores it: kLeafFloats floats per primitive, in rows
/// of `count` (p0.x of each primitive, then p0.y, … p2.z, then the primitive ids), so that one
/// unaligned SIMD load gives a coordinate of up to four triangles with no transposing. Shapes
/// store zero corners. A row's load may read up to three floats past the run.
struct LeafRun {
  static constexpr uint32_t kLeafFloats = 10;  ///< nine corner coordinates and the id
  static constexpr uint32_t kIdRow = 9;
  static constexpr size_t kBytesPerPrimitive = kLeafFloats * sizeof(float);
  static_assert(kBytesPerPrimitive % BvhLayout::kPlaceBytes == 0);
  static_assert(BvhLayout::bytes_bound(0, 1) == kBytesPerPrimitive + BvhLayout::kPadding);

  const float* data;  ///< the run's first float
  uint32_t count;     ///< primitives in the run

  /// The run a leaf's child word (BvhWideNode::leaf_word) names in a BvhLayout.
  static LeafRun of(const std::byte* layout, uint32_t word) {
    // The layout's bytes hold floats written there by memcpy.
    return {reinterpret_cast<const float*>(layout + size_t(BvhWideNode::first_of(word)) * BvhLayout::kPlaceBytes),
            BvhWideNode::count_of(word)};
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
class Bvh final : public Accelerator, public RegionSearch {
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

  /// The number of wide nodes (none for an empty world).
  size_t node_count() const { return node_count_; }
  /// The nodes and runs as traversal reads them (BvhLayout); exposed for tests.
  std::span<const std::byte> layout() const { return {layout_bytes(), layout_size_}; }
  /// The number of primitives in the leaves.
  size_t leaf_primitive_count() const { return leaf_primitive_count_; }
  /// The surface area heuristic's estimate of a ray's cost through the tree: `node_cost` per
  /// node box entered and `primitive_cost` per primitive of a leaf box entered, each weighted
  /// by the box's area over the root's (the root's own visit counts one node_cost).
  double sah_cost(double node_cost, double primitive_cost) const;
  /// Whether traversal runs the 8-wide AVX slab test (chosen at construction).
  bool uses_avx() const { return use_avx_; }

 private:
  const std::byte* layout_bytes() const { return reinterpret_cast<const std::byte*>(layout_.data()); }
  /// The node at `place` in the layout.
  const BvhWideNode& node_at(uint32_t place) const;
  /// Calls f(node) for every node, in the layout's order.
  template <class F>
  void for_each_node(F&& f) const;
  /// Writes the LeafRun of order[first, first + count) at byte `at` of the layout.
  void write_leaf_run(size_t at, uint32_t first, uint32_t count, std::span<const uint32_t> order);
  std::byte* layout_bytes() { return reinterpret_cast<std::byte*>(layout_.data()); }
  template <BvhQuery kQuery>
  bool trace(const Ray& ray, Interval t_range, Hit* hit, HitFilter* filter) const;

  const PrimitiveSet& prims_;
  uint32_t triangle_count_ = 0;
  bool use_avx_ = false;
  /// The BvhLayout, stored in the tree's own node array (grown, and read as bytes), so that
  /// laying the tree out needs no second copy of its nodes.
  BvhWideNodes layout_;
  size_t layout_size_ = 0;
  size_t node_count_ = 0;
  size_t leaf_primitive_count_ = 0;
  Bounds3 bounds_;
};

}  // namespace mjray
