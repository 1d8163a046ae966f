#include "mjray/job/prepared_job.h"

#include "mjray/core/seconds_since.h"
#include "mjray/integrator/photon/photon_light.h"
#include "mjray/integrator/whitted_integrator.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/job_camera.h"
#include "mjray/render/tile_render.h"
#include "mjray/scene/flatten.h"

namespace mjray {

PreparedJob::PreparedJob(const SceneDescription& scene, size_t index, const JobOptions& options)
    : job_(scene.jobs.at(index)),
      size_(job_image_size(job_, options.view)),
      output_(output_path(scene, index, options.outputs)),
      world_(flatten(job_, &warnings_)),
      accel_(build_accelerator(world_.primitives, options.accel)),
      camera_(job_camera(job_, options.view), size_.width, size_.height) {
  if (!accel_.note.empty()) warnings_.push_back(accel_.note);
  build_seconds_ = seconds_since(build_start_);
  IntegratorSettings settings = options.integrator;
  const PhotonSettings& photons = options.photons;
  if (photons.enabled()) {
    photons_ = std::make_unique<PhotonMaps>(world_, *accel_.structure, photons, options.render.seed,
                                            resolve_thread_count(options.render.threads));
    indirect_ = std::make_unique<PhotonMappedLight>(world_, *accel_.structure, *photons_, photons);
  }
  // The caustic map brings the light through glass; global illumination computes what the
  // ambient term stands for.
  if (photons.caustics()) settings.transmissive_shadows = false;
  if (photons.global_illumination()) world_.ambient = {};
  integrator_ = std::make_unique<WhittedIntegrator>(world_, *accel_.structure, settings, indirect_.get(), accel_.regions);
}

}  // namespace mjray
