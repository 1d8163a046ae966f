#pragma once
/// The gr.render camera: eye point, view direction, up vector, vertical field of view, and an
/// optional thin lens (gr.lens) for depth of field.

#include "mjray/core/ray.h"
#include "mjray/core/vector.h"

namespace mjray {

/// What gr.render (and gr.lens before it) says about the camera, as given (view need not be
/// unit, up need not be perpendicular to view).
struct CameraDescription {
  Point3 eye;
  Vector3 view{0, 0, -1};
  Vector3 up{0, 1, 0};
  float fovy_degrees = 50;
  float aperture_radius = 0;  ///< of the thin lens; 0 = a pinhole
  float focus_distance = 0;   ///< along the view direction to the plane in focus; used when aperture_radius > 0
};

/// A pinhole or thin-lens camera producing world-space rays through image positions.
class Camera {
 public:
  /// Throws SceneError when view is zero, up is parallel to view, fovy is not in (0, 180), or
  /// the lens is not a finite radius ≥ 0 with a finite focus distance > 0.
  Camera(const CameraDescription& description, int width, int height);

  /// Whether rays start anywhere on a lens (aperture > 0), so that each needs a lens sample.
  bool has_lens() const { return aperture_radius_ > 0; }

  /// The pinhole ray through image position (x, y) in pixels, (0,0) the top-left corner of
  /// the image; pixel (i, j) has its centre at (i + 0.5, j + 0.5). The direction is unit length.
  Ray generate_ray(float x, float y) const;

  /// The thin-lens ray through (x, y) from the lens point of (lens_u, lens_v) ∈ [0,1)²: it
  /// passes where the pinhole ray meets the plane in focus. The pinhole ray without a lens.
  Ray generate_ray(float x, float y, float lens_u, float lens_v) const;

 private:
  /// The pinhole direction through (x, y), not normalised: its forward component is 1.
  Vector3 direction_through(float x, float y) const;

  Point3 eye_;
  Vector3 forward_, right_, up_;  // orthonormal camera frame
  float half_height_ = 0;         // tan(fovy / 2) at unit distance
  float half_width_ = 0;
  float width_ = 0, height_ = 0;
  float aperture_radius_ = 0, focus_distance_ = 0;
};

}  // namespace mjray
