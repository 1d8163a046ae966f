#include "mjray/camera/camera.h"

#include <cmath>
#include <numbers>

#include "mjray/core/error.h"
#include "mjray/core/sampling.h"

namespace mjray {

namespace {

/// v divided by its largest magnitude component (or v itself when zero or not finite), so that
/// squaring it for a length neither overflows (1e30) nor underflows (1e-30).
Vector3 rescaled(const Vector3& v) {
  const float largest = max_component(abs(v));
  return largest > 0 && std::isfinite(largest) ? v / largest : v;
}

}  // namespace

Camera::Camera(const CameraDescription& d, int width, int height)
    : eye_(d.eye), width_(float(width)), height_(float(height)) {
  const Vector3 view = rescaled(d.view), up = rescaled(d.up);
  if (!(length(view) > 0) || !is_finite(view)) throw SceneError("the view direction is zero");
  if (!(d.fovy_degrees > 0 && d.fovy_degrees < 180))
    throw SceneError("fovy must be between 0 and 180 degrees, got " + std::to_string(d.fovy_degrees));
  if (!is_finite(d.eye) || !is_finite(up)) throw SceneError("the eye and up vector must be finite");
  forward_ = normalize(view);
  // Compute up orthogonal to the view (Gram–Schmidt) and right = forward × up.
  const Vector3 up_ortho = up - forward_ * dot(up, forward_);
  if (!(length(up_ortho) > 1e-6f * length(up))) throw SceneError("the up vector is parallel to the view direction");
  up_ = normalize(up_ortho);
  right_ = cross(forward_, up_);
  half_height_ = float(std::tan(double(d.fovy_degrees) * std::numbers::pi / 360.0));
  half_width_ = half_height_ * width_ / height_;
  if (!(d.aperture_radius >= 0) || !std::isfinite(d.aperture_radius))
    throw SceneError("the lens aperture radius must be a finite number of at least 0, got " + std::to_string(d.aperture_radius));
  if (d.aperture_radius > 0 && !(d.focus_distance > 0 && std::isfinite(d.focus_distance)))
    throw SceneError("the lens focus distance must be a finite number above 0, got " + std::to_string(d.focus_distance));
  aperture_radius_ = d.aperture_radius;
  focus_distance_ = d.focus_distance;
}

Vector3 Camera::direction_through(float x, float y) const {
  const float sx = (2 * x / width_ - 1) * half_width_;
  const float sy = (1 - 2 * y / height_) * half_height_;
  return forward_ + right_ * sx + up_ * sy;
}

Ray Camera::generate_ray(float x, float y) const { return {eye_, normalize(direction_through(x, y))}; }

Ray Camera::generate_ray(float x, float y, float lens_u, float lens_v) const {
  if (!has_lens()) return generate_ray(x, y);
  // The pinhole ray meets the plane in focus at focus_distance along forward (its forward
  // component is 1); every lens point's ray passes there.
  const Vector3 direction = direction_through(x, y);
  const Point2 disk = sample_concentric_disk(lens_u, lens_v);
  const Vector3 offset = (right_ * disk.u + up_ * disk.v) * aperture_radius_;
  return {eye_ + offset, normalize(direction * focus_distance_ - offset)};
}

}  // namespace mjray
