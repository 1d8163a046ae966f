#include "mjray/job/job_camera.h"

#include <cstdio>

#include "mjray/core/error.h"

namespace mjray {

namespace {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string size_text(const ImageSize& size) { return std::to_string(size.width) + "x" + std::to_string(size.height); }

std::string crop_text(const PixelRect& r) {
  return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," + std::to_string(r.y1);
}

}  // namespace

ImageSize job_image_size(const RenderJob& job, const ViewOverrides& view) {
  if (view.width && view.height) return {*view.width, *view.height};
  return {job.width, job.height};
}

CameraDescription job_camera(const RenderJob& job, const ViewOverrides& view) {
  CameraDescription camera = job.camera;
  if (view.aperture_radius) camera.aperture_radius = *view.aperture_radius;
  if (view.focus_distance) camera.focus_distance = *view.focus_distance;
  return camera;
}

void check_job_cameras(const SceneDescription& scene, const std::vector<size_t>& jobs, const JobOptions& options) {
  for (const size_t index : jobs) {
    const RenderJob& job = scene.jobs[index];
    const ImageSize size = job_image_size(job, options.view);
    const CameraDescription camera = job_camera(job, options.view);
    if (camera.aperture_radius > 0 && !(camera.focus_distance > 0))
      throw SceneError(job.where, "the lens has an aperture (radius " + number_text(camera.aperture_radius) +
                                      ") but no focus distance: give --focus-distance D, or gr.lens(radius, D) before this gr.render");
    try {
      Camera(camera, size.width, size.height);
    } catch (const SceneError& e) {
      throw SceneError(job.where, std::string("gr.render: ") + e.what());
    }
    if (const auto& crop = options.render.crop; crop && (crop->x1 > size.width || crop->y1 > size.height))
      throw SceneError(job.where, "--crop " + crop_text(*crop) + " reaches outside this gr.render's " + size_text(size) +
                                      " image (the window must lie within 0,0," + std::to_string(size.width) + "," +
                                      std::to_string(size.height) + ")");
  }
}

}  // namespace mjray
