#include "mjray/accel/bvh_builder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mjray/core/error.h"
#include "mjray/core/fork_join.h"
#include "mjray/core/parallel_for.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mjray {

namespace {

constexpr int kBins = 32;
// Below this many primitives a subtree is built by the thread that reached it; above, the
// division of its first child, and its wide subtree, are forked for any thread of the pool.
constexpr uint32_t kMinParallelSize = 8192;
// Above this many primitives a node's binning is shared among the pool's threads.
constexpr uint32_t kMinParallelBinning = 65536;
// Deeper than this, splits halve the primitives, so the depth (and the traversal stack)
// stays under kMaxSahDepth + 32.
constexpr int kMaxSahDepth = 30;

/// A box as four-float rows (the fourth lane unused, or the primitive id in a BuildRef), so
/// that growing one is two SIMD instructions.
struct alignas(16) Box4 {
  float lo[4] = {kInfinity, kInfinity, kInfinity, 0};
  float hi[4] = {-kInfinity, -kInfinity, -kInfinity, 0};

  void grow(const Box4& b) {
#if defined(__SSE2__)
    _mm_store_ps(lo, _mm_min_ps(_mm_load_ps(lo), _mm_load_ps(b.lo)));
    _mm_store_ps(hi, _mm_max_ps(_mm_load_ps(hi), _mm_load_ps(b.hi)));
#else
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
#endif
  }
  void grow_point(const float (&p)[4]) {
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  float extent(int a) const { return hi[a] - lo[a]; }
  /// Half the surface area (enough for comparing costs); 0 when empty.
  float half_area() const {
    const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
    return dx >= 0 ? dx * dy + dy * dz + dz * dx : 0;
  }
};

/// A primitive during the build: its bounds, the id in lo[3] (as bits), and the centroid kept
/// doubled (lo + hi).
struct BuildRef : Box4 {
  uint32_t prim() const { return std::bit_cast<uint32_t>(lo[3]); }
  float centroid(int axis) const { return lo[axis] + hi[axis]; }
#if defined(__SSE2__)
  /// The doubled centroid in lanes 0..2, 0 in lane 3. The id is cleared first: as a float it
  /// is mostly a denormal, whose arithmetic is slow.
  __m128 centroids() const {
    const __m128 xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));
    return _mm_add_ps(_mm_and_ps(_mm_load_ps(lo), xyz), _mm_load_ps(hi));
  }
#endif
};

using BuildRefs = std::vector<BuildRef, LargePageAllocator<BuildRef>>;

/// Grows `box` (whose fourth lanes are 0) by the centroid of `r`.
inline void grow_by_centroid(Box4& box, const BuildRef& r) {
#if defined(__SSE2__)
  const __m128 c = r.centroids();
  _mm_store_ps(box.lo, _mm_min_ps(_mm_load_ps(box.lo), c));
  _mm_store_ps(box.hi, _mm_max_ps(_mm_load_ps(box.hi), c));
#else
  const float c[4] = {r.centroid(0), r.centroid(1), r.centroid(2), 0};
  box.grow_point(c);
#endif
}

/// A subtree's box and the box of its primitives' (doubled) centroids.
struct Extent {
  Box4 box;
  Box4 centroids;
};

struct Bin {
  Box4 box;
  uint32_t count = 0;
  uint32_t shapes = 0;  // how many of count are analytic shapes
};
/// Bins per axis; only the first Binner::count of each row are used. Left uninitialised for
/// speed: find_split resets the ones it uses.
struct Bins {
  Bins() {}
  union {
    std::array<std::array<Bin, kBins>, 3> rows;
  };
  std::array<Bin, kBins>& operator[](size_t axis) { return rows[axis]; }
  const std::array<Bin, kBins>& operator[](size_t axis) const { return rows[axis]; }
  void reset(int count) {
    for (auto& row : rows)
      for (int b = 0; b < count; ++b) row[size_t(b)] = Bin{};
  }
};

bool is_finite(const Bounds3& b) { return is_finite(b.lo) && is_finite(b.hi) && !b.empty(); }

