#include "mjray/accel/embree_bvh_builder.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "mjray/core/error.h"

namespace mjray {

namespace {

constexpr unsigned kMaxLeaf = (1u << BvhWideNode::kCountBits) - 1;  // what a leaf word's count holds

/// Embree's builder hands back whatever the callbacks make: this, for inner nodes and leaves
/// alike, in memory Embree owns until the RTCBVH is released.
struct BuiltNode {
  bool leaf;
  unsigned count;  // children, or primitives of a leaf
  std::array<const BuiltNode*, kBvhWidth> children;
  std::array<RTCBounds, kBvhWidth> bounds;
  std::array<uint32_t, kMaxLeaf> prims;
};

BuiltNode* allocate(RTCThreadLocalAllocator allocator) {
  return static_cast<BuiltNode*>(rtcThreadLocalAlloc(allocator, sizeof(BuiltNode), alignof(BuiltNode)));
}

void* create_node(RTCThreadLocalAllocator allocator, unsigned count, void*) {
  BuiltNode* node = allocate(allocator);
  node->leaf = false;
  node->count = count;
  return node;
}

void set_children(void* node, void** children, unsigned count, void*) {
  for (unsigned i = 0; i < count; ++i) static_cast<BuiltNode*>(node)->children[i] = static_cast<const BuiltNode*>(children[i]);
}

void set_bounds(void* node, const RTCBounds** bounds, unsigned count, void*) {
  for (unsigned i = 0; i < count; ++i) static_cast<BuiltNode*>(node)->bounds[i] = *bounds[i];
}

void* create_leaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* prims, size_t count, void*) {
  BuiltNode* leaf = allocate(allocator);
  leaf->leaf = true;
  leaf->count = unsigned(count);
  for (size_t i = 0; i < count; ++i) leaf->prims[i] = prims[i].primID;
  return leaf;
}

Bounds3 bounds_of(const RTCBounds& b) { return {{b.lower_x, b.lower_y, b.lower_z}, {b.upper_x, b.upper_y, b.upper_z}}; }
RTCBounds rtc_bounds(const Bounds3& b) { return {b.lo.x, b.lo.y, b.lo.z, 0, b.hi.x, b.hi.y, b.hi.z, 0}; }

/// Splits a reference at the plane `axis` = `position`: a triangle's two parts are bounded by
/// its corners and edge crossings on each side; a shape's by its box on each side. Either
/// part also stays inside the reference's box.
void split_reference(const RTCBuildPrimitive* ref, unsigned axis, float position, RTCBounds* left_out,
                     RTCBounds* right_out, void* user) {
  const auto& prims = *static_cast<const PrimitiveSet*>(user);
  const int a = int(axis);
  const Bounds3 box{{ref->lower_x, ref->lower_y, ref->lower_z}, {ref->upper_x, ref->upper_y, ref->upper_z}};
  Bounds3 left, right;
  if (prims.is_triangle(ref->primID)) {
    const auto v = prims.triangle_vertices(ref->primID);
    for (size_t k = 0; k < 3; ++k) {
      const Point3& p = v[k];
      const Point3& q = v[(k + 1) % 3];
      if (p[a] <= position) left.expand(p);
      if (p[a] >= position) right.expand(p);
      if ((p[a] < position && q[a] > position) || (p[a] > position && q[a] < position)) {
        const float s = (position - p[a]) / (q[a] - p[a]);
        Point3 crossing = p + (q - p) * s;
        crossing[a] = position;
        left.expand(crossing);
        right.expand(crossing);
      }
    }
  } else {
    left = right = box;
  }
  left.lo = max(left.lo, box.lo);
  left.hi = min(left.hi, box.hi);
  right.lo = max(right.lo, box.lo);
  right.hi = min(right.hi, box.hi);
  left.hi[a] = std::min(left.hi[a], position);
  right.lo[a] = std::max(right.lo[a], position);
  *left_out = rtc_bounds(left);
  *right_out = rtc_bounds(right);
}

/// Appends the wide node of an inner BuiltNode and its subtree, depth first; returns its index.
uint32_t append_wide(const BuiltNode& built, BvhTree& tree) {
  const auto index = uint32_t(tree.nodes.size());
  BvhWideNode node = BvhWideNode::without_children();
  for (size_t i = 0; i < built.count; ++i) {
    node.set_bounds(i, bounds_of(built.bounds[i]));
    const BuiltNode& child = *built.children[i];
    if (!child.leaf) continue;
    node.child[i] = BvhWideNode::leaf_word(uint32_t(tree.order.size()), child.count);
    tree.order.insert(tree.order.end(), child.prims.begin(), child.prims.begin() + child.count);
  }
  tree.nodes.push_back(node);
  for (size_t i = 0; i < built.count; ++i)
    if (!built.children[i]->leaf) {
      const uint32_t child = append_wide(*built.children[i], tree);
      tree.nodes[index].child[i] = child;
    }
  return index;
}

}  // namespace

