#pragma once
/// Each job's camera and image as the scene and the command line decide them together, and
/// the gr.render calls a run renders (--frames).

#include <vector>

#include "mjray/camera/camera.h"
#include "mjray/job/job_options.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// A job's image size in pixels.
struct ImageSize {
  int width = 0, height = 0;
};

/// The size job renders at: --size, else gr.render's.
ImageSize job_image_size(const RenderJob& job, const ViewOptions& view);

/// The job's camera: gr.render's, with the lens of the gr.lens before it, --aperture and
/// --focus-distance over that.
CameraDescription job_camera(const RenderJob& job, const ViewOptions& view);

/// The indices of the jobs `frames` selects (all without it), in script order. Throws
/// SceneError naming the script when the range starts or ends past the last gr.render call.
std::vector<size_t> selected_jobs(const SceneDescription& scene, const std::optional<FrameRange>& frames);

/// Checks before anything renders that each job of `jobs` has a camera that builds with the
/// options (a lens with an aperture needs a focus distance) and that the --crop window lies
/// inside its image. Throws SceneError naming the gr.render call.
void check_job_views(const SceneDescription& scene, const std::vector<size_t>& jobs, const JobOptions& options);

}  // namespace mjray
