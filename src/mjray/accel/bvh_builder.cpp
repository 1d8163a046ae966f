#include "mjray/accel/bvh_builder.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <system_error>
#include <thread>

namespace mjray {

namespace {

constexpr int kBins = 32;
// Below this many primitives a subtree is built on the current thread.
constexpr uint32_t kMinParallelSize = 8192;
// Deeper than this, splits halve the primitives, so the depth (and the traversal stack)
// stays under kMaxSahDepth + 32.
constexpr int kMaxSahDepth = 30;

/// A primitive during the build: its bounds, with the centroid kept doubled (lo + hi).
struct BuildRef {
  Bounds3 box;
  uint32_t prim;
  float centroid(int axis) const { return box.lo[axis] + box.hi[axis]; }
};

struct Bin {
  Bounds3 box;
  uint32_t count = 0;
};

bool is_finite(const Bounds3& b) { return is_finite(b.lo) && is_finite(b.hi) && !b.empty(); }

std::array<float, 3> floats(const Point3& p) { return {p.x, p.y, p.z}; }

class Builder {
 public:
  Builder(std::vector<BuildRef> refs, const BvhBuildOptions& options)
      : refs_(std::move(refs)), options_(options) {}

  std::vector<BvhNode> build(int threads) {
    std::vector<BvhNode> nodes;
    nodes.reserve(refs_.size() * 2 / std::max(1, options_.max_leaf_size) + 1);
    if (!refs_.empty()) build_node(0, uint32_t(refs_.size()), 0, threads, nodes);
    return nodes;
  }

  std::vector<uint32_t> order() const {
    std::vector<uint32_t> ids(refs_.size());
    for (size_t i = 0; i < refs_.size(); ++i) ids[i] = refs_[i].prim;
    return ids;
  }

 private:
  struct Split {
    int axis = -1;
    int bin = 0;       // left side: bins [0, bin)
    float cost = kInfinity;
  };

  // Appends the subtree over refs_[begin, end) to `out`, depth-first, child indices absolute
  // in `out`.
  void build_node(uint32_t begin, uint32_t end, int depth, int threads, std::vector<BvhNode>& out) {
    const uint32_t n = end - begin;
    Bounds3 box, centroids;
    for (uint32_t i = begin; i < end; ++i) {
      box.expand(refs_[i].box);
      centroids.expand(Point3(refs_[i].centroid(0), refs_[i].centroid(1), refs_[i].centroid(2)));
    }
    const uint32_t index = uint32_t(out.size());
    out.push_back({floats(box.lo), floats(box.hi), 0, 0, 0});
    const auto make_leaf = [&] {
      out[index].offset = begin;
      out[index].count = uint16_t(n);
    };
    if (n == 1) return make_leaf();

    // Choose a split: binned SAH on all three axes, or the median of the widest centroid
    // axis when the centroids coincide, SAH found nothing, or the tree got too deep.
    const Vector3 extent = centroids.diagonal();
    const int widest = extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
    uint32_t mid = begin;
    int axis = widest;
    bool use_median = depth >= kMaxSahDepth || !(extent[widest] > 0);
    if (!use_median) {
      const Split split = find_split(begin, end, centroids);
      const float leaf_cost = float(n) * box.surface_area();
      if (n <= uint32_t(options_.max_leaf_size) && leaf_cost <= split.cost) return make_leaf();
      if (split.axis < 0) {
        use_median = true;
      } else {
        axis = split.axis;
        const float lo = centroids.lo[axis], scale = bin_scale(centroids, axis);
        BuildRef* mid_ptr = std::partition(refs_.data() + begin, refs_.data() + end,
                                           [&](const BuildRef& r) { return bin_of(r, axis, lo, scale) < split.bin; });
        mid = uint32_t(mid_ptr - refs_.data());
        use_median = mid == begin || mid == end;
      }
    }
    if (use_median) {
      if (n <= uint32_t(options_.max_leaf_size)) return make_leaf();
      axis = widest;
      mid = begin + n / 2;
      if (extent[widest] > 0)
        std::nth_element(refs_.data() + begin, refs_.data() + mid, refs_.data() + end,
                         [&](const BuildRef& a, const BuildRef& b) { return a.centroid(axis) < b.centroid(axis); });
    }
    out[index].axis = uint8_t(axis);

    // Build the children: the first right after this node, the second after the first's
    // subtree; large subtrees on two threads, spliced in afterwards.
    std::vector<BvhNode> first, second;
    std::future<void> task;  // declared after its outputs: its destructor waits for it
    if (threads > 1 && n >= kMinParallelSize) {
      try {
        task = std::async(std::launch::async, [&] { build_node(begin, mid, depth + 1, threads / 2, first); });
      } catch (const std::system_error&) {
        threads = 1;  // no thread to be had: build this subtree serially
      }
    }
    if (task.valid()) {
      build_node(mid, end, depth + 1, threads - threads / 2, second);
      task.get();
      append(out, first);
      out[index].offset = uint32_t(out.size());
      append(out, second);
    } else {
      build_node(begin, mid, depth + 1, threads, out);
      out[index].offset = uint32_t(out.size());
      build_node(mid, end, depth + 1, threads, out);
    }
  }

