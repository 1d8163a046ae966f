// BVH traversal for one instruction set. Included only by bvh.cpp, once per instruction set
// inside its own namespace (hence no include guard): with MJRAY_BVH_AVX 0 for the baseline
// build (SSE2, or plain C++ elsewhere), and with MJRAY_BVH_AVX 1 under
// `#pragma GCC target("avx")`, chosen at run time. The pragma adds no fused multiply-add,
// so the inlined watertight test rounds exactly as World::intersect_primitive's does.
// Reads only what mjray/accel/bvh_traversal.h declares (its namespace is opened here), which the
// including file includes first.

using namespace bvh_traversal;

/// What the slab tests need of a ray, splatted across SIMD lanes once per ray.
struct BoxRay {
#if MJRAY_BVH_AVX
  using Lanes = __m256;
  static Lanes splat(float x) { return _mm256_set1_ps(x); }
#elif defined(__SSE2__)
  using Lanes = __m128;
  static Lanes splat(float x) { return _mm_set1_ps(x); }
#else
  using Lanes = std::array<float, 4>;
  static Lanes splat(float x) { return {x, x, x, x}; }
#endif
  Lanes origin[3];
  Lanes inv_dir[3];
  Lanes far_scale;
  Lanes t_min, t_max;  // the range boxes are cut to
  size_t near_row[3];  // row of BvhWideNode::bounds that the ray enters through, per axis
  size_t far_row[3];

  BoxRay(const Ray& ray, Interval t_range) : t_min(splat(t_range.min)), t_max(splat(t_range.max)) {
    for (int a = 0; a < 3; ++a) {
      const float d = ray.direction[a];
      const bool negative = std::signbit(d);  // −0 counts as negative, matching 1/−0 = −∞
      origin[a] = splat(ray.origin[a]);
      inv_dir[a] = splat(1 / d);  // ±inf for a zero component
      near_row[a] = size_t(negative ? a + 3 : a);
      far_row[a] = size_t(negative ? a : a + 3);
    }
    far_scale = splat(kFarScale);
  }

  /// Cuts the range at a hit found.
  void set_t_max(float t) { t_max = splat(t); }
};

// Slab test of a node's children against t in [t_min, t_max]: a bit per child hit, and each
// child's entry distance. A slab distance is NaN only for a zero direction component with
// the origin on the slab plane (0·∞); the reductions keep their other operand then (as
// max/min instructions do for NaN in the first operand), so such a slab does not cull: a
// ray lying in a box's face may still hit what lies on it.
inline unsigned hit_children(const BvhWideNode& node, const BoxRay& r, std::array<float, kBvhWidth>& t_enter) {
  const auto& b = node.bounds;
  unsigned mask = 0;
#if MJRAY_BVH_AVX
  static_assert(kBvhWidth == 8);
  const auto slab = [&](size_t row, int a) {
    return _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b[row].data()), r.origin[a]), r.inv_dir[a]);
  };
  const __m256 t_near = _mm256_max_ps(
      slab(r.near_row[0], 0), _mm256_max_ps(slab(r.near_row[1], 1), _mm256_max_ps(slab(r.near_row[2], 2), r.t_min)));
  const __m256 t_far = _mm256_min_ps(
      slab(r.far_row[0], 0), _mm256_min_ps(slab(r.far_row[1], 1), _mm256_min_ps(slab(r.far_row[2], 2), r.t_max)));
  _mm256_storeu_ps(t_enter.data(), t_near);
  mask = unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t_near, _mm256_mul_ps(t_far, r.far_scale), _CMP_LE_OQ)));
#elif defined(__SSE2__)
  for (size_t g = 0; g < kBvhWidth; g += 4) {
    const auto slab = [&](size_t row, int a) {
      return _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&b[row][g]), r.origin[a]), r.inv_dir[a]);
    };
    const __m128 t_near = _mm_max_ps(
        slab(r.near_row[0], 0), _mm_max_ps(slab(r.near_row[1], 1), _mm_max_ps(slab(r.near_row[2], 2), r.t_min)));
    const __m128 t_far = _mm_min_ps(
        slab(r.far_row[0], 0), _mm_min_ps(slab(r.far_row[1], 1), _mm_min_ps(slab(r.far_row[2], 2), r.t_max)));
    _mm_storeu_ps(&t_enter[g], t_near);
    mask |= unsigned(_mm_movemask_ps(_mm_cmple_ps(t_near, _mm_mul_ps(t_far, r.far_scale)))) << g;
  }
