#include "mjray/job/run_plan.h"

#include "mjray/io/atomic_file.h"
#include "mjray/io/video_encoder.h"
#include "mjray/job/job_outputs.h"
#include "mjray/job/job_camera.h"

namespace mjray {

namespace {

/// The indices of the jobs `frames` selects (all without it), in script order. Throws
/// SceneError naming the script when the range starts or ends past the last gr.render call.
std::vector<size_t> selected_jobs(const SceneDescription& scene, const std::optional<FrameRange>& frames) {
  const int count = int(scene.jobs.size());
  std::vector<size_t> jobs;
  if (!frames) {
    for (int i = 0; i < count; ++i) jobs.push_back(size_t(i));
    return jobs;
  }
  const int last = frames->last.value_or(count);
  if (frames->first > count || last > count)
    throw SceneError(scene.script.string() + ": --frames " + std::to_string(frames->first) + "-" + std::to_string(last) +
                     " asks for gr.render calls the scene does not make: it makes " + std::to_string(count));
  for (int frame = frames->first; frame <= last; frame += frames->step) jobs.push_back(size_t(frame - 1));
  return jobs;
}

/// --video: the frames' files share a format and a size, and ffmpeg can write the video.
void check_video(const SceneDescription& scene, const std::vector<size_t>& jobs, const RunOptions& options) {
  const std::filesystem::path& video = *options.report.video;
  std::vector<std::filesystem::path> files;
  std::vector<std::string> sizes;
  for (const size_t i : jobs) {
    files.push_back(output_path(scene, i, options.job.outputs));
    const ImageSize size = job_image_size(scene.jobs[i], options.job.view);
    const auto& crop = options.job.render.crop;
    sizes.push_back(crop ? std::to_string(crop->x1 - crop->x0) + "x" + std::to_string(crop->y1 - crop->y0)
                         : std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  check_not_an_input(scene, video, {options.scene.string(), 0}, "--video");
  check_video_output(video, files, sizes);
}

}  // namespace

RunPlan plan_run(const SceneDescription& scene, const RunOptions& options) {
  if (options.report.resume && !scene.reads_clock.empty())
    throw SceneError(scene.script.string() + ": --resume: the script reads the clock (" + scene.reads_clock +
                     "), so the scene it describes may differ from the one the interrupted run rendered; render "
                     "without --resume");
  RunPlan plan{selected_jobs(scene, options.job.frames), JobFingerprints(scene, options.job), scene.warnings, scene.notes};
  check_job_cameras(scene, plan.jobs, options.job);
  for (std::string& w : check_outputs(scene, options.job.outputs, plan.jobs)) plan.warnings.push_back(std::move(w));
  if (options.report.video) check_video(scene, plan.jobs, options);
  if (const auto& json = options.report.stats_json) {
    check_not_an_input(scene, *json, {scene.script.string(), 0}, "--stats-json");
    create_folder_of(*json);
    check_writable_place(*json);
  }
  return plan;
}

}  // namespace mjray
