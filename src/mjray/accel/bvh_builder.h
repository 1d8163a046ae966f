#pragma once
/// Construction of the BVH's wide nodes by binned SAH; kept apart from traversal so that
/// either can change without touching the other.

#include <cstddef>
#include <cstdint>
#include <functional>

#include "mjray/accel/bvh.h"
#include "mjray/core/bounds.h"

namespace mjray {

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

/// The wide hierarchy over primitives 0..count-1 whose world-space bounds `bounds_of(prim)`
/// gives, asked once each (so that no array of all bounds need be held beside the build's own
/// copy): the nodes (root first, depth-first, with room after them for the Bvh's layout of
/// them in place), the primitive ids in leaf order (a leaf word's first and count index it),
/// and the bounds. A binary tree is chosen by binned SAH and gathered into kBvhWidth-wide nodes
/// as it is made. Primitives with empty or non-finite bounds are left out. Throws
/// std::length_error for more than BvhWideNode::kMaxLeafPrimitives primitives.
BvhTree build_bvh(size_t count, const std::function<Bounds3(uint32_t)>& bounds_of, const BvhBuildOptions& options);

}  // namespace mjray