#else
  for (size_t i = 0; i < kBvhWidth; ++i) {
    float t_near = r.t_min[0], t_far = r.t_max[0];
    for (int a = 0; a < 3; ++a) {
      const float t0 = (b[r.near_row[a]][i] - r.origin[a][0]) * r.inv_dir[a][0];
      const float t1 = (b[r.far_row[a]][i] - r.origin[a][0]) * r.inv_dir[a][0];
      t_near = t0 > t_near ? t0 : t_near;
      t_far = t1 < t_far ? t1 : t_far;
    }
    t_enter[i] = t_near;
    if (t_near <= t_far * kFarScale) mask |= 1u << i;
  }
#endif
  return mask;
}

/// What the four-wide test of a leaf run (count ≤ 4) finds, a bit or a lane per entry.
struct LeafLanes {
  unsigned hits = 0;       ///< triangles that pass every float check of the watertight test here
  unsigned full_test = 0;  ///< entries only the full test decides: shapes, and zero edge functions
  // For the hits: the distance and barycentrics, and what the range and error checks need.
  alignas(16) std::array<float, 4> t, b1, b2, t_scaled, det, max_z, max_xt, max_yt, max_e;
};

/// Runs the watertight test on a leaf run's triangles four at once for t in `t_range`, with the
/// same float operations in the same order as intersect_triangle, so a triangle counts as a
/// hit (pending the error bound, left to leaf_entry_hit) exactly when that test's float checks
/// would pass. Triangles with an edge function of zero are left to the full test, whose double
/// fallback decides them, and so are shapes.
inline void test_leaf(const TraversalView& bvh, const WatertightRay& ray, const LeafRun& run, Interval t_range,
                      LeafLanes& out) {
  const unsigned all = (1u << run.count) - 1;
#if defined(__SSE2__)
  unsigned shapes = 0;
  if (!bvh.only_triangles) {
    for (uint32_t i = 0; i < run.count; ++i) shapes |= unsigned(run.prim(i) >= bvh.triangle_count) << i;
    if (shapes == all) {
      out.full_test = all;
      return;
    }
  }
  // Lanes past the run's count hold the next row's floats: they are masked off.
  const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
  const size_t corner_rows = 3 * size_t(run.count);
  const float* x0 = run.data + size_t(kx) * run.count;
  const float* y0 = run.data + size_t(ky) * run.count;
  const float* z0 = run.data + size_t(kz) * run.count;
  const auto coordinate = [&](size_t corner, const float* row0) { return _mm_loadu_ps(row0 + corner * corner_rows); };
  const __m128 ox = _mm_set1_ps(ray.origin[size_t(kx)]), oy = _mm_set1_ps(ray.origin[size_t(ky)]);
  const __m128 oz = _mm_set1_ps(ray.origin[size_t(kz)]);
  const __m128 sx = _mm_set1_ps(ray.sx), sy = _mm_set1_ps(ray.sy), sz = _mm_set1_ps(ray.sz);
  const __m128 az = _mm_sub_ps(coordinate(0, z0), oz), bz = _mm_sub_ps(coordinate(1, z0), oz);
  const __m128 cz = _mm_sub_ps(coordinate(2, z0), oz);
  const __m128 ax = _mm_add_ps(_mm_sub_ps(coordinate(0, x0), ox), _mm_mul_ps(sx, az));
  const __m128 ay = _mm_add_ps(_mm_sub_ps(coordinate(0, y0), oy), _mm_mul_ps(sy, az));
  const __m128 bx = _mm_add_ps(_mm_sub_ps(coordinate(1, x0), ox), _mm_mul_ps(sx, bz));
  const __m128 by = _mm_add_ps(_mm_sub_ps(coordinate(1, y0), oy), _mm_mul_ps(sy, bz));
  const __m128 cx = _mm_add_ps(_mm_sub_ps(coordinate(2, x0), ox), _mm_mul_ps(sx, cz));
  const __m128 cy = _mm_add_ps(_mm_sub_ps(coordinate(2, y0), oy), _mm_mul_ps(sy, cz));
  const __m128 e0 = _mm_sub_ps(_mm_mul_ps(bx, cy), _mm_mul_ps(by, cx));
  const __m128 e1 = _mm_sub_ps(_mm_mul_ps(cx, ay), _mm_mul_ps(cy, ax));
  const __m128 e2 = _mm_sub_ps(_mm_mul_ps(ax, by), _mm_mul_ps(ay, bx));
  const __m128 zero = _mm_setzero_ps();
  const auto any = [](__m128 a, __m128 b, __m128 c) { return _mm_or_ps(_mm_or_ps(a, b), c); };
  const __m128 zeroes = any(_mm_cmpeq_ps(e0, zero), _mm_cmpeq_ps(e1, zero), _mm_cmpeq_ps(e2, zero));
  out.full_test = shapes | (unsigned(_mm_movemask_ps(zeroes)) & all);
  // The edge functions have strictly mixed signs: most leaves end here.
  const __m128 outside = _mm_and_ps(any(_mm_cmplt_ps(e0, zero), _mm_cmplt_ps(e1, zero), _mm_cmplt_ps(e2, zero)),
                                    any(_mm_cmpgt_ps(e0, zero), _mm_cmpgt_ps(e1, zero), _mm_cmpgt_ps(e2, zero)));
  const unsigned inside = ~unsigned(_mm_movemask_ps(outside)) & all & ~out.full_test;
  if (inside == 0) return;
  // The determinant is zero or not finite (x − x is 0 only for finite x).
  const __m128 det = _mm_add_ps(_mm_add_ps(e0, e1), e2);
  const __m128 no_det = _mm_or_ps(_mm_cmpeq_ps(det, zero), _mm_cmpneq_ps(_mm_sub_ps(det, det), zero));
  // The scaled distance lies outside the range.
  const __m128 t_scaled = _mm_add_ps(_mm_add_ps(_mm_mul_ps(e0, _mm_mul_ps(az, sz)), _mm_mul_ps(e1, _mm_mul_ps(bz, sz))),
                                     _mm_mul_ps(e2, _mm_mul_ps(cz, sz)));
  const __m128 t_min = _mm_set1_ps(t_range.min), t_max = _mm_set1_ps(t_range.max);
  const __m128 min_det = _mm_mul_ps(t_min, det), max_det = _mm_mul_ps(t_max, det);
  const __m128 out_of_range = _mm_or_ps(
      _mm_and_ps(_mm_cmplt_ps(det, zero), _mm_or_ps(_mm_cmpge_ps(t_scaled, min_det), _mm_cmplt_ps(t_scaled, max_det))),
      _mm_and_ps(_mm_cmpgt_ps(det, zero), _mm_or_ps(_mm_cmple_ps(t_scaled, min_det), _mm_cmpgt_ps(t_scaled, max_det))));
  const unsigned passing = inside & ~unsigned(_mm_movemask_ps(_mm_or_ps(no_det, out_of_range)));
  if (passing == 0) return;
  // The distance is above t_min and finite.
  const __m128 inv_det = _mm_div_ps(_mm_set1_ps(1.f), det);
  const __m128 t = _mm_mul_ps(t_scaled, inv_det);
  const __m128 ahead = _mm_and_ps(_mm_cmpgt_ps(t, t_min), _mm_cmpeq_ps(_mm_sub_ps(t, t), zero));
  out.hits = passing & unsigned(_mm_movemask_ps(ahead));
  if (out.hits == 0) return;
  const __m128 sign = _mm_set1_ps(-0.f);
  const auto largest = [&](__m128 a, __m128 b, __m128 c) {
    return _mm_max_ps(_mm_max_ps(_mm_andnot_ps(sign, a), _mm_andnot_ps(sign, b)), _mm_andnot_ps(sign, c));
  };
  _mm_store_ps(out.t.data(), t);
  _mm_store_ps(out.b1.data(), _mm_mul_ps(e1, inv_det));
  _mm_store_ps(out.b2.data(), _mm_mul_ps(e2, inv_det));
  _mm_store_ps(out.t_scaled.data(), t_scaled);
  _mm_store_ps(out.det.data(), det);
  _mm_store_ps(out.max_z.data(), largest(az, bz, cz));
  _mm_store_ps(out.max_xt.data(), largest(ax, bx, cx));
  _mm_store_ps(out.max_yt.data(), largest(ay, by, cy));
  _mm_store_ps(out.max_e.data(), largest(e0, e1, e2));
#else
  (void)bvh, (void)ray, (void)t_range;
  out.full_test = all;
#endif
}