/// Maps doubled centroids to bins along each axis; NaN (0·∞ when an extent is too small for
/// a finite scale) and out-of-range values land in the end bins, the same way for binning and
/// partitioning. Small nodes use fewer bins (one per primitive, at least 4): no fewer
/// candidate splits that matter, and less fixed work per node.
struct Binner {
  float lo[4] = {0, 0, 0, 0}, scale[4] = {0, 0, 0, 0};  // the fourth lane unused
  int count;

  Binner(const Box4& centroids, uint32_t primitives) : count(int(std::clamp<uint32_t>(primitives, 4, kBins))) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = centroids.lo[a];
      const float extent = centroids.hi[a] - centroids.lo[a];
      // Slightly under count / extent so that the largest centroid lands in the last bin.
      scale[a] = extent > 0 ? float(count) * (1 - 1e-6f) / extent : 0;
    }
  }
  int bin(const BuildRef& r, int axis) const {
    const float f = (r.centroid(axis) - lo[axis]) * scale[axis];
    return f > 0 ? (f < float(count - 1) ? int(f) : count - 1) : 0;
  }
  /// bin(r, axis) for the three axes at once (the fourth lane is unused).
  std::array<int, 4> bins(const BuildRef& r) const {
    std::array<int, 4> out;
#if defined(__SSE2__)
    // max(NaN, 0) is 0 (the second operand), as `f > 0` is false for NaN; min clamps the top;
    // truncation is int(f).
    const __m128 f = _mm_mul_ps(_mm_sub_ps(r.centroids(), _mm_loadu_ps(lo)), _mm_loadu_ps(scale));
    const __m128 clamped = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(float(count - 1)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out.data()), _mm_cvttps_epi32(clamped));
#else
    for (int a = 0; a < 3; ++a) out[size_t(a)] = bin(r, a);
#endif
    return out;
  }
};

// The build's references to the primitives with finite bounds, in id order, and their
// extent; made in chunks on `threads` threads.
BuildRefs make_refs(uint32_t count, const std::function<Bounds3(uint32_t)>& bounds_of, int threads,
                    Extent& extent) {
  constexpr int kChunks = 64;
  BuildRefs refs(count);
  std::array<uint32_t, kChunks> kept{};  // refs made by each chunk, at its start
  std::array<Extent, kChunks> extents;
  parallel_for(kChunks, threads, [&](int chunk, int) {
    const auto [begin, end] = chunk_range(count, chunk, kChunks);
    uint32_t at = uint32_t(begin);
    Extent local;  // not extents[chunk], whose cache line other threads write too
    for (uint32_t prim = uint32_t(begin); prim < end; ++prim) {
      const Bounds3 b = bounds_of(prim);
      if (!is_finite(b)) continue;
      BuildRef& r = refs[at++];
      r.lo[0] = b.lo.x, r.lo[1] = b.lo.y, r.lo[2] = b.lo.z, r.lo[3] = std::bit_cast<float>(prim);
      r.hi[0] = b.hi.x, r.hi[1] = b.hi.y, r.hi[2] = b.hi.z, r.hi[3] = 0;
      local.box.grow(r);
      grow_by_centroid(local.centroids, r);
    }
    extents[size_t(chunk)] = local;
    kept[size_t(chunk)] = at - uint32_t(begin);
  });
  // Close the gaps left by primitives without finite bounds (usually there are none).
  uint32_t size = 0;
  for (int chunk = 0; chunk < kChunks; ++chunk) {
    const size_t begin = chunk_range(count, chunk, kChunks).begin;
    const size_t made = kept[size_t(chunk)];
    if (size != begin) std::copy_n(refs.begin() + long(begin), made, refs.begin() + size);
    size += uint32_t(made);
    extent.box.grow(extents[size_t(chunk)].box);
    extent.centroids.grow(extents[size_t(chunk)].centroids);
  }
  refs.resize(size);
  return refs;
}

class Builder {
 public:
  Builder(BuildRefs refs, const BvhBuildOptions& options, ForkJoinPool& pool)
      : refs_(std::move(refs)), options_(options), pool_(pool) {}

