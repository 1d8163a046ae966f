#include "mjray/accel/make_accelerator.h"

#include "mjray/accel/brute_force.h"
#include "mjray/core/error.h"

namespace mjray {

std::string accelerator_names() { return "none"; }

std::unique_ptr<Accelerator> make_accelerator(const World& world, const AcceleratorOptions& options) {
  if (options.kind == "none" || options.kind == "bvh") return std::make_unique<BruteForce>(world);
  throw SceneError("unknown accelerator '" + options.kind + "' (this build has: " +
                   accelerator_names() + ")");
}

}  // namespace mjray
