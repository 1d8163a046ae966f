// gr.mesh(name, 'file.obj') with the file's own materials: each usemtl group its MTL
// material, glass from illum and Ni, textures beside the MTL, Lua's material first, and a
// warning naming file and line for whatever is missing, all within the sandbox.

#include <cmath>

#include <gtest/gtest.h>

#include "mjray/io/image_codec.h"
#include "support/lua_script_test.h"
#include "support/test_job.h"

namespace mjray {
namespace {

/// A square in the plane z = 0, its left half (x < 0) one material and its right half another.
constexpr const char* kTwoHalves =
    "mtllib halves.mtl\n"
    "v -1 -1 0\nv 0 -1 0\nv 0 1 0\nv -1 1 0\nv 1 -1 0\nv 1 1 0\n"
    "usemtl left\nf 1 2 3 4\n"
    "usemtl right\nf 2 5 6 3\n";

class LuaObjMaterials : public test::LuaScriptTest {
 protected:
  /// A scene drawing `mesh_file` (after `extra`, with `node` the mesh) facing the camera.
  SceneDescription scene(const std::string& mesh_file, const std::string& extra = "") {
    return load("root = gr.node('root')\nnode = gr.mesh('halves', '" + mesh_file + "')\n" + extra +
                "root:add_child(node)\n"
                "gr.render(root, 'out.png', 2, 1, {0,0,3}, {0,0,-1}, {0,1,0}, 20, {0,0,0}, "
                "{gr.light({0,0,3}, {1,1,1}, {1,0,0})})\n");
  }
  const SceneNode& node_of(const SceneDescription& d) { return *d.jobs.at(0).root->children.at(0); }
};

TEST_F(LuaObjMaterials, EachUsemtlGroupRendersInItsMtlMaterial) {
  write("halves.obj", kTwoHalves);
  write("halves.mtl", "newmtl left\nKd 0.8 0.1 0.1\nnewmtl right\nKd 0.1 0.7 0.2\nKs 0.3 0.3 0.3\nNs 40\n");
  const SceneDescription d = scene("halves.obj");
  const SceneNode& node = node_of(d);
  ASSERT_EQ(node.mesh_parts.size(), 2u);
  const auto& right = std::get<PhongMaterial>(*node.mesh_parts[1].material);
  EXPECT_EQ(right.kd, Color(0.1f, 0.7f, 0.2f));
  EXPECT_EQ(right.ks, Color(0.3f, 0.3f, 0.3f));
  EXPECT_EQ(right.shininess, 40);
  EXPECT_TRUE(d.warnings.empty()) << d.warnings.at(0);
  // Rendered under a light at the eye: each pixel kd·cos θ of its own half, plus the right
  // half's highlight ks·(r·v)^40 with r·v = 2cos²θ − 1 (both pixels see their half at one θ).
  const Image image = test::TestJob(d, 0, test::oracle_options()).render();
  const float c = image.at(0, 0).r / 0.8f;
  EXPECT_GT(c, 0.95f);
  EXPECT_NEAR(image.at(0, 0).g, 0.1f * c, 1e-5f);
  EXPECT_NEAR(image.at(0, 0).b, 0.1f * c, 1e-5f);
  const float highlight = 0.3f * std::pow(2 * c * c - 1, 40.f);
  EXPECT_NEAR(image.at(1, 0).r, 0.1f * c + highlight, 1e-4f);
  EXPECT_NEAR(image.at(1, 0).g, 0.7f * c + highlight, 1e-4f);
  EXPECT_NEAR(image.at(1, 0).b, 0.2f * c + highlight, 1e-4f);
}

TEST_F(LuaObjMaterials, GlassComesFromIllumOrDissolveWithNiAndTheSceneMaterialWins) {
  write("halves.obj", kTwoHalves);
  write("halves.mtl", "newmtl left\nKd 0.6 0.6 0.6\nillum 4\nNi 1.33\nnewmtl right\nd 0.5\nNi 1.0\n");
  const SceneDescription glass = scene("halves.obj");
  const SceneNode& node = node_of(glass);
  write("mirror.mtl", "newmtl left\nKd 0.1 0.1 0.1\nKs 0.6 0.7 0.8\nillum 3\nnewmtl right\nKs 0.5 0.5 0.5\nillum 2\n");
  write("mirror.obj", std::string("mtllib mirror.mtl\n") + (kTwoHalves + 18));
  const SceneDescription mirror = scene("mirror.obj");
  const SceneNode& mirrors = node_of(mirror);
  EXPECT_FLOAT_EQ(std::get<ReflectiveMaterial>(*mirrors.mesh_parts.at(0).material).reflectivity, 0.7f);
  EXPECT_TRUE(std::holds_alternative<PhongMaterial>(*mirrors.mesh_parts.at(1).material));  // illum 2: no mirror
  ASSERT_EQ(node.mesh_parts.size(), 2u);
  const auto& water = std::get<FresnelMaterial>(*node.mesh_parts[0].material);
  EXPECT_EQ(water.eta_inside, 1.33f);
  EXPECT_EQ(water.base.kd, Color(0, 0, 0));  // clear: no diffuse part
  EXPECT_EQ(std::get<FresnelMaterial>(*node.mesh_parts[1].material).eta_inside, 1.5f);  // Ni 1: a default

  const SceneDescription own_scene = scene("halves.obj", "node:set_material(gr.material({0.2,0.2,0.2}, {0,0,0}, 1))\n");
  const SceneNode& own = node_of(own_scene);
  EXPECT_TRUE(own.mesh_parts.empty());
  EXPECT_EQ(std::get<PhongMaterial>(*own.material).kd, Color(0.2f, 0.2f, 0.2f));
}

TEST_F(LuaObjMaterials, ATextureIsFoundBesideItsMtlFile) {
  std::filesystem::create_directories(dir_ / "model/maps");
  write("model/halves.obj", std::string("mtllib materials/halves.mtl\n") + (kTwoHalves + 18));
  write("model/materials/halves.mtl", "newmtl left\nmap_Kd ../maps/red.png\nnewmtl right\nKd 0 0 1\n");
  Image red(2, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) red.at(x, y) = {1, 0, 0};
  std::filesystem::create_directories(dir_ / "model/maps");
  write_image(red, dir_ / "model/maps/red.png");
  const SceneDescription d = scene("model/halves.obj");
  const auto& left = std::get<PhongMaterial>(*node_of(d).mesh_parts.at(0).material);  // d outlives it
  ASSERT_NE(left.texture, nullptr);
  EXPECT_TRUE(std::holds_alternative<ImageTexture>(*left.texture));
  EXPECT_TRUE(d.warnings.empty()) << d.warnings.at(0);
}

TEST_F(LuaObjMaterials, WhatIsMissingOrOutsideIsWarnedOfWithItsFileAndLineAndRendersGrey) {
  write("halves.obj", kTwoHalves);
  SceneDescription d = scene("halves.obj");
  ASSERT_EQ(d.warnings.size(), 1u);  // and not once more for each name it would have held
  EXPECT_EQ(d.warnings[0], at(2) + (dir_ / "halves.obj").string() + ":1: cannot find the material file 'halves.mtl'");  // the gr.mesh line
  test::TestJob job(d, 0, test::oracle_options());
  EXPECT_EQ(job.world().materials.size(), 1u);  // the default grey, for both halves

  write("halves.mtl", "newmtl left\nKd 1 0 0\nKe 5 5 5\n");
  d = scene("halves.obj");
  std::string all;
  for (const std::string& w : d.warnings) all += w + "\n";
  EXPECT_NE(all.find((dir_ / "halves.obj").string() + ":10: usemtl 'right' is in none of its material files"),
            std::string::npos) << all;
  EXPECT_NE(all.find((dir_ / "halves.mtl").string() + ":1: 'left' glows (Ke), which mjray does not show yet"),
            std::string::npos) << all;

  // A malformed value stops the load, naming the gr.mesh call and the .mtl line.
  write("halves.mtl", "newmtl left\nKd 0.5 red 0.2\n");
  EXPECT_EQ(error_of("root = gr.node('root')\nnode = gr.mesh('halves', 'halves.obj')\nroot:add_child(node)\n"
                     "gr.render(root, 'out.png', 2, 1, {0,0,3}, {0,0,-1}, {0,1,0}, 20, {0,0,0}, "
                     "{gr.light({0,0,3}, {1,1,1}, {1,0,0})})\n"),
            at(2) + "gr.mesh: " + (dir_ / "halves.mtl").string() + ":2: 'Kd' needs a number, found 'red'");
  write("halves.mtl", "newmtl left\nKd 1 0 0\n");

  // Names from the files reach the terminal escaped.
  write("evil.obj", "mtllib halves.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl \x1b]2;owned\x07\nf 1 2 3\n");
  d = scene("evil.obj");
  ASSERT_FALSE(d.warnings.empty());
  for (const std::string& w : d.warnings) {
    EXPECT_EQ(w.find('\x1b'), std::string::npos) << w;
    EXPECT_EQ(w.find('\x07'), std::string::npos) << w;
  }

  // A material file outside the scene's reach is not read, and nothing of it is told.
  write("outside.obj", std::string("mtllib /etc/passwd\n") + (kTwoHalves + 18));
  d = scene("outside.obj");
  ASSERT_FALSE(d.warnings.empty());
  EXPECT_NE(d.warnings[0].find(":1: the material file '/etc/passwd' is outside what the scene may read"),
            std::string::npos) << d.warnings[0];
  for (const std::string& w : d.warnings) EXPECT_EQ(w.find("root:"), std::string::npos) << w;
}

}  // namespace
}  // namespace mjray