  // The wide hierarchy over all the refs, whose extent is `all`, with room after its nodes
  // for their BvhLayout.
  BvhWideNodes build_wide(const Extent& all) {
    BvhWideNodes nodes;
    if (refs_.empty()) return nodes;
    build_wide_node(divide(0, uint32_t(refs_.size()), all, 0), nodes);
    const auto room = [&](size_t count) {
      return (BvhLayout::bytes_bound(count, refs_.size()) + sizeof(BvhWideNode) - 1) / sizeof(BvhWideNode);
    };
    if (forked_wide_.empty()) {
      nodes.reserve(room(nodes.size()));
      return nodes;
    }
    size_t count = nodes.size();
    for (const BvhWideNodes& subtree : forked_wide_) count += subtree.size();
    BvhWideNodes joined;
    joined.reserve(room(count));
    splice_wide(nodes, 0, joined);
    forked_wide_.clear();
    return joined;
  }

  std::vector<uint32_t> order() const {
    std::vector<uint32_t> ids(refs_.size());
    constexpr int kChunks = 16;
    parallel_for(kChunks, pool_.threads(), [&](int chunk, int) {
      for (auto [i, end] = chunk_range(refs_.size(), chunk, kChunks); i < end; ++i) ids[i] = refs_[i].prim();
    });
    return ids;
  }

 private:
  struct Split {
    int axis = -1;
    int bin = 0;  // left side: bins [0, bin)
    float cost = kInfinity;
    float node_tests = 0;  // the node's primitives in triangle tests: its leaf cost per area
  };

  bool is_shape(const BuildRef& r) const { return r.prim() >= options_.shapes_from; }
  // The cost of testing `count` primitives of which `shapes` are shapes, in triangle tests
  // (exactly float(count) without shapes).
  float tests(uint32_t count, uint32_t shapes) const {
    return float(count) + (options_.shape_cost - 1) * float(shapes);
  }

  // A node of the binary SAH hierarchy over refs_[begin, end), divided as soon as it is made:
  // a leaf, or two children, refs_[begin, mid) of extent `left` and refs_[mid, end) of
  // extent `right`, split on `axis`. Wide nodes gather these; no binary tree is stored.
  struct Divided {
    uint32_t begin = 0, end = 0, mid = 0;
    int depth = 0;
    Extent extent, left, right;
    uint8_t axis = 0;
    bool leaf = true;
  };

  // Divides the node over refs_[begin, end) (whose extent is `extent`): chooses its split,
  // binned SAH on all three axes, or the median of the widest centroid axis when the
  // centroids coincide, SAH found nothing, or the tree got too deep; and partitions its refs.
  Divided divide(uint32_t begin, uint32_t end, const Extent& extent, int depth) {
    Divided d{begin, end, begin, depth, extent, {}, {}, 0, true};
    const uint32_t n = end - begin;
    if (n == 1) return d;
    const Box4& centroids = extent.centroids;
    const int widest = centroids.extent(0) >= centroids.extent(1) ? (centroids.extent(0) >= centroids.extent(2) ? 0 : 2)
                                                                   : (centroids.extent(1) >= centroids.extent(2) ? 1 : 2);
    int axis = widest;
    bool use_median = depth >= kMaxSahDepth || !(centroids.extent(widest) > 0);
    if (!use_median) {
      const Binner binner(centroids, n);
      const Split split = find_split(begin, end, binner);
      const float leaf_cost = split.node_tests * extent.box.half_area();
      if (n <= uint32_t(options_.max_leaf_size) && leaf_cost <= split.cost) return d;
      if (split.axis < 0) {
        use_median = true;
      } else {
        axis = split.axis;
        d.mid = partition(begin, end, [&](const BuildRef& r) { return binner.bin(r, axis) < split.bin; }, d.left, d.right);
        use_median = d.mid == begin || d.mid == end;
      }
    }
    if (use_median) {
      if (n <= uint32_t(options_.max_leaf_size)) return d;
      axis = widest;
      d.mid = begin + n / 2;
      if (centroids.extent(widest) > 0)
        std::nth_element(refs_.data() + begin, refs_.data() + d.mid, refs_.data() + end,
                         [&](const BuildRef& a, const BuildRef& b) { return a.centroid(axis) < b.centroid(axis); });
      d.left = extent_of(begin, d.mid);
      d.right = extent_of(d.mid, end);
    }
    d.axis = uint8_t(axis);
    d.leaf = false;
    return d;
  }

