#pragma once
/// The gr.render camera: eye point, view direction, up vector, vertical field of view.

#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// What gr.render says about the camera, as given (view need not be unit, up need not be
/// perpendicular to view).
struct CameraDescription {
  Point3 eye;
  Vector3 view{0, 0, -1};
  Vector3 up{0, 1, 0};
  float fovy_degrees = 50;
};

/// A pinhole camera producing world-space rays through image positions.
class PinholeCamera {
 public:
  /// Throws SceneError when view is zero, up is parallel to view, or fovy is not in (0, 180).
  PinholeCamera(const CameraDescription& description, int width, int height);

  /// The ray through image position (x, y) in pixels, (0,0) the top-left corner of the image;
  /// pixel (i, j) has its centre at (i + 0.5, j + 0.5). The direction is unit length.
  Ray generate_ray(float x, float y) const;

 private:
  Point3 eye_;
  Vector3 forward_, right_, up_;  // orthonormal camera frame
  float half_height_ = 0;         // tan(fovy / 2) at unit distance
  float half_width_ = 0;
  float width_ = 0, height_ = 0;
};

}  // namespace mjray
