// Degenerate numbers and shapes: NaN and infinity anywhere, values beyond float range, zero or
// negative sizes, a zero or parallel camera frame, fovy out of (0, 180), zero-area triangles,
// tiny spheres. Each is a clear error naming the call and line, or renders with every pixel
// finite.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "mjray/camera/camera.h"
#include "mjray/integrator/whitted_integrator.h"
#include "mjray/lua/scene_loader.h"
#include "mjray/render/image_render.h"
#include "mjray/scene/flatten.h"
#include "support/test_job.h"
#include "support/lua_script_test.h"

namespace mjray {
namespace {

std::string render_call(const std::string& camera = "{0,0,10}, {0,0,-1}, {0,1,0}, 50") {
  return "gr.render(root, 'out.png', 8, 6, " + camera +
         ", {0.1,0.1,0.1}, {gr.light({0,4,10}, {1,1,1}, {1,0,0})})\n";
}

/// Renders every job of the scene (all accelerators agree on finiteness) and counts the
/// pixels that are not finite.
int non_finite_pixels(const SceneDescription& scene, int max_depth = 8) {
  int bad = 0;
  for (const RenderJob& job : scene.jobs) {
    for (const char* kind : {"bvh", "grid", "none"}) {
      JobOptions options = test::oracle_options({max_depth, max_depth, 2});
      options.accel.kind = kind;
      const Image image = test::render(job, options);
      for (const Color& c : image.pixels())
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) ++bad;
    }
  }
  return bad;
}

class HardeningDegenerate : public test::LuaScriptTest {};

TEST_F(HardeningDegenerate, NanAndInfinityAreRefusedInEveryKindOfArgument) {
  const std::string root = "root = gr.node('root')\n";
  EXPECT_EQ(error_of(root + "root:translate(0/0, 0, 0)\n"),
            at(2) + "node:translate: argument 1 (x) must be a finite number, got the number nan");
  EXPECT_EQ(error_of(root + "root:scale(1, 1/0, 1)\n"),
            at(2) + "node:scale: argument 2 (y) must be a finite number, got the number inf");
  EXPECT_EQ(error_of(root + "root:rotate('x', -1/0)\n"),
            at(2) + "node:rotate: argument 2 (angle) must be a finite number, got the number -inf");
  EXPECT_EQ(error_of("s = gr.nh_sphere('s', {0, 0/0, 0}, 1)\n"),
            at(1) + "gr.nh_sphere: argument 2 (centre) must be a table of 3 numbers, got a table whose entry 2 is "
                    "not finite");
  EXPECT_EQ(error_of("m = gr.material({1, 1, 1/0}, {0, 0, 0}, 10)\n"),
            at(1) + "gr.material: argument 1 (kd) must be a table of 3 numbers, got a table whose entry 3 is not "
                    "finite");
  EXPECT_EQ(error_of("l = gr.light({0, 0, 0}, {1, 1, 1}, {1, 0/0, 0})\n"),
            at(1) + "gr.light: argument 3 (falloff) must be a table of 3 numbers, got a table whose entry 2 is not "
                    "finite");
  EXPECT_EQ(error_of(root + render_call("{0,0,1/0}, {0,0,-1}, {0,1,0}, 50")),
            at(2) + "gr.render: argument 5 (eye) must be a table of 3 numbers, got a table whose entry 3 is not "
                    "finite");
  EXPECT_EQ(error_of(root + render_call("{0,0,10}, {0,0,-1}, {0,1,0}, 0/0")),
            at(2) + "gr.render: argument 8 (fovy) must be a finite number, got the number nan");
}

TEST_F(HardeningDegenerate, NumbersBeyondFloatRangeAreRefused) {
  EXPECT_EQ(error_of("root = gr.node('root')\nroot:translate(1e39, 0, 0)\n"),
            at(2) + "node:translate: argument 1 (x) must be a number of magnitude at most 3.4e38, got the number 1e+39");
  EXPECT_EQ(error_of("l = gr.light({-1e300, 0, 0}, {1, 1, 1}, {1, 0, 0})\n"),
            at(1) + "gr.light: argument 1 (position) must be a table of 3 numbers, got a table whose entry 1 is "
                    "beyond 3.4e38");
}

TEST_F(HardeningDegenerate, ZeroAndNegativeSizesAreErrors) {
  EXPECT_EQ(error_of("s = gr.nh_sphere('s', {0, 0, 0}, 0)\n"),
            at(1) + "gr.nh_sphere: argument 3 (radius) must be a positive number, got the number 0");
  EXPECT_EQ(error_of("s = gr.nh_sphere('s', {0, 0, 0}, -2)\n"),
            at(1) + "gr.nh_sphere: argument 3 (radius) must be a positive number, got the number -2");
  EXPECT_EQ(error_of("s = gr.nh_sphere('s', {0, 0, 0}, 1e-50)\n"),  // rounds to a float 0
            at(1) + "gr.nh_sphere: argument 3 (radius) must be a positive number, got the number 1e-50");
  EXPECT_EQ(error_of("b = gr.nh_box('b', {0, 0, 0}, 0)\n"),
            at(1) + "gr.nh_box: argument 3 (size) must be a positive number, got the number 0");
  EXPECT_EQ(error_of("b = gr.nh_box('b', {0, 0, 0}, -1)\n"),
            at(1) + "gr.nh_box: argument 3 (size) must be a positive number, got the number -1");
  EXPECT_EQ(error_of("root = gr.node('root')\nroot:scale(1, 0, 1)\n"),
            at(2) + "node:scale: a scale factor of 0 flattens the node to nothing");
  EXPECT_EQ(error_of("root = gr.node('root')\nroot:scale(1, 1e-50, 1)\n"),
            at(2) + "node:scale: a scale factor of 0 flattens the node to nothing");
}

TEST_F(HardeningDegenerate, BadCameraFramesAreErrorsAtTheRenderLine) {
  const std::string root = "root = gr.node('root')\n";
  EXPECT_EQ(error_of(root + render_call("{0,0,10}, {0,0,0}, {0,1,0}, 50")), at(2) + "gr.render: the view direction is zero");
  EXPECT_EQ(error_of(root + render_call("{0,0,10}, {0,2,0}, {0,1,0}, 50")),
            at(2) + "gr.render: the up vector is parallel to the view direction");
  EXPECT_EQ(error_of(root + render_call("{0,0,10}, {0,0,-1}, {0,0,0}, 50")),
            at(2) + "gr.render: the up vector is parallel to the view direction");
  for (const char* fovy : {"0", "180", "-30", "500"})
    EXPECT_EQ(error_of(root + render_call(std::string("{0,0,10}, {0,0,-1}, {0,1,0}, ") + fovy)),
              at(2) + "gr.render: fovy must be between 0 and 180 degrees, got " + fovy);
}

TEST_F(HardeningDegenerate, HugeAndTinyCameraVectorsWorkLikeUnitOnes) {
  const std::string scene = "root = gr.node('root')\ns = gr.sphere('s')\nroot:add_child(s)\n"
                            "s:set_material(gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 20))\n";
  const auto unit = load(scene + render_call("{0,0,10}, {0,0,-1}, {0,1,0}, 50"));
  const auto huge = load(scene + render_call("{0,0,10}, {0,0,-1e38}, {0,3e38,0}, 50"));
  const auto tiny = load(scene + render_call("{0,0,10}, {0,0,-1e-30}, {0,1e-30,0}, 50"));
  EXPECT_EQ(non_finite_pixels(huge), 0);
  const auto image_of = [](const SceneDescription& s) { return test::TestJob(s, 0, JobOptions{}).render().pixels(); };
  EXPECT_EQ(image_of(huge), image_of(unit));
  EXPECT_EQ(image_of(tiny), image_of(unit));
}

TEST_F(HardeningDegenerate, ZeroAreaTrianglesAndTinySpheresRenderFinitePixels) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "m = gr.reflectivematerial({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 20, 0.5)\n"
      "flat = gr.mesh('flat', {{-2,-2,0}, {2,2,0}, {0,0,0}, {-2,2,0}, {-2,2,0}}, {{0,1,2}, {3,4,4}, {0,0,0}, {0,1,3}})\n"
      "flat:set_material(m)\nroot:add_child(flat)\n"
      "tiny = gr.nh_sphere('tiny', {0, 0, 1}, 1e-30)\ntiny:set_material(m)\nroot:add_child(tiny)\n"
      "glass = gr.fresneldiectricmaterial({0.1, 0.1, 0.1}, {0.5, 0.5, 0.5}, 50, 1, 1.5)\n"
      "big = gr.nh_sphere('big', {0, 0, -3}, 1e30)\nbig:set_material(glass)\nroot:add_child(big)\n"
      "far = gr.nh_box('far', {1e30, 1e30, 1e30}, 1)\nfar:set_material(m)\nroot:add_child(far)\n"
      "root:rotate('z', 1e30)\n" + render_call());
  EXPECT_EQ(non_finite_pixels(scene), 0);
}