  bool forks(const Divided& d) const { return pool_.threads() > 1 && d.end - d.begin >= kMinParallelSize; }

  // Divides the two children of `d` into `first` and `second`, at once when they are large.
  void divide_children(const Divided& d, Divided& first, Divided& second) {
    if (forks(d)) {
      ForkJoinPool::Task task(pool_, [&] { first = divide(d.begin, d.mid, d.left, d.depth + 1); });
      second = divide(d.mid, d.end, d.right, d.depth + 1);
      task.join();
    } else {
      first = divide(d.begin, d.mid, d.left, d.depth + 1);
      second = divide(d.mid, d.end, d.right, d.depth + 1);
    }
  }

  // Gathers into `kids` the children of the wide node for the binary subtree of `d`, and
  // returns how many: the two of `d`, then, while there is room, the inner child of largest
  // surface area replaced by its two (the first in its slot, the second last), so that the
  // boxes a ray tests together cover the most of the node. A leaf `d` is its only child.
  int gather_children(const Divided& d, std::array<Divided, kBvhWidth>& kids) {
    if (d.leaf) {
      kids[0] = d;
      return 1;
    }
    std::array<float, kBvhWidth> area{};  // −1 for a leaf, which is never opened
    const auto area_of = [](const Divided& kid) { return kid.leaf ? -1.f : kid.extent.box.half_area(); };
    divide_children(d, kids[0], kids[1]);
    area[0] = area_of(kids[0]);
    area[1] = area_of(kids[1]);
    int n = 2;
    while (n < kBvhWidth) {
      int open = 0;
      for (int i = 1; i < n; ++i)
        if (area[size_t(i)] > area[size_t(open)]) open = i;
      if (area[size_t(open)] < 0) break;
      const Divided inner = kids[size_t(open)];
      divide_children(inner, kids[size_t(open)], kids[size_t(n)]);
      area[size_t(open)] = area_of(kids[size_t(open)]);
      area[size_t(n)] = area_of(kids[size_t(n)]);
      ++n;
    }
    return n;
  }

  // Appends to `out` the wide node for the binary subtree of `d`, then the wide nodes below it
  // depth-first, except that large inner children are forked into subtrees of their own
  // (spliced in later) and named by kForkedChild words; returns its index.
  uint32_t build_wide_node(const Divided& d, BvhWideNodes& out) {
    std::array<Divided, kBvhWidth> kids;
    const size_t n = size_t(gather_children(d, kids));

    // Fill the slots; unused ones keep empty bounds (lo = +inf, hi = −inf) and word 0.
    const uint32_t index = uint32_t(out.size());
    BvhWideNode node = BvhWideNode::without_children();
    for (size_t i = 0; i < n; ++i) {
      const Box4& box = kids[i].extent.box;
      for (size_t k = 0; k < 3; ++k) {
        node.bounds[k][i] = box.lo[k];
        node.bounds[k + 3][i] = box.hi[k];
      }
      if (kids[i].leaf) node.child[i] = BvhWideNode::leaf_word(kids[i].begin, kids[i].end - kids[i].begin);
    }
    out.push_back(node);
    std::deque<ForkJoinPool::Task> tasks;
    for (size_t i = 0; i < n; ++i) {
      if (kids[i].leaf) continue;
      if (forks(kids[i])) {
        const std::pair<BvhWideNodes*, uint32_t> forked = new_forked_wide();
        out[index].child[i] = forked.second;
        tasks.emplace_back(pool_, [this, &kids, i, subtree = forked.first] { build_wide_node(kids[i], *subtree); });
      } else {
        const uint32_t child = build_wide_node(kids[i], out);
        out[index].child[i] = child;
      }
    }
    for (ForkJoinPool::Task& task : tasks) task.join();
    return index;
  }

  // A child word naming forked wide subtree number (word & ~kForkedChild): above any node
  // index (there are fewer nodes than primitives), below the leaf flag.
  static constexpr uint32_t kForkedChild = 0x40000000u;
  static_assert(BvhWideNode::kMaxLeafPrimitives <= kForkedChild && kForkedChild < BvhWideNode::kLeafFlag);

