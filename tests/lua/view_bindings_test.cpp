// gr.lens, gr.background and -D as load_scene sees them: what each gr.render records, and the
// exact text (with scene.lua:LINE) of every error.

#include <string>

#include <gtest/gtest.h>

#include "mjray/io/image_codec.h"
#include "support/lua_script_test.h"

namespace mjray {
namespace {

const std::string kRender =
    "gr.render(gr.node('root'), 'out.png', 4, 3, {0,0,10}, {0,0,-1}, {0,1,0}, 50, {0.1,0.1,0.1}, "
    "{gr.light({0,0,10}, {1,1,1}, {1,0,0})})\n";

class LuaView : public test::LuaScriptTest {};

TEST_F(LuaView, TheLensAppliesToTheRendersAfterIt) {
  const SceneDescription scene = load(kRender + "gr.lens(0.25, 7.5)\n" + kRender + "gr.lens(0)\n" + kRender);
  ASSERT_EQ(scene.jobs.size(), 3u);
  EXPECT_EQ(scene.jobs[0].camera.aperture_radius, 0);
  EXPECT_EQ(scene.jobs[1].camera.aperture_radius, 0.25f);
  EXPECT_EQ(scene.jobs[1].camera.focus_distance, 7.5f);
  EXPECT_EQ(scene.jobs[2].camera.aperture_radius, 0);
}

TEST_F(LuaView, LensMistakesNameTheLine) {
  EXPECT_EQ(error_of("gr.lens(-1, 5)\n" + kRender),
            at(1) + "gr.lens: argument 1 (aperture radius) must be a number of at least 0, got the number -1");
  EXPECT_EQ(error_of("\ngr.lens(0.1)\n" + kRender),
            at(2) + "gr.lens: argument 2 (focus distance) must be a number, got nothing");
  EXPECT_EQ(error_of("gr.lens(0.1, 0)\n" + kRender),
            at(1) + "gr.lens: argument 2 (focus distance) must be a positive distance, got the number 0");
  EXPECT_EQ(error_of("gr.lens('wide', 3)\n" + kRender),
            at(1) + "gr.lens: argument 1 (aperture radius) must be a number, got the string 'wide'");
}

TEST_F(LuaView, BackgroundsApplyToTheRendersAfterThem) {
  write_image(Image(8, 4), dir_ / "sky.png");
  const SceneDescription scene = load(kRender + "gr.background({0.1, 0.2, 0.3})\n" + kRender +
                                      "gr.background({1, 1, 1}, {0, 0, 0})\n" + kRender + "gr.background('sky.png')\n" +
                                      kRender + "gr.background()\n" + kRender);
  ASSERT_EQ(scene.jobs.size(), 5u);
  const Background fallback;
  EXPECT_EQ(scene.jobs[0].background.zenith, fallback.zenith);
  EXPECT_EQ(scene.jobs[0].background.horizon, fallback.horizon);
  EXPECT_EQ(scene.jobs[1].background.zenith, Color(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(scene.jobs[1].background.horizon, Color(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(scene.jobs[2].background.zenith, Color(1, 1, 1));
  EXPECT_EQ(scene.jobs[2].background.horizon, Color(0, 0, 0));
  ASSERT_NE(scene.jobs[3].background.environment, nullptr);
  EXPECT_EQ(scene.jobs[3].background.environment->width(), 8);
  EXPECT_EQ(scene.jobs[4].background.environment, nullptr);
  // The environment is an input: no output may replace it, and a resume sees it change.
  ASSERT_EQ(scene.inputs.size(), 1u);
  EXPECT_EQ(scene.inputs[0].filename(), "sky.png");
}

TEST_F(LuaView, BackgroundMistakesNameTheLine) {
  EXPECT_EQ(error_of("gr.background(3)\n" + kRender),
            at(1) + "gr.background: argument 1 (background) must be a colour {r, g, b}, two colours (top, bottom) or "
                    "an image file name, got the number 3");
  EXPECT_NE(error_of("gr.background('nowhere.exr')\n" + kRender).find(at(1) + "gr.background: cannot find 'nowhere.exr'"),
            std::string::npos);
  write("broken.png", "not an image");
  EXPECT_EQ(error_of("gr.background('broken.png')\n" + kRender),
            at(1) + "gr.background: cannot read '" + (dir_ / "broken.png").string() +
                "': not a PNG, JPEG, OpenEXR or binary (P6) PPM file");
  EXPECT_EQ(error_of("gr.background({1, 0, 0}, 'x')\n" + kRender).rfind(at(1) + "gr.background: argument 2 (bottom colour)", 0), 0u);
}

TEST_F(LuaView, DefinesAreNumbersWhenLuaReadsThemAsOneElseStrings) {
  SceneLoadOptions options;
  options.defines = {{"frame", "7"}, {"clock", "0.5"}, {"big", "1e3"}, {"hex", "0x10"}, {"word", "7 frames"}, {"empty", ""}};
  const SceneDescription scene = load("assert(math.type(frame) == 'integer' and frame == 7)\n"
                                      "assert(math.type(clock) == 'float' and clock == 0.5)\n"
                                      "assert(big == 1000 and hex == 16)\n"
                                      "assert(word == '7 frames' and empty == '')\n" + kRender,
                                      options);
  EXPECT_EQ(scene.defines, options.defines);
  options.defines = {{"math", "1"}};
  EXPECT_EQ(error_of(kRender, options), (dir_ / "scene.lua").string() +
                                            ": -D math=1 would replace the global 'math' that mjray or Lua defines (a "
                                            "table); choose another name");
}

}  // namespace
}  // namespace mjray
