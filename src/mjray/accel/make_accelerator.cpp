#include "mjray/accel/make_accelerator.h"

#include "mjray/accel/brute_force.h"
#include "mjray/accel/bvh.h"
#include "mjray/accel/uniform_grid.h"
#include "mjray/core/error.h"

#ifdef MJRAY_HAVE_EMBREE
#include "mjray/accel/embree_accelerator.h"
#endif

namespace mjray {

std::string accelerator_names() {
#ifdef MJRAY_HAVE_EMBREE
  return "none, grid, bvh, embree";
#else
  return "none, grid, bvh";
#endif
}

std::unique_ptr<Accelerator> make_accelerator(const PrimitiveSet& prims, const AcceleratorOptions& options) {
  return build_accelerator(prims, options).structure;
}

AcceleratorBuild build_accelerator(const PrimitiveSet& prims, const AcceleratorOptions& options) {
  if (options.kind == "bvh") {
    auto bvh = std::make_unique<Bvh>(prims, options.threads);
    const RegionSearch* regions = bvh.get();
    return {std::move(bvh), regions, 0, ""};
  }
  if (options.kind == "none") return {std::make_unique<BruteForce>(prims), nullptr, 0, ""};
  if (options.kind == "grid") {
    auto grid = std::make_unique<UniformGrid>(prims, options.grid_size);
    const int resolution = grid->resolution();
    std::string note = grid->resolution_note();
    return {std::move(grid), nullptr, resolution, std::move(note)};
  }
  if (options.kind == "embree") {
#ifdef MJRAY_HAVE_EMBREE
    return {std::make_unique<EmbreeAccelerator>(prims, options.threads, options.embree_exact_hits,
                                                options.embree_robust), nullptr, 0, ""};
#else
    throw SceneError("accelerator 'embree' is not available: this mjray was built without Embree "
                     "(install libembree-dev and configure with -DMJRAY_WITH_EMBREE=ON)");
#endif
  }
  throw SceneError("unknown accelerator '" + options.kind + "' (this build has: " +
                   accelerator_names() + ")");
}

}  // namespace mjray