/// Entry i's hit for t in `t_range` (within the range test_leaf was given), exactly as
/// intersect_triangle or the shape's own test finds it.
/// Always inlined: its shape branch is large enough that GCC would otherwise call it.
[[gnu::always_inline]] inline std::optional<Hit> leaf_entry_hit(const TraversalView& bvh, const Ray& ray,
                                                                const WatertightRay& tri_ray, const LeafRun& run,
                                                                const LeafLanes& lanes, uint32_t i, Interval t_range) {
  const uint32_t prim = run.prim(i);
  if ((lanes.hits >> i & 1) != 0) {
    // The range may have shrunk since the leaf was tested.
    if (!scaled_distance_in_range(lanes.t_scaled[i], lanes.det[i], t_range) ||
        !clears_rounding_error(lanes.t[i], lanes.det[i], tri_ray.sz, lanes.max_z[i], lanes.max_xt[i], lanes.max_yt[i],
                               lanes.max_e[i]))
      return std::nullopt;
    return Hit{lanes.t[i], prim, lanes.b1[i], lanes.b2[i]};
  }
  if (prim >= bvh.triangle_count) return bvh.prims->intersect_shape(prim, ray, t_range);
  const auto tri = intersect_triangle(tri_ray, t_range, run.corner(0, i), run.corner(1, i), run.corner(2, i));
  if (!tri) return std::nullopt;
  return Hit{tri->t, prim, tri->b1, tri->b2};
}

