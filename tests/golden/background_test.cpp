// Backgrounds through renders: an equirectangular environment seen directly and in a mirror
// at the directions its layout promises, one colour, a gradient, and the default kept.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "support/lua_script_test.h"
#include "support/test_job.h"

namespace mjray {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

/// The direction of texel (x, y) of a width × height equirectangular image, as the layout
/// promises: the centre column looks along −z, the right quarter along +x, the top row up.
Vector3 texel_direction(int x, int y, int width, int height) {
  const float theta = kPi * (float(y) + 0.5f) / float(height);
  const float phi = 2 * kPi * ((float(x) + 0.5f) / float(width) - 0.5f);
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

struct Marker {
  Vector3 direction;
  Color colour;
};

/// Dark grey with a coloured patch within 20° of each marker's direction.
Image marked_environment(const std::vector<Marker>& markers) {
  Image image(128, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 128; ++x) {
      image.at(x, y) = {0.1f, 0.1f, 0.1f};
      for (const Marker& m : markers)
        if (dot(texel_direction(x, y, 128, 64), normalize(m.direction)) > std::cos(20 * kPi / 180)) image.at(x, y) = m.colour;
    }
  return image;
}

const std::vector<Marker> kMarkers = {{{0, 0, 1}, {1, 0, 0}},   // behind the camera: red
                                      {{1, 0, 0}, {0, 1, 0}},   // right: green
                                      {{-1, 0, 0}, {1, 1, 0}},  // left: yellow
                                      {{0, 1, 0}, {0, 0, 1}}};  // up: blue

class Background : public test::LuaScriptTest {
 protected:
  /// Renders job `index` of `script` with one sample per pixel.
  Image render(const std::string& script, size_t index = 0) {
    scene_ = load(script);
    job_ = std::make_unique<test::TestJob>(scene_, index, test::oracle_options({4, 4, 1}));
    return job_->render();
  }

  SceneDescription scene_;
  std::unique_ptr<test::TestJob> job_;
};

/// A perfect mirror sphere of radius 1 at the origin seen from +z, before `background`.
std::string mirror_scene(const std::string& background, int size = 65) {
  return background +
         "local root = gr.node('root')\n"
         "local s = gr.sphere('mirror')\n"
         "s:set_material(gr.reflectivematerial({0, 0, 0}, {0, 0, 0}, 1, 1))\n"
         "root:add_child(s)\n"
         "gr.render(root, 'm.png', " + std::to_string(size) + ", " + std::to_string(size) +
         ", {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 30, {0, 0, 0}, {gr.light({0, 0, 10}, {0, 0, 0}, {1, 0, 0})})\n";
}

TEST_F(Background, AMirrorSphereReflectsTheEnvironmentAtTheExpectedDirections) {
  write_image(marked_environment(kMarkers), dir_ / "env.png");
  const Image image = render(mirror_scene("gr.background('env.png')\n"));
  const Camera& camera = job_->prepared().camera();
  for (const Marker& m : kMarkers) {
    // The pixel whose ray the unit sphere reflects closest to the marker's direction.
    float best = -2;
    int bx = -1, by = -1;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const Ray ray = camera.generate_ray(float(x) + 0.5f, float(y) + 0.5f);
        const Vector3 o(ray.origin.x, ray.origin.y, ray.origin.z);
        const float b = dot(o, ray.direction), c = dot(o, o) - 1;
        if (b * b - c < 0) continue;
        const Vector3 n = o + ray.direction * (-b - std::sqrt(b * b - c));
        const Vector3 reflected = ray.direction - n * (2 * dot(ray.direction, n));
        if (const float closeness = dot(normalize(reflected), m.direction); closeness > best) best = closeness, bx = x, by = y;
      }
    ASSERT_GT(best, 0.99f);
    EXPECT_EQ(image.at(bx, by), m.colour) << "at pixel " << bx << "," << by;
  }
  // Around the sphere the camera sees the environment straight ahead (−z): no marker.
  const Color grey = read_image(dir_ / "env.png").at(64, 32);  // ahead (-z): 0.1 as 8 bits hold it
  EXPECT_NEAR(grey.r, 0.1f, 0.5f / 255);
  for (const auto& [got, want] : {std::pair{image.at(0, 32).r, grey.r}, {image.at(0, 32).g, grey.g}, {image.at(0, 32).b, grey.b}})
    EXPECT_NEAR(got, want, 1e-6f);  // the film's sum over its weight may round one step
  EXPECT_EQ(image.at(32, 32), Color(1, 0, 0));
}

TEST_F(Background, CameraRaysSeeTheEnvironmentAndAnExrKeepsValuesAboveOne) {
  // Looking right (+x) from the origin, the green marker fills the view.
  Image env = marked_environment({{{1, 0, 0}, {4, 2, 0.5f}}});
  write_image(env, dir_ / "env.exr");
  const Image image = render("gr.background('env.exr')\n"
                             "local root = gr.node('root')\n"
                             "gr.render(root, 'v.png', 9, 9, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 10, {0, 0, 0},\n"
                             "          {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})\n");
  EXPECT_EQ(image.at(4, 4), Color(4, 2, 0.5f));
}

TEST_F(Background, OneColourAndAGradientAndTheDefaultKept) {
  const std::string empty = "local root = gr.node('root')\n"
                            "gr.render(root, 'b.png', 9, 9, {0, 0, 0}, {0, 1, 0.001}, {0, 0, -1}, 120, {0, 0, 0},\n"
                            "          {gr.light({0, 0, 10}, {1, 1, 1}, {1, 0, 0})})\n";
  const Image plain = render(empty);
  // The default gradient, written out, is the default exactly.
  EXPECT_EQ(render("gr.background({0.20, 0.28, 0.45}, {0.62, 0.68, 0.78})\n" + empty).pixels(), plain.pixels());
  // One colour everywhere.
  const Image one_colour = render("gr.background({0.3, 0.5, 0.7})\n" + empty);
  for (const Color& c : one_colour.pixels()) EXPECT_EQ(c, Color(0.3f, 0.5f, 0.7f));
  // Top straight up; the bottom colour from the horizon down.
  const Image gradient = render("gr.background({1, 0, 0}, {0, 0, 1})\n" + empty);
  EXPECT_NEAR(gradient.at(4, 4).r, 1, 1e-3f);
  EXPECT_NEAR(gradient.at(4, 4).b, 0, 1e-3f);
  EXPECT_GT(gradient.at(0, 4).b, gradient.at(4, 4).b);
  // gr.background() goes back to the default, for the gr.render calls after it.
  EXPECT_EQ(render("gr.background({1, 1, 1})\n" + empty + "gr.background()\n" + empty, 1).pixels(), plain.pixels());
}

}  // namespace
}  // namespace mjray