  static float bin_scale(const Bounds3& centroids, int axis) {
    // Slightly under kBins / extent so that the largest centroid lands in the last bin.
    return float(kBins) * (1 - 1e-6f) / (centroids.hi[axis] - centroids.lo[axis]);
  }

  // The bin of a centroid; NaN (0·∞ when the extent is too small for a finite scale) and
  // out-of-range values land in the end bins, the same way for binning and partitioning.
  static int bin_of(const BuildRef& r, int axis, float lo, float scale) {
    const float f = (r.centroid(axis) - lo) * scale;
    return f > 0 ? (f < float(kBins - 1) ? int(f) : kBins - 1) : 0;
  }

  // The cheapest SAH split over all axes, costs in units of node area (not divided by it,
  // so flat or point-like nodes need no special case).
  Split find_split(uint32_t begin, uint32_t end, const Bounds3& centroids) const {
    // Bin the primitives on all three axes in one pass over them.
    const Vector3 extent = centroids.diagonal();
    std::array<std::array<Bin, kBins>, 3> bins{};
    std::array<float, 3> lo{}, scale{};
    for (int axis = 0; axis < 3; ++axis) {
      lo[size_t(axis)] = centroids.lo[axis];
      scale[size_t(axis)] = extent[axis] > 0 ? bin_scale(centroids, axis) : 0;
    }
    for (uint32_t i = begin; i < end; ++i) {
      const BuildRef& ref = refs_[i];
      for (size_t axis = 0; axis < 3; ++axis) {
        Bin& bin = bins[axis][size_t(bin_of(ref, int(axis), lo[axis], scale[axis]))];
        bin.box.expand(ref.box);
        ++bin.count;
      }
    }

    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!(extent[axis] > 0)) continue;
      const auto& axis_bins = bins[size_t(axis)];
      // Compute the right-hand areas and counts, then sweep from the left.
      std::array<float, kBins> right_cost{};
      Bounds3 right;
      uint32_t right_count = 0;
      for (int b = kBins - 1; b > 0; --b) {
        right.expand(axis_bins[size_t(b)].box);
        right_count += axis_bins[size_t(b)].count;
        right_cost[size_t(b)] = right.surface_area() * float(right_count);
      }
      Bounds3 left;
      uint32_t left_count = 0;
      Bounds3 node;
      for (const Bin& bin : axis_bins) node.expand(bin.box);
      const float traversal = options_.traversal_cost * node.surface_area();
      for (int b = 1; b < kBins; ++b) {
        left.expand(axis_bins[size_t(b - 1)].box);
        left_count += axis_bins[size_t(b - 1)].count;
        if (left_count == 0 || left_count == end - begin) continue;
        const float cost = traversal + left.surface_area() * float(left_count) + right_cost[size_t(b)];
        if (cost < best.cost) best = {axis, b, cost};
      }
    }
    return best;
  }

