// Image textures on a cube read the right way round: every face shows the image upright and
// unmirrored from outside (side faces with +y up, the top and bottom as a folded cross net).

#include <string>

#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

/// An 8×8 image, one colour per quadrant, so one look tells up from down and left from right
/// (big enough that filtering leaves the middle of each quadrant pure).
const Color kTopLeft{1, 0, 0}, kTopRight{0, 1, 0}, kBottomLeft{0, 0, 1}, kBottomRight{1, 1, 1};

Image quadrants() {
  Image image(8, 8);  // row 0 is the top row
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) image.at(x, y) = y < 4 ? (x < 4 ? kTopLeft : kTopRight) : (x < 4 ? kBottomLeft : kBottomRight);
  return image;
}

/// The unit cube [0,1]^3 seen straight on from `eye` (looking at the centre), `up` upwards.
Image view_of_textured_cube(Point3 eye, Vector3 up) {
  PhongMaterial material{{1, 1, 1}, {0, 0, 0}, 1};
  material.texture = std::make_shared<const Texture>(ImageTexture{quadrants()});
  RenderJob job;
  job.root = test::box({0, 0, 0}, {1, 1, 1}, material);
  job.width = job.height = 32;
  job.camera = {eye, Point3(0.5f, 0.5f, 0.5f) - eye, up, 20};
  job.ambient = {1, 1, 1};
  job.lights = {PointLight{eye, {0, 0, 0}, {1, 0, 0}}};  // ambient alone: the texture's own colours
  return test::render(job);
}

/// The colour's name, for readable failures.
std::string name(const Color& c) {
  if (c == kTopLeft) return "red (top left)";
  if (c == kTopRight) return "green (top right)";
  if (c == kBottomLeft) return "blue (bottom left)";
  if (c == kBottomRight) return "white (bottom right)";
  std::string text = "(";
  text.append(std::to_string(c.r)).append(", ").append(std::to_string(c.g)).append(", ");
  return text.append(std::to_string(c.b)).append(")");
}

void expect_upright_and_unmirrored(const Image& image, const std::string& face) {
  EXPECT_EQ(name(image.at(9, 9)), name(kTopLeft)) << face;
  EXPECT_EQ(name(image.at(22, 9)), name(kTopRight)) << face;
  EXPECT_EQ(name(image.at(9, 22)), name(kBottomLeft)) << face;
  EXPECT_EQ(name(image.at(22, 22)), name(kBottomRight)) << face;
}

TEST(GoldenTextures, EverySideOfACubeShowsItsImageUprightAndUnmirrored) {
  expect_upright_and_unmirrored(view_of_textured_cube({0.5f, 0.5f, 4}, {0, 1, 0}), "+z (front)");
  expect_upright_and_unmirrored(view_of_textured_cube({0.5f, 0.5f, -3}, {0, 1, 0}), "-z (back)");
  expect_upright_and_unmirrored(view_of_textured_cube({4, 0.5f, 0.5f}, {0, 1, 0}), "+x (right)");
  expect_upright_and_unmirrored(view_of_textured_cube({-3, 0.5f, 0.5f}, {0, 1, 0}), "-x (left)");
}

TEST(GoldenTextures, TopAndBottomOfACubeReadAsTheFoldedNetAroundTheFront) {
  // The top's upper edge is at the back (−z): upright to a viewer above, facing −z.
  expect_upright_and_unmirrored(view_of_textured_cube({0.5f, 4, 0.5f}, {0, 0, -1}), "+y (top)");
  // The bottom's upper edge is at the front (+z): upright to a viewer below whose head points to +z.
  expect_upright_and_unmirrored(view_of_textured_cube({0.5f, -3, 0.5f}, {0, 0, 1}), "-y (bottom)");
}

}  // namespace
}  // namespace mjray
