#pragma once
/// Scenes built in C++ or Lua, rendered through the same job library as the program.

#include <memory>

#include "mjray/integrator/integrator.h"
#include "mjray/job/job_options.h"
#include "mjray/job/prepared_job.h"
#include "mjray/render/image_render.h"
#include "mjray/scene/scene_description.h"

namespace mjray::test {

/// Brute force on one thread: the oracle renderer.
JobOptions oracle_options(IntegratorSettings integrator = {});

/// A scene description holding one C++-built job (its script named "test.lua").
SceneDescription single_job_scene(RenderJob job);

/// One job of a scene, prepared (flattened, accelerated, camera, integrator) by PreparedJob.
class TestJob {
 public:
  explicit TestJob(RenderJob job, JobOptions options = oracle_options());
  TestJob(SceneDescription scene, size_t index, JobOptions options);

  const PreparedJob& prepared() const { return *prepared_; }
  const World& world() const { return prepared_->world(); }
  const JobOptions& options() const { return options_; }
  /// The whole image, rendered with options().render.
  Image render(RenderStats* stats = nullptr) const;
  /// The colour along one ray, drawing from the stream of pixel 0, sample `sample`.
  Color radiance(const Ray& ray, RayCounters* counters = nullptr, uint64_t sample = 0) const;

 private:
  SceneDescription scene_;
  JobOptions options_;
  std::unique_ptr<PreparedJob> prepared_;
};

/// Renders a C++-built job with `options` (brute force by default).
Image render(RenderJob job, JobOptions options = oracle_options());

}  // namespace mjray::test
