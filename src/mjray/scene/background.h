#pragma once
/// What rays that leave the scene see: a vertical gradient over the ray direction (the
/// default), one colour, or an equirectangular environment image (gr.background).

#include <memory>

#include "mjray/core/color.h"
#include "mjray/core/image.h"
#include "mjray/core/vector.h"

namespace mjray {

/// The background of one gr.render job.
struct Background {
  Color zenith{0.20f, 0.28f, 0.45f};   ///< straight up
  Color horizon{0.62f, 0.68f, 0.78f};  ///< level and below
  /// When set, the environment over every direction, latitude-longitude: the image's centre
  /// is seen looking along −z, its right quarter along +x, its top row straight up (+y).
  std::shared_ptr<const Image> environment;

  /// The radiance arriving along `direction` (any length but 0) from the background.
  Color radiance(const Vector3& direction) const;
};

/// Where the unit `direction` falls in an equirectangular image, in [0,1)² (u to the right,
/// v down): u = 1/2 + atan2(x, −z)/2π, v = acos(y)/π.
Point2 equirectangular_uv(const Vector3& direction);

}  // namespace mjray
