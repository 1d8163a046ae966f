// The texture calls as load_scene sees them: what they attach to materials, and the exact
// text (with scene.lua:LINE) of every error.

#include <fstream>
#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "mjray/io/image_codec.h"
#include "mjray/lua/scene_loader.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

const std::string kRender =
    "gr.render(root, 'out.png', 4, 3, {0,0,10}, {0,0,-1}, {0,1,0}, 50, {0.1,0.1,0.1}, "
    "{gr.light({0,0,10}, {1,1,1}, {1,0,0})})\n";

class LuaTextureTest : public test::ScratchFolderTest {
 protected:

  SceneDescription load(const std::string& script) { return load_scene(write("scene.lua", script), {}); }

  std::string error_of(const std::string& script) {
    try {
      load(script);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "(no error)";
  }

  /// "<dir>/scene.lua:LINE: ", the prefix of an error raised on that line.
  std::string at(int line) const { return (dir_ / "scene.lua").string() + ":" + std::to_string(line) + ": "; }

  /// The texture on the material of the job's root node.
  static const Texture* texture_of(const SceneDescription& scene) {
    const auto& material = scene.jobs.at(0).root->material;
    return material ? phong_of(*material).texture.get() : nullptr;
  }

};

// --- what the calls make ---------------------------------------------------------------------

using LuaTexture = LuaTextureTest;

TEST_F(LuaTexture, CheckerboardOnAPhongMaterial) {
  const auto scene = load(
      "root = gr.sphere('s')\n"
      "m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
      "m:set_material_texture(gr.checkerboardtexture({0.9, 0.9, 0.9}, {0.1, 0.2, 0.3}, 2))\n"
      "root:set_material(m)\n" +
      kRender);
  const Texture* t = texture_of(scene);
  ASSERT_NE(t, nullptr);
  const auto* board = std::get_if<CheckerboardTexture>(t);
  ASSERT_NE(board, nullptr);
  EXPECT_EQ(board->colour1, Color(0.9f, 0.9f, 0.9f));
  EXPECT_EQ(board->colour2, Color(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(board->scale, 2);
}

TEST_F(LuaTexture, SolidTexturesReadWorldSpaceUnlessObjectIsAsked) {
  const std::string texture = "t = gr.checkerboardtexture({1, 1, 1}, {0, 0, 0}, 1)\n";
  for (const auto& [call, space] : {std::pair{"m:set_material_texture(t)", TextureSpace::kWorld},
                                    std::pair{"m:set_material_texture(t, 'world')", TextureSpace::kWorld},
                                    std::pair{"m:set_material_texture(t, 'object')", TextureSpace::kObject}}) {
    const auto scene = load("root = gr.sphere('s')\nm = gr.reflectivematerial({1, 1, 1}, {0, 0, 0}, 1, 0.5)\n" + texture +
                            call + "\nroot:set_material(m)\n" + kRender);
    EXPECT_EQ(phong_of(*scene.jobs.at(0).root->material).texture_space, space) << call;
  }
}

TEST_F(LuaTexture, EveryPerlinCallMakesItsPattern) {
  const std::pair<const char*, PerlinPattern> calls[] = {
      {"perlinnoiselininterptexture", PerlinPattern::kLinear},
      {"perlinnoisecosineinterptexture", PerlinPattern::kCosine},
      {"perlinnoisemarbletexture", PerlinPattern::kMarble},
      {"perlinnoisewavytexture", PerlinPattern::kWavy},
      {"perlinnoisewoodgraintexture", PerlinPattern::kWoodGrain}};
  for (const auto& [name, pattern] : calls) {
    const auto scene = load(
        "root = gr.cube('c')\n"
        "m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
        "m:set_material_texture(gr." + std::string(name) + "({1, 0, 0}, {0, 0, 1}, 0.5, 3, 'extra'))\n"
        "root:set_material(m)\n" +
        kRender);
    const auto* perlin = std::get_if<PerlinTexture>(texture_of(scene));
    ASSERT_NE(perlin, nullptr) << name;
    EXPECT_EQ(perlin->pattern, pattern) << name;
    EXPECT_EQ(perlin->colour1, Color(1, 0, 0)) << name;
    EXPECT_EQ(perlin->colour2, Color(0, 0, 1)) << name;
    EXPECT_EQ(perlin->scale, 0.5f) << name;
    EXPECT_EQ(perlin->noise_multiplier, pattern == PerlinPattern::kWavy ? 3.f : 1.f) << name;
  }
}

TEST_F(LuaTexture, SetMaterialTextureReachesTheBaseOfEveryMaterialKind) {
  const char* makers[] = {"gr.material({1,1,1}, {0,0,0}, 1)",
                          "gr.reflectivematerial({1,1,1}, {0,0,0}, 1, 0.5)",
                          "gr.refractedmaterial({1,1,1}, {0,0,0}, 1, 1, 1.5)",
                          "gr.reflectrefractmaterial({1,1,1}, {0,0,0}, 1, 0.3, 1, 1.5)",
                          "gr.fresneldiectricmaterial({1,1,1}, {0,0,0}, 1, 1, 1.5)",
                          "gr.glossyreflectivematerial({1,1,1}, {0,0,0}, 1, 0.5, 4)"};
  for (const char* maker : makers) {
    const auto scene = load(
        "root = gr.sphere('s')\n"
        "root:set_material(" + std::string(maker) + ")\n"
        "m = " + maker + "\n"
        "root:set_material(m)\n"
        "m:set_material_texture(gr.perlinnoisemarbletexture({1,1,1}, {0,0,0}, 2.5))\n" +
        kRender);
    const Texture* t = texture_of(scene);
    ASSERT_NE(t, nullptr) << maker;
    EXPECT_TRUE(std::holds_alternative<PerlinTexture>(*t)) << maker;
  }
}

TEST_F(LuaTexture, FileTextureLoadsAPngBesideTheScript) {
  Image image(2, 1);
  image.at(0, 0) = {1, 0, 0};
  image.at(1, 0) = {0, 0, 1};
  fs::create_directories(dir_ / "Assets");
  write_image(image, dir_ / "Assets" / "stripes.png");
  const auto scene = load(
      "root = gr.cube('c')\n"
      "m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
      "m:set_material_texture(gr.filetexture('stripes.png'))\n"
      "root:set_material(m)\n" +
      kRender);
  const auto* file = std::get_if<ImageTexture>(texture_of(scene));
  ASSERT_NE(file, nullptr);
  EXPECT_EQ(file->image.width(), 2);
  EXPECT_EQ(file->evaluate({}, {0.25f, 0.5f}), Color(1, 0, 0));
  EXPECT_EQ(file->evaluate({}, {0.75f, 0.5f}), Color(0, 0, 1));
}

// --- errors ----------------------------------------------------------------------------------

using LuaTextureErrors = LuaTextureTest;

TEST_F(LuaTextureErrors, BadColours) {
  EXPECT_EQ(error_of("\nt = gr.checkerboardtexture({1, 0}, {0, 0, 0}, 2)\n"),
            at(2) + "gr.checkerboardtexture: argument 1 (colour1) must be a table of 3 numbers, got a table of 2 values");
  EXPECT_EQ(error_of("t = gr.perlinnoisemarbletexture({1, 0, 0}, 'blue', 2)\n"),
            at(1) + "gr.perlinnoisemarbletexture: argument 2 (colour2) must be a table of 3 numbers, got the string 'blue'");
  EXPECT_EQ(error_of("t = gr.perlinnoiselininterptexture()\n"),
            at(1) + "gr.perlinnoiselininterptexture: argument 1 (colour1) must be a table of 3 numbers, got nothing");
}

TEST_F(LuaTextureErrors, BadScale) {
  EXPECT_EQ(error_of("t = gr.checkerboardtexture({1, 1, 1}, {0, 0, 0})\n"),
            at(1) + "gr.checkerboardtexture: argument 3 (scale) must be a number, got nothing");
  EXPECT_EQ(error_of("\n\nt = gr.perlinnoisewoodgraintexture({1, 1, 1}, {0, 0, 0}, 0)\n"),
            at(3) + "gr.perlinnoisewoodgraintexture: argument 3 (scale) must be a positive number, got the number 0");
  EXPECT_EQ(error_of("t = gr.perlinnoisecosineinterptexture({1, 1, 1}, {0, 0, 0}, -2)\n"),
            at(1) + "gr.perlinnoisecosineinterptexture: argument 3 (scale) must be a positive number, got the number -2");
  EXPECT_EQ(error_of("t = gr.perlinnoisemarbletexture({1, 1, 1}, {0, 0, 0}, {})\n"),
            at(1) + "gr.perlinnoisemarbletexture: argument 3 (scale) must be a number, got an empty table");
}

TEST_F(LuaTextureErrors, WavyNeedsItsNoiseMultiplier) {
  EXPECT_EQ(error_of("t = gr.perlinnoisewavytexture({1, 1, 1}, {0, 0, 0}, 2)\n"),
            at(1) + "gr.perlinnoisewavytexture: argument 4 (noise_multiplier) must be a number, got nothing");
  EXPECT_EQ(error_of("t = gr.perlinnoisewavytexture({1, 1, 1}, {0, 0, 0}, 2, 1/0)\n"),
            at(1) + "gr.perlinnoisewavytexture: argument 4 (noise_multiplier) must be a finite number, got the number inf");
}

TEST_F(LuaTextureErrors, FileTextureNameMissingOrNotAString) {
  EXPECT_EQ(error_of("t = gr.filetexture()\n"),
            at(1) + "gr.filetexture: argument 1 (file name) must be a string, got nothing");
  EXPECT_EQ(error_of("t = gr.filetexture({})\n"),
            at(1) + "gr.filetexture: argument 1 (file name) must be a string, got an empty table");
  EXPECT_EQ(error_of("t = gr.filetexture('')\n"),
            at(1) + "gr.filetexture: argument 1 (file name) must be a file name, got an empty string");
}

TEST_F(LuaTextureErrors, MissingImageFileNamesTheFileAndTheLine) {
  EXPECT_EQ(error_of("root = gr.node('root')\n\nt = gr.filetexture('missing_texture.png')\n"),
            at(3) + "gr.filetexture: cannot find 'missing_texture.png' (looked in the scene's folder, its parent "
                    "folders, their Assets/ folders and the working directory)");
}

TEST_F(LuaTextureErrors, UndecodableImageIsAClearError) {
  const fs::path bad = write("notes.png", "this is not an image\n");
  EXPECT_EQ(error_of("t = gr.filetexture('notes.png')\n"),
            at(1) + "gr.filetexture: cannot read '" + bad.string() + "': not a PNG, JPEG, OpenEXR or binary (P6) PPM file");
  // A PNG signature followed by garbage.
  const fs::path cut = write("cut.png", std::string("\x89PNG\r\n\x1a\n", 8) + "garbage");
  const std::string message = error_of("\nt = gr.filetexture('cut.png')\n");
  EXPECT_EQ(message.rfind(at(2) + "gr.filetexture: cannot read '" + cut.string() + "': ", 0), 0u) << message;
}

TEST_F(LuaTextureErrors, SetMaterialTextureArguments) {
  EXPECT_EQ(error_of("m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\nm:set_material_texture({})\n"),
            at(2) + "material:set_material_texture: argument 1 (texture) must be a texture (gr.checkerboardtexture, "
                    "gr.perlinnoise...texture or gr.filetexture), got an empty table");
  EXPECT_EQ(error_of("m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\nm:set_material_texture(m)\n"),
            at(2) + "material:set_material_texture: argument 1 (texture) must be a texture (gr.checkerboardtexture, "
                    "gr.perlinnoise...texture or gr.filetexture), got a gr.material");
  EXPECT_EQ(error_of("m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
                     "t = gr.checkerboardtexture({1, 1, 1}, {0, 0, 0}, 1)\n"
                     "m.set_material_texture(t)\n"),
            at(3) + "material:set_material_texture: must be called on a material (with ':'), got a gr.texture");
  EXPECT_EQ(error_of("m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
                     "m:set_material_texture(gr.checkerboardtexture({1, 1, 1}, {0, 0, 0}, 1), 'model')\n"),
            at(2) + "material:set_material_texture: argument 2 (texture space) must be 'world' or 'object', got the string 'model'");
}

TEST_F(LuaTextureErrors, TextureIsNotAMaterial) {
  EXPECT_EQ(error_of("s = gr.sphere('s')\ns:set_material(gr.checkerboardtexture({1, 1, 1}, {0, 0, 0}, 1))\n"),
            at(2) + "node:set_material: argument 1 (material) must be a material, got a gr.texture");
}

}  // namespace
}  // namespace mjray