TEST_F(HardeningDegenerate, LightsWithZeroOrNegativeFalloffAddNothingInsteadOfInfinity) {
  const auto scene = load(
      "root = gr.node('root')\ns = gr.nh_sphere('s', {0, 0, 0}, 1)\nroot:add_child(s)\n"
      "s:set_material(gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 20))\n"
      "gr.render(root, 'out.png', 8, 6, {0,0,10}, {0,0,-1}, {0,1,0}, 50, {0.1,0.1,0.1},\n"
      "  {gr.light({0,0,1}, {1,1,1}, {0,0,0}), gr.light({0,4,4}, {1,1,1}, {-1,0,0}),\n"
      "   gr.arealight({0,4,4}, {1,1,1}, {0,0,0}, {1,4,4}, {0,5,4})})\n");
  EXPECT_EQ(non_finite_pixels(scene), 0);
}

TEST_F(HardeningDegenerate, TransformsThatOverflowWhenComposedAreErrorsNamingTheNode) {
  const auto scene = load("root = gr.node('root')\nlocal n = root\n"
                          "for i = 1, 4 do local c = gr.node('c' .. i) c:scale(1e30, 1e30, 1e30) n:add_child(c) n = c end\n"
                          "s = gr.sphere('s')\nn:add_child(s)\n" + render_call());
  try {
    flatten(scene.jobs[0]);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), at(4) + "'s' is scaled or moved so far (its transforms composed down the "
                                             "scene graph) that its geometry leaves float range");
  }
}

