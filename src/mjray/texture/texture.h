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

/// Where a solid texture reads its point: the world-space hit point (the original's rule, so
/// one texture looks the same on every object), or the point in the object's own frame (so
/// the pattern moves and turns with its object, as animations want).
enum class TextureSpace { kWorld, kObject };

/// The texture's colour at a hit: solid textures read `point` (world or object space, as the
/// material chose), image textures the surface's `uv`.
inline Color evaluate(const Texture& texture, const Point3& point, const Point2& uv) {
  return std::visit([&](const auto& t) { return t.evaluate(point, uv); }, texture);
}

}  // namespace mjray
