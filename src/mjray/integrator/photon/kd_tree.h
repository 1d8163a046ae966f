#pragma once
/// A static kd-tree over surface points, for k-nearest-neighbour queries (photon density
/// estimates, nearest precomputed irradiance).

#include <algorithm>
#include <cstdint>
#include <span>
#include <thread>
#include <vector>

#include "mjray/core/bounds.h"
#include "mjray/integrator/photon/photon.h"

namespace mjray {

/// One item found near a query point: its index in KdTree::items() and squared distance.
struct Neighbour {
  float distance2 = 0;
  uint32_t index = 0;
  bool operator<(const Neighbour& o) const { return distance2 < o.distance2 || (distance2 == o.distance2 && index < o.index); }
};

/// The items found by KdTree::nearest, and the squared radius of the disc they lie in: the
/// farthest one's distance when `count` reached k, else the search radius.
struct Neighbourhood {
  std::span<const Neighbour> found;
  float radius2 = 0;
};

/// An implicit balanced kd-tree: the items of a range [lo, hi) are split at their median
/// m = (lo + hi) / 2 along the axis of the range's widest extent, the left half before m and
/// the right half after it; ranges of kLeafSize items or fewer stay unsplit. The tree depends
/// only on the items and their order, never on the number of threads that built it.
/// `Item` has a `Point3 position` and a `PackedNormal normal`.
template <class Item>
class KdTree {
 public:
  static constexpr size_t kLeafSize = 8;

  KdTree() = default;
  /// Reorders `items` into a tree, splitting the work over `threads` threads.
  KdTree(std::vector<Item> items, int threads) : items_(std::move(items)), nodes_(items_.size()) {
    for (const Item& item : items_) bounds_.expand(item.position);
    build(0, items_.size(), std::max(1, threads));
    for (size_t i = 0; i < items_.size(); ++i) nodes_[i].position = items_[i].position, nodes_[i].normal = items_[i].normal;
  }

  std::span<const Item> items() const { return items_; }
  size_t size() const { return items_.size(); }
  bool empty() const { return items_.empty(); }
  /// The bounds of every item's position.
  const Bounds3& bounds() const { return bounds_; }
  /// Bytes held by the tree.
  size_t memory_bytes() const { return items_.capacity() * sizeof(Item) + nodes_.capacity() * sizeof(Node); }

  /// The (at most) out.size() items nearest `p`, closer than √max_distance2, whose normal
  /// `accept(normal)` takes, in no particular order. No allocation: `out` is the caller's.
  template <class Accept>
  Neighbourhood nearest(const Point3& p, float max_distance2, Accept&& accept, std::span<Neighbour> out) const {
    Search<Accept> search{p, out, accept, max_distance2};
    if (out.empty()) return {{}, max_distance2};
    visit(0, items_.size(), search);
    return {out.first(search.count), search.count == out.size() ? out[0].distance2 : max_distance2};
  }

 private:
  /// What a search reads of an item, packed: 16 bytes, four to a cache line.
  struct Node {
    Point3 position;
    PackedNormal normal;
    uint8_t axis = 0;  ///< the split axis, at a range's median
  };

  /// The state of one query: a max-heap of the best items so far in `out[0, count)`.
  template <class Accept>
  struct Search {
    Point3 p;
    std::span<Neighbour> out;
    Accept& accept;
    float radius2;
    size_t count = 0;

    void consider(const Node& node, uint32_t index) {
      const Vector3 d = node.position - p;
      const float distance2 = dot(d, d);
      if (distance2 >= radius2 || !accept(node.normal)) return;
      if (count < out.size()) {
        out[count++] = {distance2, index};
        std::push_heap(out.begin(), out.begin() + ptrdiff_t(count));
        if (count == out.size()) radius2 = out[0].distance2;
        return;
      }
      std::pop_heap(out.begin(), out.end());
      out.back() = {distance2, index};
      std::push_heap(out.begin(), out.end());
      radius2 = out[0].distance2;
    }
  };

  template <class S>
  void visit(size_t lo, size_t hi, S& search) const {
    if (hi - lo <= kLeafSize) {
      for (size_t i = lo; i < hi; ++i) search.consider(nodes_[i], uint32_t(i));
      return;
    }
    const size_t m = lo + (hi - lo) / 2;
    const Node& node = nodes_[m];
    const float delta = search.p[node.axis] - node.position[node.axis];
    // The side the query point is on first; the other only if the disc reaches across.
    if (delta < 0) visit(lo, m, search);
    else visit(m + 1, hi, search);
    search.consider(node, uint32_t(m));
    if (delta * delta < search.radius2) {
      if (delta < 0) visit(m + 1, hi, search);
      else visit(lo, m, search);
    }
  }

  void build(size_t lo, size_t hi, int threads) {
    if (hi - lo <= kLeafSize) return;
    Bounds3 range;
    for (size_t i = lo; i < hi; ++i) range.expand(items_[i].position);
    const Vector3 extent = range.diagonal();
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const size_t m = lo + (hi - lo) / 2;
    std::nth_element(items_.begin() + ptrdiff_t(lo), items_.begin() + ptrdiff_t(m), items_.begin() + ptrdiff_t(hi),
                     [axis](const Item& a, const Item& b) { return a.position[axis] < b.position[axis]; });
    nodes_[m].axis = uint8_t(axis);
    if (threads > 1) {
      std::thread left([&, lo, m] { build(lo, m, threads / 2); });
      build(m + 1, hi, threads - threads / 2);
      left.join();
    } else {
      build(lo, m, 1);
      build(m + 1, hi, 1);
    }
  }

  std::vector<Item> items_;
  std::vector<Node> nodes_;  ///< parallel to items_
  Bounds3 bounds_;
};

}  // namespace mjray
