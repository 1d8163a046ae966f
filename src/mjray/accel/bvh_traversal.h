#pragma once
/// What the BVH's traversal (bvh_traversal_impl.h, compiled once per instruction set) reads
/// from bvh.cpp: the stack's bound, the slab test's rounding margin, how far ahead memory is
/// loaded, and the view of a tree. Internal to bvh.cpp.

#include <cstddef>
#include <cstdint>
#include <limits>

#include "mjray/accel/bvh.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray::bvh_traversal {

/// The builder's binary depth stays under 64 and gathering wide nodes never deepens it; each
/// wide node leaves at most kBvhWidth − 1 entries on the stack (the any-hit traversal pushes
/// all kBvhWidth and pops one at once, so it peaks one above).
inline constexpr int kStackSize = (kBvhWidth - 1) * 64 + 1;

/// Widens the far slab distance by 2γ₃ (pbrt-v4) so rounding never culls a box the ray
/// actually touches.
inline constexpr float kGamma3 = 3 * std::numeric_limits<float>::epsilon() * 0.5f /
                                 (1 - 3 * std::numeric_limits<float>::epsilon() * 0.5f);
inline constexpr float kFarScale = 1 + 2 * kGamma3;

/// A pushed child's node or run, and what follows it, is loaded ahead in large trees: 768
/// bytes (the node and some 540 bytes of its runs, or a run and its siblings), measured best
/// among 256 to 768 on large meshes.
inline constexpr size_t kPrefetchBytes = 12 * 64;

/// A pending child: its word in the parent node (an inner node or a leaf, see BvhWideNode), and
/// where the ray enters its box.
struct StackEntry {
  uint32_t child;
  float t_enter;
};

/// The node at `place` of a layout. Its bytes hold a node written there by memcpy.
inline const BvhWideNode& node_in(const std::byte* layout, uint32_t place) {
  return *reinterpret_cast<const BvhWideNode*>(layout + size_t(place) * BvhLayout::kPlaceBytes);
}

/// What traversal reads of a Bvh.
struct TraversalView {
  const std::byte* layout;  // BvhLayout
  const PrimitiveSet* prims;
  uint32_t triangle_count;
  bool only_triangles;  // no shapes: a leaf's entries need no check of their kind
  bool prefetches;      // the tree is large enough that its memory is worth loading ahead

  const BvhWideNode& node(uint32_t place) const { return node_in(layout, place); }
  LeafRun leaf(uint32_t word) const { return LeafRun::of(layout, word); }
};

}  // namespace mjray::bvh_traversal