  // A new, empty wide subtree, and the child word that names it.
  std::pair<BvhWideNodes*, uint32_t> new_forked_wide() {
    std::lock_guard lock(forked_mutex_);
    const uint32_t word = kForkedChild | uint32_t(forked_wide_.size());
    return {&forked_wide_.emplace_back(), word};  // a deque: earlier subtrees stay where they are
  }

  // Appends the wide subtree at nodes[i] to `out` in plain depth-first order, with forked
  // subtrees in their places; returns the index of its root there.
  uint32_t splice_wide(const BvhWideNodes& nodes, uint32_t i, BvhWideNodes& out) const {
    const uint32_t index = uint32_t(out.size());
    out.push_back(nodes[i]);
    for (size_t c = 0; c < size_t(kBvhWidth); ++c) {
      const uint32_t word = nodes[i].child[c];
      if (word == 0 || nodes[i].is_leaf(c)) continue;  // an unused slot (no root is a child), or a leaf
      const uint32_t child = (word & kForkedChild) != 0 ? splice_wide(forked_wide_[word & ~kForkedChild], 0, out)
                                                        : splice_wide(nodes, word, out);
      out[index].child[c] = child;
    }
    return index;
  }

  Extent extent_of(uint32_t begin, uint32_t end) const {
    Extent e;
    for (uint32_t i = begin; i < end; ++i) add(e, refs_[i]);
    return e;
  }

  static void add(Extent& e, const BuildRef& r) {
    e.box.grow(r);
    grow_by_centroid(e.centroids, r);
  }

  // Moves the refs for which `goes_left` holds to the front of [begin, end) and returns the
  // boundary, computing each side's extent on the way.
  template <class Predicate>
  uint32_t partition(uint32_t begin, uint32_t end, Predicate goes_left, Extent& left, Extent& right) {
    uint32_t i = begin, j = end;
    while (i < j) {
      if (goes_left(refs_[i])) {
        add(left, refs_[i++]);
      } else {
        --j;
        std::swap(refs_[i], refs_[j]);
        add(right, refs_[j]);
      }
    }
    return i;
  }

  // Bins refs_[begin, end) on all three axes at once.
  void bin(uint32_t begin, uint32_t end, const Binner& binner, Bins& bins) const {
    const auto add_to = [&](Bins& to, const BuildRef& ref) {
      const std::array<int, 4> at = binner.bins(ref);
      for (size_t axis = 0; axis < 3; ++axis) {
        Bin& b = to[axis][size_t(at[axis])];
        b.box.grow(ref);
        ++b.count;
        b.shapes += is_shape(ref);
      }
    };
    // Neighbouring refs mostly fall in the same bins; alternating between two sets of bins
    // lets one ref's update start before the previous one's has been stored.
    constexpr uint32_t kTwoSets = 1024;
    if (end - begin < kTwoSets) {
      for (uint32_t i = begin; i < end; ++i) add_to(bins, refs_[i]);
      return;
    }
    Bins odd;
    odd.reset(binner.count);
    uint32_t i = begin;
    for (; i + 1 < end; i += 2) {
      add_to(bins, refs_[i]);
      add_to(odd, refs_[i + 1]);
    }
    if (i < end) add_to(bins, refs_[i]);
    merge(bins, odd, binner.count);
  }

  static void merge(Bins& into, const Bins& from, int count) {
    for (size_t a = 0; a < 3; ++a)
      for (size_t b = 0; b < size_t(count); ++b) {
        into[a][b].box.grow(from[a][b].box);
        into[a][b].count += from[a][b].count;
        into[a][b].shapes += from[a][b].shapes;
      }
  }

