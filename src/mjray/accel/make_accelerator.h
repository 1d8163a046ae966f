#pragma once
/// Chooses and builds the accelerator the user asked for.

#include <memory>
#include <string>

#include "mjray/accel/accelerator.h"
#include "mjray/accel/region_search.h"
#include "mjray/geometry/primitive_set.h"

namespace mjray {

/// Which structure to build and how.
struct AcceleratorOptions {
  std::string kind = "bvh";  ///< "none", "grid", "bvh" or "embree"
  int grid_size = 0;         ///< voxels per axis for "grid"; 0 with kind "grid" = optimal
  int threads = 0;           ///< build threads, 0 = all cores
  bool embree_exact_hits = true;  ///< "embree": refine hits with mjray's triangle test (see EmbreeAccelerator)
  bool embree_robust = true;      ///< "embree": the robust scene flag (see EmbreeAccelerator)
};

/// The names --accel accepts in this build.
std::string accelerator_names();

/// Builds the accelerator over `prims` (which must outlive it). Throws SceneError for an
/// unknown or unavailable kind.
std::unique_ptr<Accelerator> make_accelerator(const PrimitiveSet& prims, const AcceleratorOptions& options);

/// An accelerator as built for a render, with what its building decided that the user is told.
struct AcceleratorBuild {
  std::unique_ptr<Accelerator> structure;
  /// The structure's region search, where it has one (the BVH's); null for the others.
  const RegionSearch* regions = nullptr;
  int grid_resolution = 0;  ///< voxels per axis of a grid (0 for the others)
  std::string note;         ///< e.g. why a grid is smaller than asked; empty when nothing to say
};

/// make_accelerator, with what the build decided.
AcceleratorBuild build_accelerator(const PrimitiveSet& prims, const AcceleratorOptions& options);

}  // namespace mjray
