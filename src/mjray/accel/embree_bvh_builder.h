#pragma once
/// Embree's BVH builder (rtcBuildBVH) making a tree for mjray's own BVH traversal, so that the
/// two builders' trees can be compared under one traversal (mjray-bench --tree). Not used for
/// rendering.

#include "mjray/accel/bvh.h"
#include "mjray/accel/bvh_builder.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// How Embree builds the tree; the defaults are mjray's own builder's cost model and leaves.
struct EmbreeTreeOptions {
  bool spatial_splits = false;  ///< Embree's high-quality build, which splits triangles' references
  int max_leaf_size = BvhBuildOptions{}.max_leaf_size;         ///< 1..7 primitives a leaf
  float traversal_cost = BvhBuildOptions{}.traversal_cost;     ///< SAH cost of a node relative to one primitive test
  int threads = 0;              ///< 0 = all cores
};

/// An 8-wide tree over every primitive of `prims` whose bounds are finite, built by Embree.
/// Throws SceneError when Embree cannot create a device or build.
BvhTree embree_built_tree(const PrimitiveSet& prims, const EmbreeTreeOptions& options);

}  // namespace mjray
