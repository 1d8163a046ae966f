#include "mjray/camera/pinhole_camera.h"

#include <cmath>
#include <numbers>

#include "mjray/core/error.h"

namespace mjray {

PinholeCamera::PinholeCamera(const CameraDescription& d, int width, int height)
    : eye_(d.eye), width_(float(width)), height_(float(height)) {
  if (!(length(d.view) > 0) || !is_finite(d.view)) throw SceneError("the view direction is zero");
  if (!(d.fovy_degrees > 0 && d.fovy_degrees < 180))
    throw SceneError("fovy must be between 0 and 180 degrees, got " + std::to_string(d.fovy_degrees));
  forward_ = normalize(d.view);
  // Compute up orthogonal to the view (Gram–Schmidt) and right = forward × up.
  const Vector3 up_ortho = d.up - forward_ * dot(d.up, forward_);
  if (!(length(up_ortho) > 1e-6f * length(d.up))) throw SceneError("the up vector is parallel to the view direction");
  up_ = normalize(up_ortho);
  right_ = cross(forward_, up_);
  half_height_ = float(std::tan(double(d.fovy_degrees) * std::numbers::pi / 360.0));
  half_width_ = half_height_ * width_ / height_;
}

Ray PinholeCamera::generate_ray(float x, float y) const {
  const float sx = (2 * x / width_ - 1) * half_width_;
  const float sy = (1 - 2 * y / height_) * half_height_;
  return {eye_, normalize(forward_ + right_ * sx + up_ * sy)};
}

}  // namespace mjray
