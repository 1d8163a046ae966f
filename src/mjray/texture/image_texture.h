#pragma once
/// gr.filetexture: an image mapped by the surface's (u, v).

#include "mjray/core/color.h"
#include "mjray/core/image.h"
#include "mjray/core/vector.h"

namespace mjray {

/// An image over the unit square of (u, v), repeated beyond it, read with bilinear
/// filtering. v = 0 is the image's bottom row and v = 1 its top (the OBJ convention); texel
/// (i, j), j counted from the top, has its centre at ((i + ½)/w, 1 − (j + ½)/h). Colours are
/// the file's values as stored (8-bit value / 255, no gamma decoding), like gr.material's.
struct ImageTexture {
  Image image;

  /// The filtered colour at (u, v) (the object point is unused); black for an empty image.
  Color evaluate(const Point3& object_point, const Point2& uv) const;
};

}  // namespace mjray