/// Asks for the memory of a stack entry to be loaded into the cache before it is needed: its
/// node or its leaf's run, and what follows it in the layout (a node's runs, a run's sibling
/// runs), which the ray mostly tests next. Trees that stay in the cache skip this.
inline void prefetch(const TraversalView& bvh, const StackEntry& e) {
  if (!bvh.prefetches) return;
  // The place a word names, without a branch: a node's, or a leaf's run.
  const uint32_t place = (e.child & BvhWideNode::kLeafFlag) != 0 ? BvhWideNode::first_of(e.child) : e.child;
  const char* p = reinterpret_cast<const char*>(bvh.layout) + size_t(place) * BvhLayout::kPlaceBytes;
  for (size_t at = 0; at < kPrefetchBytes; at += 64) __builtin_prefetch(p + at);
}

/// What a closest-hit traversal carries for one ray: the ray as the box and triangle tests take
/// it, and the nearest hit so far.
struct NearestSearch {
  const TraversalView& bvh;
  const Ray& ray;
  BoxRay box_ray;
  const WatertightRay tri_ray;
  const float t_min;
  float t_max;
  Hit* hit;
  bool found = false;

  NearestSearch(const TraversalView& tree, const Ray& query, Interval t_range, Hit* result)
      : bvh(tree), ray(query), box_ray(query, t_range), tri_ray(query), t_min(t_range.min), t_max(t_range.max),
        hit(result) {}

  /// Once something is hit, a primitive at exactly the same t may still win: the lower
  /// primitive id does, as with every accelerator.
  float reach() const { return found ? next_float(t_max, true) : t_max; }
  /// Whether a box the ray enters at `t_enter` may hold something nearer.
  bool reachable(float t_enter) const { return t_enter <= t_max * kFarScale; }

  /// Tests a leaf run's entries for hits nearer than the nearest so far, keeping the nearest
  /// and cutting the box ray's range at it. Always inlined, so that the search stays in
  /// registers.
  [[gnu::always_inline]] void test(const LeafRun& run) {
    LeafLanes lanes;
    test_leaf(bvh, tri_ray, run, {t_min, reach()}, lanes);
    for (unsigned m = lanes.hits | lanes.full_test; m != 0; m &= m - 1) {
      const auto i = uint32_t(std::countr_zero(m));
      const auto found_hit = leaf_entry_hit(bvh, ray, tri_ray, run, lanes, i, {t_min, reach()});
      if (!found_hit) continue;
      const Hit& h = *found_hit;
      if (found && (h.t > t_max || (h.t == t_max && h.prim > hit->prim))) continue;
      t_max = h.t;
      box_ray.set_t_max(h.t);
      *hit = h;
      found = true;
    }
  }
};

