#pragma once
/// The closed set of textures. A material with a texture takes its diffuse colour kd from it.
///
/// To add a texture: write `<name>_texture.h/.cpp` with a struct that has
/// `Color evaluate(const Point3& object_point, const Point2& uv) const`, add it to `Texture`
/// below and its .cpp to the `mjray` library in CMakeLists.txt, bind it in
/// `lua/texture_bindings.cpp`, and test it in `tests/unit/texture/texture_test.cpp`.

#include <variant>

#include "mjray/texture/checkerboard_texture.h"
#include "mjray/texture/image_texture.h"
#include "mjray/texture/perlin_texture.h"

namespace mjray {

using Texture = std::variant<CheckerboardTexture, PerlinTexture, ImageTexture>;

/// The texture's colour at a hit. Solid textures read `object_point`, the hit in the frame
/// the primitive is written in (SurfaceInteraction::object_point), so they move with their
/// objects; image textures read the surface's `uv`.
inline Color evaluate(const Texture& texture, const Point3& object_point, const Point2& uv) {
  return std::visit([&](const auto& t) { return t.evaluate(object_point, uv); }, texture);
}

}  // namespace mjray
