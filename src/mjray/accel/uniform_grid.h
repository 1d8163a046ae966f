#pragma once
/// Uniform spatial subdivision (the original project's -g/-o): N×N×N voxels over the scene
/// box, each listing the primitives that overlap it, traversed by Amanatides–Woo 3-D DDA.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mjray/accel/accelerator.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// The "optimal" voxels per axis for `primitive_count` primitives: 3·∛N (Pharr 2004), at least 1.
int optimal_grid_resolution(size_t primitive_count);

/// A uniform grid whose voxel lists are stored compactly (CSR: one begin offset per voxel into
/// one flat array of primitive ids). Triangles are listed only in the voxels they overlap;
/// spheres and cubes in every voxel of their world AABB.
class UniformGrid final : public Accelerator {
 public:
  /// Builds `resolution`³ voxels over `prims` (which must outlive the grid); 0 = optimal,
  /// negative = 1. The resolution is capped (256) and halved while the primitive references
  /// would exceed a memory budget, so huge -g values or huge shapes cannot exhaust memory.
  UniformGrid(const PrimitiveSet& prims, int resolution);

  std::optional<Hit> intersect(const Ray& ray, Interval t_range) const override;
  bool occluded(const Ray& ray, float t_max) const override;
  bool occluded(const Ray& ray, Interval t_range, HitFilter& filter) const override;
  Bounds3 bounds() const override { return bounds_; }
  std::string_view name() const override { return "grid"; }
  size_t memory_bytes() const override;

  /// Voxels per axis actually built.
  int resolution() const { return resolution_; }
  /// Why the grid has fewer voxels per axis than asked for; empty when it has them all.
  std::string resolution_note() const;
  /// The box the voxels tile: the scene bounds, padded (empty for an empty world).
  Bounds3 grid_bounds() const { return prims_.empty() ? Bounds3{} : Bounds3{grid_lo_, grid_hi_}; }
  /// Primitive references over all voxels (a primitive counts once per voxel it is in).
  size_t reference_count() const { return prims_.size(); }

 private:
  /// The closest hit (filter null, kAnyHit false), any hit, or a blocking hit (with filter).
  template <bool kAnyHit>
  std::optional<Hit> traverse(const Ray& ray, Interval t_range, HitFilter* filter = nullptr) const;

  const PrimitiveSet& primitives_;
  uint32_t triangle_count_ = 0;
  Bounds3 bounds_;                      ///< of all primitives, unpadded
  Point3 grid_lo_;                      ///< padded grid box corner
  Point3 grid_hi_;
  Vector3 voxel_size_;
  Vector3 inv_voxel_size_;
  int resolution_ = 1;
  int requested_resolution_ = 1;        ///< as asked for (0 resolved to the optimal size)
  uint64_t reference_budget_ = 0;       ///< references beyond this halve the resolution
  std::vector<uint32_t> voxel_begin_;   ///< voxel v lists prims_[voxel_begin_[v], voxel_begin_[v+1])
  std::vector<uint32_t> prims_;
  std::vector<uint64_t> occupied_;      ///< one bit per voxel: skips empty voxels in cache
  std::vector<std::array<std::array<float, 3>, 3>> corners_;  ///< per triangle, world space
  std::vector<uint32_t> unbounded_;     ///< primitives with non-finite bounds, tested by every ray
};

}  // namespace mjray
