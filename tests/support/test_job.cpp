#include "support/test_job.h"

namespace mjray::test {

JobOptions oracle_options(IntegratorSettings integrator) {
  JobOptions o;
  o.accel.kind = "none";
  o.accel.threads = 1;
  o.integrator = integrator;
  o.render.threads = 1;
  return o;
}

SceneDescription single_job_scene(RenderJob job) {
  SceneDescription scene;
  scene.script = "test.lua";
  if (job.output.empty()) job.output = "test.png";
  scene.jobs.push_back(std::move(job));
  return scene;
}

TestJob::TestJob(RenderJob job, JobOptions options) : TestJob(single_job_scene(std::move(job)), 0, std::move(options)) {}

TestJob::TestJob(SceneDescription scene, size_t index, JobOptions options)
    : scene_(std::move(scene)), options_(std::move(options)),
      prepared_(std::make_unique<PreparedJob>(scene_, index, options_)) {}

Image TestJob::render(RenderStats* stats) const {
  return render_image(prepared_->camera(), prepared_->width(), prepared_->height(), prepared_->integrator(),
                      options_.render, stats);
}

Color TestJob::radiance(const Ray& ray, RayCounters* counters, uint64_t sample) const {
  RandomStream random(0, 0, sample);
  TraceState state;
  state.camera_sample = uint32_t(sample);
  const Color c = prepared_->integrator().radiance(ray, random, state);
  if (counters) *counters = state.rays;
  return c;
}

Image render(RenderJob job, JobOptions options) { return TestJob(std::move(job), std::move(options)).render(); }

}  // namespace mjray::test
