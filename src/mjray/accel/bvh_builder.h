#pragma once
/// Construction of the BVH: a binary tree by binned SAH, then collapsed to wide nodes; kept
/// apart from traversal so that either can change without touching the other.

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "mjray/accel/bvh.h"
#include "mjray/core/bounds.h"

namespace mjray {

/// One node of the binary hierarchy, flattened depth-first in 32 bytes: an interior node's
/// first child follows it directly.
struct BvhNode {
  std::array<float, 3> lo;  ///< world-space bounds
  std::array<float, 3> hi;
  uint32_t offset;          ///< leaf: first index into `order`; interior: index of the second child
  uint16_t count;           ///< leaf: number of primitives (≥ 1); interior: 0
  uint8_t axis;             ///< interior: split axis
  uint8_t pad = 0;
};
static_assert(sizeof(BvhNode) == 32);

/// Binary nodes, on large pages: a million-triangle build fills tens of megabytes at once.
using BvhNodes = std::vector<BvhNode, LargePageAllocator<BvhNode>>;

/// The built hierarchy: nodes depth-first (root first), and the primitive ids in leaf
/// order; a leaf's `offset`/`count` index `order`.
struct BvhBuildResult {
  BvhNodes nodes;
  std::vector<uint32_t> order;
};

/// Tuning of the build; the defaults are what the renderer uses.
struct BvhBuildOptions {
  int threads = 0;              ///< 0 = all cores
  int max_leaf_size = 4;        ///< leaves hold 1..max_leaf_size primitives
  /// SAH cost of visiting a node relative to one primitive test; 2 rather than 1 makes
  /// leaves a little larger, which keeps 8-wide nodes fuller (memory) at ~4% speed.
  float traversal_cost = 2.0f;
  /// Primitive ids from here on are analytic shapes (a ray mapped into their frame and a
  /// quadratic or slab test in double), which cost `shape_cost` triangle tests: leaves of
  /// shapes are kept smaller, so that the wide nodes' boxes reject more rays before them.
  uint32_t shapes_from = UINT32_MAX;
  float shape_cost = 4.0f;
};

/// Builds over primitives 0..bounds.size()-1 with world-space `bounds[prim]`. Primitives with
/// empty or non-finite bounds are left out.
BvhBuildResult build_bvh(std::span<const Bounds3> bounds, const BvhBuildOptions& options);
/// The same over primitives 0..count-1 whose bounds `bounds_of(prim)` gives, asked once each
/// (so that no array of all bounds need be held beside the build's own copy).
BvhBuildResult build_bvh(uint32_t count, const std::function<Bounds3(uint32_t)>& bounds_of,
                         const BvhBuildOptions& options);

/// Collapses a binary hierarchy into kBvhWidth-wide nodes (root first) by repeatedly opening
/// the inner child with the largest surface area; leaves keep their `order` ranges. The array
/// has room for at least `capacity` nodes.
BvhWideNodes collapse_to_wide(const BvhNodes& binary, size_t capacity = 0);

}  // namespace mjray
