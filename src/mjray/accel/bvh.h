#pragma once
/// The default accelerator: a bounding volume hierarchy built with the binned surface area
/// heuristic, collapsed to eight children per node so that a few SIMD slab tests cover all
/// of a node's boxes and a ray visits few nodes.

#include <array>
#include <cstdint>
#include <vector>

#include "mjray/accel/accelerator.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// Children per node of the traversed hierarchy.
constexpr int kBvhWidth = 8;

/// A node with up to kBvhWidth children, bounds stored axis by axis (structure of arrays) so
/// that SIMD slab tests cover several children at once. A child is an inner node or a leaf:
/// a run of LeafPrimitives. Unused slots have empty bounds, which every ray misses.
struct alignas(64) BvhWideNode {
  /// bounds[k][i]: k = 0..2 lower x, y, z; k = 3..5 upper x, y, z of child i (world space).
  std::array<std::array<float, kBvhWidth>, 6> bounds;
  std::array<uint32_t, kBvhWidth> child;  ///< inner: child node index; leaf: first LeafPrimitive
  std::array<uint8_t, kBvhWidth> count;   ///< leaf: number of primitives (≥ 1); inner or unused: 0
};

/// A primitive as a leaf stores it: a triangle's world-space corners copied in leaf order
/// (so leaf tests read contiguous memory), or just the id of a shape.
struct LeafPrimitive {
  std::array<float, 3> p0, p1, p2;  ///< triangle corners; unused for shapes
  uint32_t prim;                    ///< primitive id in the PrimitiveSet
};
static_assert(sizeof(LeafPrimitive) == 40);

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

/// Binned-SAH BVH over all of a PrimitiveSet's primitives (triangles and shapes). Primitives
/// whose bounds are not finite are left out: the intersection tests never hit them.
class Bvh final : public Accelerator {
 public:
  /// Builds over `prims` (which must outlive the Bvh) with `threads` threads (0 = all cores).
  Bvh(const PrimitiveSet& prims, int threads, BvhSimd simd = BvhSimd::kBest);

  std::optional<Hit> intersect(const Ray& ray, Interval t_range) const override;
  bool occluded(const Ray& ray, float t_max) const override;
  bool occluded(const Ray& ray, Interval t_range, HitFilter& filter) const override;
  bool region_clear(const LightPyramid& region, uint32_t ignore) const override;
  Bounds3 bounds() const override { return bounds_; }
  std::string_view name() const override { return "bvh"; }
  size_t memory_bytes() const override;

  /// The nodes, root first (none for an empty world); exposed for tests and statistics.
  const std::vector<BvhWideNode>& nodes() const { return nodes_; }
  /// The primitives in leaf order.
  const std::vector<LeafPrimitive>& leaf_primitives() const { return leaf_prims_; }
  /// Whether traversal runs the 8-wide AVX slab test (chosen at construction).
  bool uses_avx() const { return use_avx_; }

 private:
  template <BvhQuery kQuery>
  bool trace(const Ray& ray, Interval t_range, Hit* hit, HitFilter* filter) const;

  const PrimitiveSet& prims_;
  uint32_t triangle_count_ = 0;
  bool use_avx_ = false;
  std::vector<BvhWideNode> nodes_;
  std::vector<LeafPrimitive> leaf_prims_;
  Bounds3 bounds_;
};

}  // namespace mjray