  static void append(std::vector<BvhNode>& out, const std::vector<BvhNode>& subtree) {
    const uint32_t shift = uint32_t(out.size());
    for (BvhNode node : subtree) {
      if (node.count == 0) node.offset += shift;
      out.push_back(node);
    }
  }

  std::vector<BuildRef> refs_;
  BvhBuildOptions options_;
};

}  // namespace

BvhBuildResult build_bvh(std::span<const Bounds3> bounds, const BvhBuildOptions& options) {
  std::vector<BuildRef> refs;
  refs.reserve(bounds.size());
  for (uint32_t prim = 0; prim < bounds.size(); ++prim)
    if (is_finite(bounds[prim])) refs.push_back({bounds[prim], prim});
  const int threads = options.threads > 0 ? options.threads
                                          : int(std::max(1u, std::thread::hardware_concurrency()));
  Builder builder(std::move(refs), options);
  BvhBuildResult result;
  result.nodes = builder.build(threads);
  result.order = builder.order();
  return result;
}

namespace {

float surface_area(const BvhNode& n) {
  const float dx = n.hi[0] - n.lo[0], dy = n.hi[1] - n.lo[1], dz = n.hi[2] - n.lo[2];
  return dx * dy + dy * dz + dz * dx;
}

// Turns the binary tree into wide nodes.
class Collapser {
 public:
  explicit Collapser(const std::vector<BvhNode>& binary) : binary_(binary) {}

  // Appends the wide node for binary node `b` and its subtree; returns its index.
  uint32_t collapse(uint32_t b, std::vector<BvhWideNode>& out) const {
    // Gather up to kBvhWidth children, opening the largest inner one each time.
    std::array<uint32_t, kBvhWidth> kids{};
    int n = 0;
    if (is_leaf(b)) {
      kids[size_t(n++)] = b;  // a leaf root becomes the only child of a wide root
    } else {
      kids[size_t(n++)] = b + 1;
      kids[size_t(n++)] = binary_[b].offset;
      while (n < kBvhWidth) {
        int open = -1;
        for (int i = 0; i < n; ++i)
          if (!is_leaf(kids[size_t(i)]) &&
              (open < 0 || surface_area(binary_[kids[size_t(i)]]) > surface_area(binary_[kids[size_t(open)]])))
            open = i;
        if (open < 0) break;
        const uint32_t inner = kids[size_t(open)];
        kids[size_t(open)] = inner + 1;
        kids[size_t(n++)] = binary_[inner].offset;
      }
    }

    // Fill the slots; unused ones keep empty bounds (lo = +inf, hi = −inf).
    const uint32_t index = uint32_t(out.size());
    BvhWideNode node{};
    for (size_t k = 0; k < 3; ++k) {
      node.bounds[k].fill(kInfinity);
      node.bounds[k + 3].fill(-kInfinity);
    }
    for (size_t i = 0; i < size_t(n); ++i) {
      const BvhNode& kid = binary_[kids[i]];
      for (size_t k = 0; k < 3; ++k) {
        node.bounds[k][i] = kid.lo[k];
        node.bounds[k + 3][i] = kid.hi[k];
      }
      if (is_leaf(kids[i])) {
        node.child[i] = kid.offset;
        node.count[i] = uint8_t(kid.count);
      }
    }
    out.push_back(node);
    for (size_t i = 0; i < size_t(n); ++i)
      if (!is_leaf(kids[i])) {
        const uint32_t child = collapse(kids[i], out);
        out[index].child[i] = child;
      }
    return index;
  }

 private:
  bool is_leaf(uint32_t b) const { return binary_[b].count > 0; }

  const std::vector<BvhNode>& binary_;
};

}  // namespace

std::vector<BvhWideNode> collapse_to_wide(const std::vector<BvhNode>& binary) {
  std::vector<BvhWideNode> wide;
  if (binary.empty()) return wide;
  wide.reserve(binary.size() / (kBvhWidth - 1) + 1);
  Collapser(binary).collapse(0, wide);
  wide.shrink_to_fit();
  return wide;
}

}  // namespace mjray
