// gr.spotlight and gr.sunlight: what they build, their defaults, and their argument errors
// with scene.lua:LINE.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "support/lua_script_test.h"

namespace mjray {
namespace {

constexpr float kDegree = std::numbers::pi_v<float> / 180;

class LuaLights : public test::LuaScriptTest {
 protected:
  /// The first light of a scene whose light list is `lights`.
  Light light_of(const std::string& lights) {
    const auto d = load("root = gr.node('root')\ngr.render(root, 'out.png', 4, 3, {0,0,10}, {0,0,-1}, {0,1,0}, 50, "
                        "{0.1,0.1,0.1}, {" + lights + "})\n");
    return d.jobs.at(0).lights.at(0);
  }
};

TEST_F(LuaLights, SpotlightKeepsItsArgumentsWithAUnitDirectionAndAnglesInRadians) {
  const auto spot = std::get<SpotLight>(light_of("gr.spotlight({1,2,3}, {0,-2,0}, {0.5,0.6,0.7}, {1,0.1,0.01}, 30, 5)"));
  EXPECT_EQ(spot.position, Point3(1, 2, 3));
  EXPECT_EQ(spot.direction, Vector3(0, -1, 0));
  EXPECT_EQ(spot.colour, Color(0.5f, 0.6f, 0.7f));
  EXPECT_EQ(spot.falloff[2], 0.01f);
  EXPECT_FLOAT_EQ(spot.cone, 30 * kDegree);
  EXPECT_FLOAT_EQ(spot.penumbra, 5 * kDegree);
  EXPECT_EQ(std::get<SpotLight>(light_of("gr.spotlight({0,0,0}, {0,0,-1}, {1,1,1}, {1,0,0}, 10)")).penumbra, 0);
}

TEST_F(LuaLights, SunlightKeepsItsDirectionAndColourAndSpansTheRealSunUnlessTold) {
  const auto sun = std::get<SunLight>(light_of("gr.sunlight({3,-4,0}, {1,0.9,0.8}, 2)"));
  EXPECT_NEAR(sun.direction.x, 0.6f, 1e-7f);
  EXPECT_NEAR(sun.direction.y, -0.8f, 1e-7f);
  EXPECT_EQ(sun.colour, Color(1, 0.9f, 0.8f));
  EXPECT_FLOAT_EQ(sun.half_angle, 1 * kDegree);
  EXPECT_FLOAT_EQ(std::get<SunLight>(light_of("gr.sunlight({0,-1,0}, {1,1,1})")).half_angle, 0.265f * kDegree);
  EXPECT_EQ(std::get<SunLight>(light_of("gr.sunlight({0,-1,0}, {1,1,1}, 0)")).half_angle, 0);
}

TEST_F(LuaLights, WrongArgumentsNameTheCallAndLine) {
  EXPECT_EQ(error_of("\nl = gr.spotlight({0,0,0}, {0,0,0}, {1,1,1}, {1,0,0}, 30)\n"),
            at(2) + "gr.spotlight: argument 2 (direction) must be a direction, not {0, 0, 0}");
  EXPECT_EQ(error_of("l = gr.spotlight({0,0,0}, {0,0,-1}, {1,1,1}, {1,0,0})\n"),
            at(1) + "gr.spotlight: argument 5 (cone_degrees) must be a number, got nothing");
  EXPECT_EQ(error_of("l = gr.spotlight({0,0,0}, {0,0,-1}, {1,1,1}, {1,0,0}, 0)\n"),
            at(1) + "gr.spotlight: argument 5 (cone_degrees) must be more than 0 and at most 180 degrees, got the number 0");
  EXPECT_EQ(error_of("l = gr.spotlight({0,0,0}, {0,0,-1}, {1,1,1}, {1,0,0}, 170, 20)\n"),
            at(1) + "gr.spotlight: the cone (170°) and its penumbra (20°) together reach past 180°");
  EXPECT_EQ(error_of("l = gr.sunlight({0,-1,0}, {1,1,1}, 30)\n"),
            at(1) + "gr.sunlight: argument 3 (angular_diameter_degrees) must be from 0 to 20 degrees, got the number 30");
  EXPECT_EQ(error_of("l = gr.sunlight({0,-1,0})\n"), at(1) + "gr.sunlight: argument 2 (colour) must be a table of 3 numbers, got nothing");
}

}  // namespace
}  // namespace mjray
