#pragma once
/// Each job's camera and image size, as the scene and the command line decide them together.

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
ImageSize job_image_size(const RenderJob& job, const ViewOverrides& view);

/// The job's camera: gr.render's, with the lens of the gr.lens before it, --aperture and
/// --focus-distance over that.
CameraDescription job_camera(const RenderJob& job, const ViewOverrides& view);

/// Checks before anything renders that each job of `jobs` has a camera that builds with the
/// options (a lens with an aperture needs a focus distance) and that the --crop window lies
/// inside its image. Throws SceneError naming the gr.render call.
void check_job_cameras(const SceneDescription& scene, const std::vector<size_t>& jobs, const JobOptions& options);

}  // namespace mjray
