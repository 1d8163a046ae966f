#pragma once
/// One gr.render job made ready to render: the flat world, its accelerator, the camera and
/// the integrator, built from the scene description and the job options.

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "mjray/accel/accelerator.h"
#include "mjray/accel/make_accelerator.h"
#include "mjray/camera/camera.h"
#include "mjray/integrator/indirect_light.h"
#include "mjray/integrator/integrator.h"
#include "mjray/integrator/photon/photon_maps.h"
#include "mjray/job/job_options.h"
#include "mjray/job/job_camera.h"
#include "mjray/scene/scene_description.h"
#include "mjray/scene/world.h"

namespace mjray {

/// Owns everything a render of one job reads; not movable (the parts refer to each other).
class PreparedJob {
 public:
  PreparedJob(const SceneDescription& scene, size_t index, const JobOptions& options);
  PreparedJob(const PreparedJob&) = delete;
  PreparedJob& operator=(const PreparedJob&) = delete;

  const RenderJob& description() const { return job_; }
  /// The image size: --size, else gr.render's (a crop renders a window of it).
  int width() const { return size_.width; }
  int height() const { return size_.height; }
  const std::filesystem::path& output() const { return output_; }
  const World& world() const { return world_; }
  const Accelerator& accelerator() const { return *accel_.structure; }
  /// Voxels per axis of --accel grid; 0 for other accelerators.
  int grid_resolution() const { return accel_.grid_resolution; }
  const Camera& camera() const { return camera_; }
  const Integrator& integrator() const { return *integrator_; }
  /// flatten's warnings ("file:line: text"), then the accelerator's (a grid smaller than asked).
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// Seconds spent flattening and building the accelerator.
  double build_seconds() const { return build_seconds_; }
  /// The photon maps' statistics, or nothing without --caustics and --gi.
  const PhotonStatistics* photon_statistics() const { return photons_ ? &photons_->statistics() : nullptr; }

 private:
  const RenderJob& job_;
  ImageSize size_;
  std::filesystem::path output_;
  std::vector<std::string> warnings_;
  std::chrono::steady_clock::time_point build_start_ = std::chrono::steady_clock::now();
  World world_;
  AcceleratorBuild accel_;
  Camera camera_;
  std::unique_ptr<PhotonMaps> photons_;
  std::unique_ptr<IndirectLight> indirect_;
  std::unique_ptr<Integrator> integrator_;
  double build_seconds_ = 0;
};

}  // namespace mjray