/// traverse_closest in a tree with shapes. Leaves are stack entries like nodes: every child is
/// visited nearest entry first, so a leaf farther than a hit found in a nearer node is never
/// tested; a shape's test costs more than a triangle's, and a large shape (a floor) sits near
/// the root. Popped entries the ray cannot reach before its current nearest hit are skipped.
inline bool traverse_closest_nearest_first(const TraversalView& bvh, const Ray& ray, Interval t_range, Hit* hit) {
  NearestSearch search(bvh, ray, t_range, hit);
  StackEntry stack[kStackSize];
  int top = 0;
  StackEntry current{0, 0};
  for (;;) {
    if ((current.child & BvhWideNode::kLeafFlag) == 0) {
      const BvhWideNode& node = bvh.node(current.child);
      std::array<float, kBvhWidth> t_enter;
      unsigned mask = hit_children(node, search.box_ray, t_enter);
      if (mask != 0) {
        const auto entry = [&](int i) { return StackEntry{node.child[size_t(i)], t_enter[size_t(i)]}; };
        current = entry(std::countr_zero(mask));
        prefetch(bvh, current);
        mask &= mask - 1;
        // Keep the nearest as `current`; the rest go on the stack sorted so that nearer
        // ones are popped first (insertion into the few entries pushed here).
        const int base = top;
        for (; mask != 0; mask &= mask - 1) {
          StackEntry e = entry(std::countr_zero(mask));
          // Start loading what the entry points to: it, or the current one it may displace,
          // is searched after the current one.
          prefetch(bvh, e);
          if (e.t_enter < current.t_enter) std::swap(e, current);
          int j = top++;
          for (; j > base && stack[j - 1].t_enter < e.t_enter; --j) stack[j] = stack[j - 1];
          stack[j] = e;
        }
        continue;
      }
    } else {
      search.test(bvh.leaf(current.child));
    }
    // Pop the next entry the ray can still reach before its nearest hit.
    do {
      if (top == 0) return search.found;
      current = stack[--top];
    } while (!search.reachable(current.t_enter));
  }
}

/// The leaf children of a node: the top bits of its child words.
inline unsigned leaf_children(const BvhWideNode& node) {
#if MJRAY_BVH_AVX
  return unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_load_si256(reinterpret_cast<const __m256i*>(node.child.data())))));
#elif defined(__SSE2__)
  const auto half = [&](size_t at) {
    return unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_load_si128(reinterpret_cast<const __m128i*>(&node.child[at])))));
  };
  return half(0) | half(4) << 4;
#else
  unsigned mask = 0;
  for (size_t i = 0; i < kBvhWidth; ++i) mask |= unsigned(node.is_leaf(i)) << i;
  return mask;
#endif
}

/// traverse_closest in a tree of triangles only, with the same hits as the nearest-first loop.
/// A node's hit leaves are tested at once, while its inner children's nodes load: their runs
/// follow the node in the layout and arrive with it, and a hit there may cull the inner
/// children before they are ordered. So the stack holds only nodes, fewer entries a node are
/// sorted, and the loop never asks whether the next entry is a leaf.
inline bool traverse_closest_leaves_first(const TraversalView& bvh, const Ray& ray, Interval t_range, Hit* hit) {
  NearestSearch search(bvh, ray, t_range, hit);
  StackEntry stack[kStackSize];
  int top = 0;
  uint32_t node_place = 0;  // the root's
  for (;;) {
    const BvhWideNode& node = bvh.node(node_place);
    std::array<float, kBvhWidth> t_enter;
    const unsigned mask = hit_children(node, search.box_ray, t_enter);
    const unsigned leaves = leaf_children(node);
    unsigned inner = mask & ~leaves;
    for (unsigned m = inner; m != 0; m &= m - 1) prefetch(bvh, {node.child[size_t(std::countr_zero(m))], 0});
    for (unsigned m = mask & leaves; m != 0; m &= m - 1) {
      const auto c = size_t(std::countr_zero(m));
      if (search.reachable(t_enter[c])) search.test(bvh.leaf(node.child[c]));
    }
    if (inner != 0) {
      // Descend into the nearest inner child; the rest go on the stack sorted so that nearer
      // ones are popped first (insertion into the few entries pushed here).
      const auto entry = [&](int i) { return StackEntry{node.child[size_t(i)], t_enter[size_t(i)]}; };
      StackEntry nearest = entry(std::countr_zero(inner));
      const int base = top;
      for (inner &= inner - 1; inner != 0; inner &= inner - 1) {
        StackEntry e = entry(std::countr_zero(inner));
        if (e.t_enter < nearest.t_enter) std::swap(e, nearest);
        int j = top++;
        for (; j > base && stack[j - 1].t_enter < e.t_enter; --j) stack[j] = stack[j - 1];
        stack[j] = e;
      }
      if (search.reachable(nearest.t_enter)) {
        node_place = nearest.child;
        continue;
      }
    }
    // Pop the next node the ray can still reach before its nearest hit.
    StackEntry next;
    do {
      if (top == 0) return search.found;
      next = stack[--top];
    } while (!search.reachable(next.t_enter));
    node_place = next.child;
  }
}