BvhTree embree_built_tree(const PrimitiveSet& prims, const EmbreeTreeOptions& options) {
  if (options.max_leaf_size < 1 || options.max_leaf_size > int(kMaxLeaf))
    throw SceneError("embree tree: leaves hold 1 to " + std::to_string(kMaxLeaf) + " primitives");
  BvhTree tree;
  std::vector<RTCBuildPrimitive> refs;
  for (uint32_t prim = 0; prim < prims.size(); ++prim) {
    const Bounds3 b = prims.primitive_bounds(prim);
    if (b.empty() || !is_finite(b.lo) || !is_finite(b.hi)) continue;
    refs.push_back({b.lo.x, b.lo.y, b.lo.z, 0, b.hi.x, b.hi.y, b.hi.z, prim});
    tree.bounds.expand(b);
  }
  if (refs.empty()) return tree;
  const size_t count = refs.size();
  // Spatial splits add references: Embree uses the spare capacity for them.
  refs.resize(options.spatial_splits ? 2 * count : count);

  const std::string config = options.threads > 0 ? "threads=" + std::to_string(options.threads) : "";
  RTCDevice device = rtcNewDevice(config.c_str());
  if (!device) throw SceneError("embree tree: cannot create a device");
  RTCBuildArguments args = rtcDefaultBuildArguments();
  args.buildQuality = options.spatial_splits ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
  args.maxBranchingFactor = kBvhWidth;
  args.maxDepth = 48;  // mjray's traversal stack holds 64 levels
  args.minLeafSize = 1;
  args.maxLeafSize = unsigned(options.max_leaf_size);
  args.traversalCost = options.traversal_cost;
  args.intersectionCost = 1;
  args.bvh = rtcNewBVH(device);
  args.primitives = refs.data();
  args.primitiveCount = count;
  args.primitiveArrayCapacity = refs.size();
  args.createNode = create_node;
  args.setNodeChildren = set_children;
  args.setNodeBounds = set_bounds;
  args.createLeaf = create_leaf;
  args.splitPrimitive = options.spatial_splits ? split_reference : nullptr;
  args.userPtr = const_cast<PrimitiveSet*>(&prims);
  const auto* root = static_cast<const BuiltNode*>(rtcBuildBVH(&args));
  if (root && root->leaf) {
    // One leaf: the only child of a wide root.
    BuiltNode only{false, 1, {}, {}, {}};
    only.children[0] = root;
    only.bounds[0] = rtc_bounds(tree.bounds);
    append_wide(only, tree);
  } else if (root) {
    append_wide(*root, tree);
  }
  const RTCError error = rtcGetDeviceError(device);
  rtcReleaseBVH(args.bvh);
  rtcReleaseDevice(device);
  if (!root || error != RTC_ERROR_NONE) throw SceneError("embree tree: the build failed");
  return tree;
}

}  // namespace mjray