  // The cheapest SAH split over all axes, costs in units of half node area (not divided by
  // it, so flat or point-like nodes need no special case).
  Split find_split(uint32_t begin, uint32_t end, const Binner& binner) {
    // Compute the bins, in slices on the pool's threads for the largest nodes.
    const int count = binner.count;
    Bins bins;
    bins.reset(count);
    const uint32_t n = end - begin;
    const int slices = pool_.threads();
    if (slices > 1 && n >= kMinParallelBinning) {
      std::vector<Bins> partial(static_cast<size_t>(slices));
      for (Bins& p : partial) p.reset(count);
      const auto bin_slice = [&](int t) {
        const uint32_t lo = begin + uint32_t(uint64_t(n) * uint64_t(t) / uint64_t(slices));
        const uint32_t hi = begin + uint32_t(uint64_t(n) * uint64_t(t + 1) / uint64_t(slices));
        bin(lo, hi, binner, partial[size_t(t)]);
      };
      std::deque<ForkJoinPool::Task> tasks;
      for (int t = 1; t < slices; ++t) tasks.emplace_back(pool_, [&, t] { bin_slice(t); });
      bin_slice(0);
      for (ForkJoinPool::Task& task : tasks) task.join();
      for (const Bins& p : partial) merge(bins, p, count);
    } else {
      bin(begin, end, binner, bins);
    }

    Split best;
    uint32_t node_shapes = 0;  // every ref is in one bin of each axis
    for (int b = 0; b < count; ++b) node_shapes += bins[0][size_t(b)].shapes;
    best.node_tests = tests(n, node_shapes);
    for (int axis = 0; axis < 3; ++axis) {
      if (!(binner.scale[axis] > 0)) continue;
      const auto& axis_bins = bins[size_t(axis)];
      // Compute the right-hand costs, then sweep from the left.
      std::array<float, kBins> right_cost;
      Box4 right;
      uint32_t right_count = 0, right_shapes = 0;
      // A split after an empty bin has the sides, and so the cost, of the split before it, which
      // was tried first and wins a tie: it is skipped, and so are empty bins' (empty) boxes.
      for (int b = count - 1; b > 0; --b) {
        const Bin& bin = axis_bins[size_t(b)];
        if (bin.count > 0) {
          right.grow(bin.box);
          right_count += bin.count;
          right_shapes += bin.shapes;
        }
        if (axis_bins[size_t(b - 1)].count > 0) right_cost[size_t(b)] = right.half_area() * tests(right_count, right_shapes);
      }
      Box4 node = right;
      node.grow(axis_bins[0].box);
      const float traversal = options_.traversal_cost * node.half_area();
      Box4 left;
      uint32_t left_count = 0, left_shapes = 0;
      for (int b = 1; b < count; ++b) {
        const Bin& bin = axis_bins[size_t(b - 1)];
        if (bin.count == 0) continue;
        left.grow(bin.box);
        left_count += bin.count;
        left_shapes += bin.shapes;
        if (left_count == n) break;
        const float cost = traversal + left.half_area() * tests(left_count, left_shapes) + right_cost[size_t(b)];
        if (cost < best.cost) best = {axis, b, cost, best.node_tests};
      }
    }
    return best;
  }

  BuildRefs refs_;
  BvhBuildOptions options_;
  ForkJoinPool& pool_;
  std::mutex forked_mutex_;
  std::deque<BvhWideNodes> forked_wide_;  // subtrees built as forked tasks
};

}  // namespace

BvhTree build_bvh(size_t count, const std::function<Bounds3(uint32_t)>& bounds_of,
                  const BvhBuildOptions& options) {
  // Leaf words hold a leaf's first entry and count (BvhWideNode::leaf_word).
  if (count > BvhWideNode::kMaxLeafPrimitives)
    throw std::length_error("the BVH indexes at most " + std::to_string(BvhWideNode::kMaxLeafPrimitives) +
                            " primitives; use --accel embree for this scene");
  MJRAY_CHECK(options.max_leaf_size >= 1 && options.max_leaf_size < (1 << BvhWideNode::kCountBits));
  const int threads = resolve_thread_count(options.threads);
  Extent all;
  BuildRefs refs = make_refs(uint32_t(count), bounds_of, threads, all);
  ForkJoinPool pool(threads);
  Builder builder(std::move(refs), options, pool);
  BvhTree tree;
  tree.nodes = builder.build_wide(all);
  tree.order = builder.order();
  if (!tree.nodes.empty())
    tree.bounds = {{all.box.lo[0], all.box.lo[1], all.box.lo[2]}, {all.box.hi[0], all.box.hi[1], all.box.hi[2]}};
  return tree;
}

}  // namespace mjray