TEST_F(HardeningDegenerate, DeepestReflectionAndRefractionDepthsDoNotOverflowTheStack) {
  // Two facing mirrors with a clear slab between: every bounce crosses the slab twice, so a
  // ray nests about 1500 traces at -r 1000 -f 1000, on worker threads.
  const auto scene = load(
      "root = gr.node('root')\n"
      "mirror = gr.reflectivematerial({0, 0, 0}, {0, 0, 0}, 10, 1)\n"
      "clear = gr.refractedmaterial({0, 0, 0}, {0, 0, 0}, 10, 1, 1)\n"
      "a = gr.nh_box('a', {-50, -50, -101}, 100)\na:set_material(mirror)\nroot:add_child(a)\n"
      "b = gr.nh_box('b', {-50, -50, 5}, 100)\nb:set_material(mirror)\nroot:add_child(b)\n"
      "slab = gr.nh_box('slab', {-50, -50, 0}, 100)\nslab:scale(1, 1, 0.001)\nslab:set_material(clear)\n"
      "root:add_child(slab)\n"
      "gr.render(root, 'out.png', 2, 2, {0,0,1}, {0,0,-1}, {0,1,0}, 1, {0.1,0.1,0.1}, {gr.light({0,0,1}, {1,1,1}, {1,0,0})})\n");
  JobOptions options;
  options.integrator = {1000, 1000, 1};
  options.render.threads = 2;
  RenderStats stats;
  const Image image = test::TestJob(scene, 0, options).render(&stats);
  EXPECT_GT(stats.rays.secondary, 4u * 1000u);
  for (const Color& c : image.pixels()) EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
}

}  // namespace
}  // namespace mjray