/// The nearest hit for t in `t_range`, written to *hit; returns whether there was one. The
/// loop depends on the tree: leaves first where it holds triangles only.
inline bool traverse_closest(const TraversalView& bvh, const Ray& ray, Interval t_range, Hit* hit) {
  return bvh.only_triangles ? traverse_closest_leaves_first(bvh, ray, t_range, hit)
                            : traverse_closest_nearest_first(bvh, ray, t_range, hit);
}

/// Any blocking hit for t in `t_range` (an opaque primitive, or a transmissive one `filter`
/// says blocks; with kFiltered false, any primitive): returns at the first. No child is
/// ordered by distance, and a node's leaves are tested before its inner children are
/// descended into, since a leaf may end the query at once.
template <bool kFiltered>
bool traverse_any(const TraversalView& bvh, const Ray& ray, Interval t_range, HitFilter* filter) {
  const BoxRay box_ray(ray, t_range);
  const WatertightRay tri_ray(ray);
  const float t_min = t_range.min, t_max = t_range.max;
  uint32_t stack[kStackSize];
  int top = 0;
  uint32_t node_index = 0;  // the root's place
  std::array<float, kBvhWidth> t_enter;
  for (;;) {
    const BvhWideNode& node = bvh.node(node_index);
    const unsigned mask = hit_children(node, box_ray, t_enter);
    const unsigned leaves = leaf_children(node);
    // Push the inner children and start loading their nodes, then test the leaves' primitives
    // meanwhile. One loop both pushes and loads: a loop's exit is a branch often mispredicted.
    const unsigned inner = mask & ~leaves;
    uint32_t last_pushed = 0;
    for (unsigned m = inner; m != 0; m &= m - 1) {
      last_pushed = node.child[size_t(std::countr_zero(m))];
      prefetch(bvh, {last_pushed, 0});
      stack[top++] = last_pushed;
    }
    for (unsigned m = mask & leaves; m != 0; m &= m - 1) {
      const size_t i = size_t(std::countr_zero(m));
      const LeafRun run = bvh.leaf(node.child[i]);
      LeafLanes lanes;
      test_leaf(bvh, tri_ray, run, {t_min, t_max}, lanes);
      for (unsigned entries = lanes.hits | lanes.full_test; entries != 0; entries &= entries - 1) {
        const auto k = uint32_t(std::countr_zero(entries));
        if constexpr (kFiltered)
          if (filter->ignores_transmissive && bvh.prims->transmissive(run.prim(k))) continue;
        const auto h = leaf_entry_hit(bvh, ray, tri_ray, run, lanes, k, {t_min, t_max});
        if (!h) continue;
        if constexpr (!kFiltered) return true;
        if (!bvh.prims->filtered(h->prim, filter->sees_opaque) || filter->blocks(*h)) return true;
      }
    }
    // Then descend into the last child pushed, kept in a register: reloading it from the stack
    // would put a store-to-load round trip before the next node's address.
    if (inner != 0) {
      node_index = last_pushed;
      --top;
      continue;
    }
    if (top == 0) return false;
    node_index = stack[--top];
  }
}
