// The gr.* scene API as load_scene sees it: tiny scripts in a temp folder, asserting the
// SceneDescription they produce and the exact text (with scene.lua:LINE) of every error.

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/io/file_hash.h"
#include "mjray/lua/scene_loader.h"
#include "support/lua_script_test.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

// One light and a fixed camera; scripts end with `<root>:render(...)` through this.
std::string render_call(const std::string& root = "root", const std::string& output = "'out.png'") {
  return "gr.render(" + root + ", " + output +
         ", 4, 3, {0,0,10}, {0,0,-1}, {0,1,0}, 50, {0.1,0.1,0.1}, "
         "{gr.light({0,0,10}, {1,1,1}, {1,0,0})})\n";
}

// "[a b c d; ...]" with every digit a double carries, so exact comparisons print readably.
std::string text(const Matrix4& m) {
  std::string out = "[";
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.17g", m.m[size_t(i)][size_t(j)] + 0.0);
      out += buffer;
      out += j < 3 ? " " : (i < 3 ? "; " : "]");
    }
  }
  return out;
}

std::string text(const Point3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.9g %.9g %.9g)", p.x, p.y, p.z);
  return buffer;
}

std::string triangles_of(const TriangleMesh& mesh) {
  std::string out;
  for (const auto& t : mesh.triangles) {
    if (!out.empty()) out += ' ';
    out += std::to_string(t[0].position) + "," + std::to_string(t[1].position) + "," +
           std::to_string(t[2].position);
  }
  return out;
}

using LuaTest = test::LuaScriptTest;

// --- core calls --------------------------------------------------------------------------

using LuaScene = LuaTest;

TEST_F(LuaScene, SnapshotsFreezeMaterialsAsTheyWereAtEachRender) {
  // An animation may retexture a material between frames; earlier frames keep what they had.
  const SceneDescription d = load(
      "root = gr.node('root')\n"
      "m = gr.material({1,0,0}, {0,0,0}, 1)\n"
      "a = gr.sphere('a'); a:set_material(m); root:add_child(a)\n"
      "b = gr.sphere('b'); b:set_material(m); root:add_child(b)\n" +
      render_call() + "m:set_material_texture(gr.checkerboardtexture({0,0,0}, {1,1,1}, 1))\n" + render_call());
  ASSERT_EQ(d.jobs.size(), 2u);
  const auto& first = d.jobs[0].root->children;
  const auto& second = d.jobs[1].root->children;
  EXPECT_EQ(phong_of(*first[0]->material).texture, nullptr);
  EXPECT_NE(phong_of(*second[0]->material).texture, nullptr);
  EXPECT_EQ(first[0]->material, first[1]->material);  // still one material within a frame
}

TEST_F(LuaScene, NodeIsAnEmptyGroupWithIdentityTransform) {
  const auto scene = load("root = gr.node('root')\n" + render_call());
  ASSERT_EQ(scene.jobs.size(), 1u);
  const SceneNode& root = *scene.jobs[0].root;
  EXPECT_EQ(root.name, "root");
  EXPECT_FALSE(root.shape || root.mesh);
  EXPECT_TRUE(root.parent_from_node.is_identity());
  EXPECT_TRUE(root.children.empty());
  EXPECT_EQ(root.material, nullptr);
  EXPECT_EQ(root.where.to_string(), (dir_ / "scene.lua").string() + ":1");
}

TEST_F(LuaScene, JointIsAPlainGroup) {
  const auto scene = load(
      "root = gr.joint('elbow', {-90, 0, 90}, {-10, 5, 10})\n"
      "root:add_child(gr.sphere('s'))\n" +
      render_call());
  const SceneNode& root = *scene.jobs[0].root;
  EXPECT_EQ(root.name, "elbow");
  EXPECT_FALSE(root.shape || root.mesh);
  EXPECT_TRUE(root.parent_from_node.is_identity());
  ASSERT_EQ(root.children.size(), 1u);
  EXPECT_TRUE(root.children[0]->shape && std::holds_alternative<UnitSphere>(*root.children[0]->shape));
}

TEST_F(LuaScene, SphereAndCubeAreUnitPrimitives) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "root:add_child(gr.sphere('ball'))\n"
      "root:add_child(gr.cube('box'))\n" +
      render_call());
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 2u);
  EXPECT_EQ(children[0]->name, "ball");
  EXPECT_TRUE(children[0]->shape && std::holds_alternative<UnitSphere>(*children[0]->shape));
  EXPECT_TRUE(children[0]->node_from_object.is_identity());
  EXPECT_EQ(children[1]->name, "box");
  EXPECT_TRUE(children[1]->shape && std::holds_alternative<UnitCube>(*children[1]->shape));
  EXPECT_TRUE(children[1]->node_from_object.is_identity());
  EXPECT_EQ(children[1]->where.line, 3);
}

TEST_F(LuaScene, NodesMadeAndRenderedInsideACoroutineAreTheScene) {
  // The bindings find their context through the running thread: a coroutine is another one.
  const auto scene = load(
      "local build = coroutine.wrap(function()\n"
      "  root = gr.node('root')\n"
      "  coroutine.yield()\n"
      "  root:add_child(gr.sphere('ball'))\n" +
      render_call() +
      "end)\n"
      "build()\n"
      "build()\n");
  ASSERT_EQ(scene.jobs.size(), 1u);
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 1u);
  EXPECT_EQ(children[0]->name, "ball");
  EXPECT_EQ(children[0]->where.line, 4);
}

TEST_F(LuaScene, NhSpherePlacesTheUnitSphereByCentreAndRadius) {
  const auto scene = load("root = gr.nh_sphere('s', {1, 2, 3}, 2)\n" + render_call());
  const SceneNode& s = *scene.jobs[0].root;
  EXPECT_TRUE(s.shape && std::holds_alternative<UnitSphere>(*s.shape));
  EXPECT_TRUE(s.parent_from_node.is_identity());
  EXPECT_EQ(text(s.node_from_object.matrix()), "[2 0 0 1; 0 2 0 2; 0 0 2 3; 0 0 0 1]");
  EXPECT_EQ(text(s.node_from_object.inverse_matrix()), "[0.5 0 0 -0.5; 0 0.5 0 -1; 0 0 0.5 -1.5; 0 0 0 1]");
}

TEST_F(LuaScene, NhBoxSpansCornerToCornerPlusSize) {
  const auto scene = load("root = gr.nh_box('b', {-1, 0, 2}, 4)\n" + render_call());
  const SceneNode& b = *scene.jobs[0].root;
  EXPECT_TRUE(b.shape && std::holds_alternative<UnitCube>(*b.shape));
  EXPECT_EQ(text(b.node_from_object(Point3(0, 0, 0))), "(-1 0 2)");
  EXPECT_EQ(text(b.node_from_object(Point3(1, 1, 1))), "(3 4 6)");
}

TEST_F(LuaScene, TableMeshFanTriangulatesZeroBasedPolygons) {
  const auto scene = load(
      "root = gr.mesh('penta', {{0,0,0}, {2,0,0}, {3,1,0}, {1,2,0}, {-1,1,0}},\n"
      "                {{0, 1, 2, 3, 4}, {4, 3, 2}})\n" +
      render_call());
  const SceneNode& m = *scene.jobs[0].root;
  EXPECT_TRUE(m.mesh && !m.shape);
  ASSERT_NE(m.mesh, nullptr);
  ASSERT_EQ(m.mesh->positions.size(), 5u);
  EXPECT_EQ(text(m.mesh->positions[2]), "(3 1 0)");
  EXPECT_EQ(text(m.mesh->positions[4]), "(-1 1 0)");
  EXPECT_EQ(triangles_of(*m.mesh), "0,1,2 0,2,3 0,3,4 4,3,2");
  EXPECT_EQ(m.mesh->polygon_count, 2u);
}

TEST_F(LuaScene, FileMeshIsReadFromTheScriptsFolderAndSharedByName) {
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 5\nf 1 2 3\nf 1 3 4\n");
  const auto scene = load(
      "root = gr.node('root')\n"
      "root:add_child(gr.mesh('a', 'tri.obj'))\n"
      "root:add_child(gr.mesh('b', 'tri.obj'))\n" +
      render_call());
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 2u);
  ASSERT_NE(children[0]->mesh, nullptr);
  EXPECT_TRUE(children[0]->mesh && !children[0]->shape);
  EXPECT_EQ(triangles_of(*children[0]->mesh), "0,1,2 0,2,3");
  EXPECT_EQ(text(children[0]->mesh->positions[3]), "(0 0 5)");
  EXPECT_EQ(children[0]->mesh, children[1]->mesh);  // loaded once
}

TEST_F(LuaScene, MeshIsFoundInAParentsAssetsFolderButTheScriptsFolderComesFirst) {
  write("Assets/far.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("Assets/near.obj", "v 9 9 9\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("scenes/near.obj", "v 7 7 7\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto script = write("scenes/scene.lua",
                            "root = gr.node('root')\n"
                            "root:add_child(gr.mesh('far', 'far.obj'))\n"
                            "root:add_child(gr.mesh('near', 'near.obj'))\n" +
                                render_call());
  const auto scene = load_scene(script, {});
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 2u);
  EXPECT_EQ(text(children[0]->mesh->positions[0]), "(0 0 0)");
  EXPECT_EQ(text(children[1]->mesh->positions[0]), "(7 7 7)");
}

TEST_F(LuaScene, InputsAreHashedWhileTheScriptRunsAsTheyWouldBeAfter) {
  write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("b.obj", "v 0 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto script = write("scene.lua",
                            "root = gr.node('root')\n"
                            "root:add_child(gr.mesh('a', 'a.obj'))\n"
                            "root:add_child(gr.mesh('b', 'b.obj'))\n"
                            "root:add_child(gr.mesh('again', 'a.obj'))\n" +
                                render_call());
  const auto scene = load_scene(script, {});
  ASSERT_EQ(scene.input_hashes.size(), 2u);
  for (const auto& input : scene.inputs) {
    ASSERT_EQ(scene.input_hashes.count(input), 1u) << input;
    EXPECT_EQ(scene.input_hashes.at(input), file_hash(input)) << input;
  }
  EXPECT_NE(file_hash(scene.inputs[0]), file_hash(scene.inputs[1]));
}

TEST_F(LuaScene, MaterialIsSharedByTheNodesThatUseIt) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "m = gr.material({0.25, 0.5, 0.75}, {0.125, 1, 0}, 25)\n"
      "a = gr.sphere('a') a:set_material(m) root:add_child(a)\n"
      "b = gr.cube('b') b:set_material(m) root:add_child(b)\n" +
      render_call());
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 2u);
  ASSERT_NE(children[0]->material, nullptr);
  const auto& phong = std::get<PhongMaterial>(*children[0]->material);
  EXPECT_EQ(phong.kd, Color(0.25f, 0.5f, 0.75f));
  EXPECT_EQ(phong.ks, Color(0.125f, 1, 0));
  EXPECT_EQ(phong.shininess, 25);
  EXPECT_EQ(children[0]->material, children[1]->material);
}

TEST_F(LuaScene, RenderRecordsEveryField) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "l1 = gr.light({1, 2, 3}, {0.5, 0.25, 1}, {1, 0.5, 0.25})\n"
      "l2 = gr.light({-4, 5, -6}, {1, 1, 1}, {1, 0, 0})\n"
      "gr.render(root, 'img/out.png', 7, 5, {0, 1, 20}, {0, -2, -10}, {0, 1, 0.5}, 40,\n"
      "          {0.3, 0.2, 0.1}, {l1, l2})\n");
  ASSERT_EQ(scene.jobs.size(), 1u);
  const RenderJob& job = scene.jobs[0];
  EXPECT_EQ(job.where.to_string(), (dir_ / "scene.lua").string() + ":4");
  EXPECT_EQ(job.output, fs::path("img/out.png"));
  EXPECT_EQ(job.width, 7);
  EXPECT_EQ(job.height, 5);
  EXPECT_EQ(text(job.camera.eye), "(0 1 20)");
  EXPECT_EQ(job.camera.view, Vector3(0, -2, -10));  // as given: normalised by the camera
  EXPECT_EQ(job.camera.up, Vector3(0, 1, 0.5f));
  EXPECT_EQ(job.camera.fovy_degrees, 40);
  EXPECT_EQ(job.ambient, Color(0.3f, 0.2f, 0.1f));
  ASSERT_EQ(job.lights.size(), 2u);
  const auto& light = std::get<PointLight>(job.lights[0]);
  EXPECT_EQ(text(light.position), "(1 2 3)");
  EXPECT_EQ(light.colour, Color(0.5f, 0.25f, 1));
  EXPECT_EQ(light.falloff[0], 1);
  EXPECT_EQ(light.falloff[1], 0.5f);
  EXPECT_EQ(light.falloff[2], 0.25f);
  EXPECT_EQ(text(std::get<PointLight>(job.lights[1]).position), "(-4 5 -6)");
  EXPECT_EQ(job.root->name, "root");
}

TEST_F(LuaScene, RenderIsAlsoANodeMethod) {
  const auto scene = load(
      "root = gr.node('top')\n"
      "root:render('m.png', 6, 2, {0,0,1}, {0,0,-1}, {0,1,0}, 50, {0,0,0}, {gr.light({0,0,0}, {1,1,1}, {1,0,0})})\n");
  ASSERT_EQ(scene.jobs.size(), 1u);
  EXPECT_EQ(scene.jobs[0].root->name, "top");
  EXPECT_EQ(scene.jobs[0].output, fs::path("m.png"));
  EXPECT_EQ(scene.jobs[0].width, 6);
  EXPECT_EQ(scene.jobs[0].where.line, 2);
}

TEST_F(LuaScene, EachRenderSnapshotsTheGraphSoLaterChangesDoNotLeakBack) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "ball = gr.sphere('ball')\n"
      "root:add_child(ball)\n"
      "for frame = 1, 3 do\n"
      "  ball:translate(0, 1, 0)\n"
      "  " + render_call("root", "'frame' .. frame .. '.png'") +
      "end\n"
      "ball:scale(5, 5, 5)\n"
      "ball:set_material(gr.material({1,0,0}, {0,0,0}, 1))\n"
      "root:add_child(gr.cube('late'))\n");
  ASSERT_EQ(scene.jobs.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE(i);
    const RenderJob& job = scene.jobs[i];
    EXPECT_EQ(job.output, fs::path("frame" + std::to_string(i + 1) + ".png"));
    ASSERT_EQ(job.root->children.size(), 1u);
    const SceneNode& ball = *job.root->children[0];
    EXPECT_EQ(text(ball.parent_from_node(Point3(0, 0, 0))), text(Point3(0, float(i + 1), 0)));
    EXPECT_EQ(ball.material, nullptr);
  }
}

TEST_F(LuaScene, ExtraTrailingArgumentsAreIgnored) {
  const auto scene = load(
      "root = gr.node('root', 'extra')\n"
      "s = gr.sphere('s2', {0, -1, 0}, 0.5)\n"
      "s:set_material(gr.material({1, 1, 1}, {0, 0, 0}, 25, 0.0, true), 'x')\n"
      "s:translate(1, 2, 3, 4)\n"
      "s:rotate('y', 90, 'extra')\n"
      "root:add_child(s, s)\n"
      "root:add_child(gr.nh_sphere('n', {0,0,0}, 1, {1,2,3}))\n"
      "l = gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0}, 0.5, 'soft')\n"
      "gr.render(root, 'o.png', 3, 2, {0,0,5}, {0,0,-1}, {0,1,0}, 50, {0,0,0}, {l}, true, 4, 8)\n");
  ASSERT_EQ(scene.jobs.size(), 1u);
  EXPECT_EQ(scene.jobs[0].root->children.size(), 2u);
  EXPECT_EQ(scene.jobs[0].lights.size(), 1u);
}

TEST_F(LuaScene, NumericStringsAndNumberNamesAreAcceptedLikeTheStockBinding) {
  // The course binding reads with luaL_checknumber/luaL_checkstring, which convert.
  const auto scene = load(
      "root = gr.node(42)\n"
      "root:translate('1', 2, '3.5')\n" +
      render_call());
  EXPECT_EQ(scene.jobs[0].root->name, "42");
  EXPECT_EQ(text(scene.jobs[0].root->parent_from_node(Point3(0, 0, 0))), "(1 2 3.5)");
}

TEST_F(LuaScene, RotateTakesTheAxisInEitherCaseAndDegrees) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "a = gr.node('a') a:rotate('z', 90) root:add_child(a)\n"
      "b = gr.node('b') b:rotate('Z', 90) root:add_child(b)\n"
      "c = gr.node('c') c:rotate('X', 90) root:add_child(c)\n" +
      render_call());
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 3u);
  EXPECT_EQ(text(children[0]->parent_from_node.matrix()), text(children[1]->parent_from_node.matrix()));
  EXPECT_EQ(text(children[0]->parent_from_node.matrix()), text(Transform::rotate(2, 90).matrix()));
  // Right-handed: +x turns to +y about z, +y turns to +z about x.
  const Point3 x_turned = children[0]->parent_from_node(Point3(1, 0, 0));
  EXPECT_NEAR(x_turned.x, 0, 1e-6);
  EXPECT_NEAR(x_turned.y, 1, 1e-6);
  const Point3 y_turned = children[2]->parent_from_node(Point3(0, 1, 0));
  EXPECT_NEAR(y_turned.y, 0, 1e-6);
  EXPECT_NEAR(y_turned.z, 1, 1e-6);
}

TEST_F(LuaScene, OneNodeUnderTwoParentsIsSharedNotCopied) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "cow = gr.sphere('cow')\n"
      "left = gr.node('left') left:translate(-1, 0, 0) left:add_child(cow)\n"
      "right = gr.node('right') right:translate(1, 0, 0) right:add_child(cow)\n"
      "root:add_child(left) root:add_child(right)\n" +
      render_call());
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 2u);
  ASSERT_EQ(children[0]->children.size(), 1u);
  ASSERT_EQ(children[1]->children.size(), 1u);
  EXPECT_EQ(children[0]->children[0].get(), children[1]->children[0].get());
  EXPECT_EQ(children[0]->children[0]->name, "cow");
}

TEST_F(LuaScene, GeometryMayHaveChildrenAndNoMaterial) {
  const auto scene = load(
      "root = gr.sphere('body')\n"
      "root:add_child(gr.cube('hat'))\n" +
      render_call());
  const SceneNode& root = *scene.jobs[0].root;
  EXPECT_TRUE(root.shape && std::holds_alternative<UnitSphere>(*root.shape));
  EXPECT_EQ(root.material, nullptr);
  ASSERT_EQ(root.children.size(), 1u);
  EXPECT_TRUE(root.children[0]->shape && std::holds_alternative<UnitCube>(*root.children[0]->shape));
}

// --- transform order ---------------------------------------------------------------------

constexpr const char* kTranslateThenScale =
    "root = gr.node('root')\n"
    "root:translate(1, 2, 3)\n"
    "root:scale(2, 3, 4)\n";
constexpr const char* kTableMesh = "tri = gr.mesh('tri', {{0,0,0},{1,0,0},{0,1,0}}, {{0,1,2}})\n";
// M = S·T: the translation happens first, then everything is scaled.
constexpr const char* kPreMatrix = "[2 0 0 2; 0 3 0 6; 0 0 4 12; 0 0 0 1]";
// M = T·S: the scale applies in the node's frame, the translation stays as written.
constexpr const char* kPostMatrix = "[2 0 0 1; 0 3 0 2; 0 0 4 3; 0 0 0 1]";

void expect_inverse_consistent(const Transform& t) {
  const Matrix4 product = t.matrix() * t.inverse_matrix();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(product.m[size_t(i)][size_t(j)], i == j ? 1 : 0, 1e-12);
}

TEST_F(LuaScene, TransformOrderIsPreMultiplyWithoutTableMeshes) {
  const auto scene = load(std::string(kTranslateThenScale) + render_call());
  EXPECT_EQ(text(scene.jobs[0].root->parent_from_node.matrix()), kPreMatrix);
  expect_inverse_consistent(scene.jobs[0].root->parent_from_node);
}

TEST_F(LuaScene, TransformOrderIsPostMultiplyWhenTheRenderedSceneHoldsATableMesh) {
  const auto scene = load(std::string(kTableMesh) + kTranslateThenScale + "root:add_child(tri)\n" + render_call());
  EXPECT_EQ(text(scene.jobs[0].root->parent_from_node.matrix()), kPostMatrix);
  expect_inverse_consistent(scene.jobs[0].root->parent_from_node);
  // The choice is told, naming the gr.render line and the mesh that decided it.
  ASSERT_EQ(scene.notes.size(), 1u);
  EXPECT_EQ(scene.notes[0], at(6) + "node transforms compose post-multiplied (M = M·T, the old course skeleton's order) "
                                    "for every gr.render of this script, because this scene holds the table-form gr.mesh "
                                    "'tri' made at " + at(1).substr(0, at(1).size() - 2) +
                                    "; --transform-order pre overrides");
}

TEST_F(LuaScene, MeshesThatTheRenderedSceneDoesNotHoldLeaveTheOrderPre) {
  // The case: an extended mesh made but never added moved a sphere from x=1 to x=2.
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (const std::string& unused : {std::string(kTableMesh), std::string("e = gr.extendedmesh('e', false, read_extended_obj('tri.obj'))\n")}) {
    const auto scene = load(unused + kTranslateThenScale + render_call());
    EXPECT_EQ(text(scene.jobs[0].root->parent_from_node.matrix()), kPreMatrix) << unused;
    EXPECT_TRUE(scene.notes.empty());
  }
}

TEST_F(LuaScene, TheFirstRenderDecidesTheOrderForTheWholeScript) {
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // Extended mesh in the first render: every render is post, also one without the mesh.
  auto scene = load(std::string(kTranslateThenScale) + "e = gr.extendedmesh('e', false, read_extended_obj('tri.obj'))\n"
                    "root:add_child(e)\n" + render_call() + "other = gr.node('other')\nother:translate(1, 2, 3)\n"
                    "other:scale(2, 3, 4)\n" + render_call("other"));
  EXPECT_EQ(text(scene.jobs[0].root->parent_from_node.matrix()), kPostMatrix);
  EXPECT_EQ(text(scene.jobs[1].root->parent_from_node.matrix()), kPostMatrix);
  // A first render without one keeps every render pre, also a later one with the mesh.
  scene = load(std::string(kTranslateThenScale) + render_call() + kTableMesh + "root:add_child(tri)\n" + render_call());
  EXPECT_EQ(text(scene.jobs[1].root->parent_from_node.matrix()), kPreMatrix);
  EXPECT_TRUE(scene.notes.empty());
}

TEST_F(LuaScene, FileMeshesKeepThePreMultiplyRule) {
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto scene = load("gr.mesh('m', 'tri.obj')\n" + std::string(kTranslateThenScale) + render_call());
  EXPECT_EQ(text(scene.jobs[0].root->parent_from_node.matrix()), kPreMatrix);
}

TEST_F(LuaScene, TransformOrderOptionOverridesTheAutomaticRule) {
  SceneLoadOptions post;
  post.transform_order = TransformOrder::kPost;
  EXPECT_EQ(text(load(std::string(kTranslateThenScale) + render_call(), post).jobs[0].root->parent_from_node.matrix()),
            kPostMatrix);
  SceneLoadOptions pre;
  pre.transform_order = TransformOrder::kPre;
  EXPECT_EQ(text(load(std::string(kTableMesh) + kTranslateThenScale + "root:add_child(tri)\n" + render_call(), pre)
                     .jobs[0].root->parent_from_node.matrix()),
            kPreMatrix);
}

// --- compatibility: require, readobj, Lua 5.1 names -----------------------------------------

TEST_F(LuaScene, RequireFindsAHelperBesideTheScene) {
  write("shapes.lua",
        "local M = {}\n"
        "function M.ball(name) local s = gr.sphere(name) s:scale(2, 2, 2) return s end\n"
        "return M\n");
  const auto scene = load(
      "local shapes = require('shapes')\n"
      "root = gr.node('root')\n"
      "root:add_child(shapes.ball('b'))\n" +
      render_call());
  const auto& children = scene.jobs[0].root->children;
  ASSERT_EQ(children.size(), 1u);
  EXPECT_EQ(children[0]->name, "b");
  EXPECT_EQ(children[0]->where.to_string(), (dir_ / "shapes.lua").string() + ":2");
}

TEST_F(LuaScene, TheScenesOwnReadobjWinsOverTheBuiltIn) {
  // A course-style readobj.lua (Lua 5.1 idioms: string.gfind, unpack) that tags its vertices.
  write("readobj.lua",
        "function readobj(filename)\n"
        "  local verts, faces = {}, {}\n"
        "  for line in io.lines(filename) do\n"
        "    local tokens = {}\n"
        "    for t in string.gfind(line, '%S+') do table.insert(tokens, t) end\n"
        "    if tokens[1] == 'v' then\n"
        "      table.insert(verts, {tonumber(tokens[2]) + 100, tonumber(tokens[3]), tonumber(tokens[4])})\n"
        "    elseif tokens[1] == 'f' then\n"
        "      local a, b, c = unpack(tokens, 2, 4)\n"
        "      table.insert(faces, {tonumber(a) - 1, tonumber(b) - 1, tonumber(c) - 1})\n"
        "    end\n"
        "  end\n"
        "  return verts, faces\n"
        "end\n");
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto scene = load(
      "require('readobj')\n"
      "root = gr.mesh('m', readobj('tri.obj'))\n" +
      render_call());
  const SceneNode& m = *scene.jobs[0].root;
  ASSERT_NE(m.mesh, nullptr);
  EXPECT_EQ(text(m.mesh->positions[0]), "(100 0 0)");
  EXPECT_EQ(text(m.mesh->positions[1]), "(101 0 0)");
  EXPECT_EQ(triangles_of(*m.mesh), "0,1,2");
}

TEST_F(LuaScene, BuiltInReadobjReturnsZeroBasedFaces) {
  write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
  const auto scene = load(
      "assert(require('readobj'))\n"
      "local v, f = readobj('quad.obj')\n"
      "local parts = {}\n"
      "for _, face in ipairs(f) do parts[#parts + 1] = table.concat(face, ',') end\n"
      "root = gr.mesh('m', v, f)\n" +
      render_call("root", "#v .. ' ' .. table.concat(parts, ' ')"));
  EXPECT_EQ(scene.jobs[0].output, fs::path("4 0,1,2 0,2,3"));
  EXPECT_EQ(triangles_of(*scene.jobs[0].root->mesh), "0,1,2 0,2,3");
  EXPECT_EQ(text(scene.jobs[0].root->mesh->positions[2]), "(1 1 0)");
}

TEST_F(LuaScene, UnpackAndStringGfindExist) {
  const auto scene = load(
      "local a, b, c = unpack({1, 2, 3})\n"
      "local x, y = table.unpack({4, 5})\n"
      "local letters = ''\n"
      "for w in string.gfind('p q r', '%a') do letters = letters .. w end\n"
      "root = gr.node('root')\n" +
      render_call("root", "(a + b + c + x + y) .. letters"));
  EXPECT_EQ(scene.jobs[0].output, fs::path("15pqr"));
}

// --- errors ------------------------------------------------------------------------------

using LuaErrors = LuaTest;

TEST_F(LuaErrors, SyntaxErrorNamesTheLine) {
  EXPECT_EQ(error_of("root = gr.node('root')\nlocal x = = 1\n"), at(2) + "unexpected symbol near '='");
}

TEST_F(LuaErrors, RuntimeErrorNamesTheLine) {
  EXPECT_EQ(error_of("root = gr.node('root')\n\nundefined_function()\n"),
            at(3) + "attempt to call a nil value (global 'undefined_function')");
}

TEST_F(LuaErrors, ErrorWithANonStringValueStillNamesTheLine) {
  EXPECT_EQ(error_of("root = gr.node('root')\nerror({code = 7})\n"),
            at(2) + "the script raised an error value that is not a string (a table)");
}

TEST_F(LuaErrors, TwoNumberColourToMaterial) {
  EXPECT_EQ(error_of("root = gr.node('root')\nm = gr.material({1, 0}, {0, 0, 0}, 10)\n"),
            at(2) + "gr.material: argument 1 (kd) must be a table of 3 numbers, got a table of 2 values");
}

TEST_F(LuaErrors, ColourWithANonNumberEntry) {
  EXPECT_EQ(error_of("m = gr.material({1, 0, 0}, {0, 'x', 0}, 10)\n"),
            at(1) + "gr.material: argument 2 (ks) must be a table of 3 numbers, got a table whose entry 2 is "
                    "the string 'x'");
}

TEST_F(LuaErrors, StringWhereANumberGoes) {
  EXPECT_EQ(error_of("m = gr.material({1, 0, 0}, {0, 0, 0}, 'shiny')\n"),
            at(1) + "gr.material: argument 3 (shininess) must be a number, got the string 'shiny'");
  EXPECT_EQ(error_of("s = gr.nh_sphere('s', {0, 0, 0}, nil)\n"),
            at(1) + "gr.nh_sphere: argument 3 (radius) must be a number, got nil");
}

TEST_F(LuaErrors, MissingName) {
  EXPECT_EQ(error_of("\ns = gr.sphere()\n"), at(2) + "gr.sphere: argument 1 (name) must be a string, got nothing");
}

TEST_F(LuaErrors, NonNodeToAddChild) {
  EXPECT_EQ(error_of("root = gr.node('root')\nroot:add_child({})\n"),
            at(2) + "node:add_child: argument 1 (child) must be a node, got an empty table");
}

TEST_F(LuaErrors, MethodCalledWithADotInsteadOfAColon) {
  EXPECT_EQ(error_of("root = gr.node('root')\nroot.translate(1, 2, 3)\n"),
            at(2) + "node:translate: must be called on a node (with ':'), got the number 1");
}

TEST_F(LuaErrors, NonMaterialToSetMaterial) {
  EXPECT_EQ(error_of("s = gr.sphere('s')\ns:set_material(gr.light({0,0,0}, {1,1,1}, {1,0,0}))\n"),
            at(2) + "node:set_material: argument 1 (material) must be a material, got a gr.light");
}

TEST_F(LuaErrors, BadRotateAxis) {
  EXPECT_EQ(error_of("s = gr.sphere('s')\ns:rotate('w', 30)\n"), at(2) + "node:rotate: axis must be 'x', 'y' or 'z', got 'w'");
  EXPECT_EQ(error_of("s = gr.sphere('s')\ns:rotate('xy', 30)\n"), at(2) + "node:rotate: axis must be 'x', 'y' or 'z', got 'xy'");
}

TEST_F(LuaErrors, MissingObjFile) {
  EXPECT_EQ(error_of("root = gr.node('root')\nm = gr.mesh('m', 'missing.obj')\n"),
            at(2) + "gr.mesh: cannot find 'missing.obj' (looked in the scene's folder, its parent folders, their "
                    "Assets/ folders and the working directory)");
}

TEST_F(LuaErrors, MalformedObjFileNamesBothTheSceneLineAndTheObjLine) {
  const auto obj = write("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  const std::string message = error_of("\n\nm = gr.mesh('m', 'bad.obj')\n");
  EXPECT_EQ(message.rfind(at(3) + "gr.mesh: " + obj.string() + ":3: ", 0), 0u) << message;
}

TEST_F(LuaErrors, GarbageObjFilesAreErrorsNamingTheFile) {
  const auto obj = write("junk.obj", "hello world\n");
  EXPECT_EQ(error_of("m = gr.mesh('m', 'junk.obj')\n"),
            at(1) + "gr.mesh: " + obj.string() + ": no vertices ('v x y z' lines) in this OBJ file; line 1 starts with "
                    "'hello', which is not an OBJ statement: is it an OBJ file?");
  write("points.obj", "# only points\nv 0 0 0\nv 1 0 0\np 1 2\n");
  EXPECT_EQ(error_of("m = gr.extendedmesh('m', false, read_extended_obj('points.obj'))\n"),
            at(1) + "read_extended_obj: " + (dir_ / "points.obj").string() +
                    ": no faces ('f' lines) in this OBJ file, so it would draw nothing");
  EXPECT_EQ(error_of("v, f = readobj('junk.obj')\n").rfind(at(1) + "readobj: " + obj.string() + ": no vertices", 0), 0u);
}

TEST_F(LuaScene, ObjFileMostlyNotObjWarns) {
  const auto obj = write("odd.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nfoo 1\nbar 2\nbaz 3\nqux 4\nquux 5\n");
  const auto scene = load("root = gr.node('root')\nm = gr.mesh('m', 'odd.obj')\nroot:add_child(m)\n" + render_call());
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0], at(2) + obj.string() + ": 5 of its 9 statements are not OBJ; line 5 starts with 'foo', "
                                       "which is not an OBJ statement: is it an OBJ file?");
}

TEST_F(LuaErrors, TableMeshIndexOutOfRange) {
  EXPECT_EQ(error_of("m = gr.mesh('m', {{0,0,0}, {1,0,0}, {0,1,0}},\n  {{0, 1, 3}})\n"),
            at(1) + "gr.mesh: face 1 has index 3 outside 0..2");
  EXPECT_EQ(error_of("m = gr.mesh('m', {{0,0,0}, {1,0,0}, {0,1,0}}, {{0, 1, -1}})\n"),
            at(1) + "gr.mesh: face 1 has index -1 outside 0..2");
}

TEST_F(LuaErrors, TableMeshBadVertexIsNamedByItsNumber) {
  EXPECT_EQ(error_of("m = gr.mesh('m', {{0,0,0}, {1,'a',0}, {0,1,0}}, {{0, 1, 2}})\n"),
            at(1) + "gr.mesh: vertex 2 must be a table of 3 numbers, got a table whose entry 2 is the string 'a'");
  EXPECT_EQ(error_of("m = gr.mesh('m', {{0,0,0}, {1,0,0}, {0,1}}, {{0, 1, 2}})\n"),
            at(1) + "gr.mesh: vertex 3 must be a table of 3 numbers, got a table of 2 values");
  EXPECT_EQ(error_of("m = gr.mesh('m', {{0,0,0}, {1,0,0}, {0,1,0}}, {{0, 1, 2}, 5})\n"),
            at(1) + "gr.mesh: face 2 must be a table of at least 3 vertex indices, got the number 5");
}

TEST_F(LuaErrors, EmptyLightsTable) {
  EXPECT_EQ(error_of("root = gr.node('root')\n"
                     "gr.render(root, 'o.png', 4, 3, {0,0,1}, {0,0,-1}, {0,1,0}, 50, {0,0,0}, {})\n"),
            at(2) + "gr.render: the lights table is empty (give at least one gr.light)");
}

TEST_F(LuaErrors, NonLightInLightsTable) {
  EXPECT_EQ(error_of("root = gr.node('root')\n"
                     "l = gr.light({0,0,0}, {1,1,1}, {1,0,0})\n"
                     "gr.render(root, 'o.png', 4, 3, {0,0,1}, {0,0,-1}, {0,1,0}, 50, {0,0,0}, {l, root})\n"),
            at(3) + "gr.render: lights entry 2 must be a light, got a gr.node");
}

std::string render_with(const std::string& size, const std::string& view, const std::string& up,
                        const std::string& fovy) {
  return "root = gr.node('root')\n"
         "l = gr.light({0,0,0}, {1,1,1}, {1,0,0})\n"
         "gr.render(root, 'o.png', " + size + ", {0,0,1}, " + view + ", " + up + ", " + fovy + ", {0,0,0}, {l})\n";
}

TEST_F(LuaErrors, ZeroWidth) {
  EXPECT_EQ(error_of(render_with("0, 3", "{0,0,-1}", "{0,1,0}", "50")),
            at(3) + "gr.render: width and height must be whole numbers from 1 to 65536, got 0 x 3");
  EXPECT_EQ(error_of(render_with("4, 2.5", "{0,0,-1}", "{0,1,0}", "50")),
            at(3) + "gr.render: width and height must be whole numbers from 1 to 65536, got 4 x 2.5");
}

TEST_F(LuaErrors, ZeroViewVector) {
  EXPECT_EQ(error_of(render_with("4, 3", "{0,0,0}", "{0,1,0}", "50")), at(3) + "gr.render: the view direction is zero");
}

TEST_F(LuaErrors, UpParallelToView) {
  EXPECT_EQ(error_of(render_with("4, 3", "{0,0,-1}", "{0,0,5}", "50")),
            at(3) + "gr.render: the up vector is parallel to the view direction");
  EXPECT_EQ(error_of(render_with("4, 3", "{0,0,-1}", "{0,0,0}", "50")),
            at(3) + "gr.render: the up vector is parallel to the view direction");
}

TEST_F(LuaErrors, FovyOutOfRange) {
  EXPECT_EQ(error_of(render_with("4, 3", "{0,0,-1}", "{0,1,0}", "0")),
            at(3) + "gr.render: fovy must be between 0 and 180 degrees, got 0");
  EXPECT_EQ(error_of(render_with("4, 3", "{0,0,-1}", "{0,1,0}", "180")),
            at(3) + "gr.render: fovy must be between 0 and 180 degrees, got 180");
}

TEST_F(LuaErrors, EmptyOutputName) {
  EXPECT_EQ(error_of("root = gr.node('root')\n" + render_call("root", "''")),
            at(2) + "gr.render: argument 2 (output file) must be a file name, got an empty string");
}

TEST_F(LuaErrors, ControlCharactersInStringsAreRefusedAndShownEscaped) {
  // A NUL would end the file name where the system reads it: 'notes.txt\0.png' passes as a PNG
  // here and would then replace notes.txt.
  EXPECT_EQ(error_of("root = gr.node('root')\n" + render_call("root", "'notes.txt\\0.png'")),
            at(2) + "gr.render: argument 2 (output file) must be a string without control characters (such as a "
                    "NUL, a tab or a line break), got the string 'notes.txt\\000.png'");
  // An escape or a line break in a name would reach the terminal raw in later messages.
  EXPECT_EQ(error_of("s = gr.sphere('a\\0271\\\\2\\nmjray: wrote x.png')\n"),
            at(1) + "gr.sphere: argument 1 (name) must be a string without control characters (such as a NUL, a "
                    "tab or a line break), got the string 'a\\0271\\\\2\\nmjray: wrote x.png'");
  EXPECT_EQ(error_of("m = gr.mesh('m', 'model\\0.obj')\n"),
            at(1) + "gr.mesh: argument 2 (file name) must be a string without control characters (such as a NUL, "
                    "a tab or a line break), got the string 'model\\000.obj'");
}

TEST_F(LuaErrors, EachArgumentIsCheckedInTheOrderWritten) {
  EXPECT_EQ(error_of("n = gr.node('n')\nn:translate(1, 'a')\n"),
            at(2) + "node:translate: argument 2 (y) must be a number, got the string 'a'");
  EXPECT_EQ(error_of("n = gr.node('n')\nn:translate({1, 2, 3})\n"),
            at(2) + "node:translate: argument 1 (x) must be a number, got a table of 3 values");
}

TEST_F(LuaErrors, SceneThatNeverRenders) {
  EXPECT_EQ(error_of("root = gr.node('root')\n"), (dir_ / "scene.lua").string() + ": the scene never calls gr.render");
}

TEST_F(LuaErrors, MissingSceneFile) {
  const fs::path missing = dir_ / "nowhere.lua";
  try {
    load_scene(missing, {});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open the scene file (no such file)");
  }
}

TEST_F(LuaErrors, CycleIsReportedNotFollowed) {
  EXPECT_EQ(error_of("a = gr.node('a')\n"
                     "b = gr.node('b')\n"
                     "a:add_child(b)\n"
                     "b:add_child(a)\n" +
                     render_call("a")),
            at(5) + "gr.render: node 'a' (created at " + (dir_ / "scene.lua").string() +
                ":1) is its own ancestor: the scene graph has a cycle");
}

TEST_F(LuaErrors, SelfChildIsACycle) {
  EXPECT_EQ(error_of("a = gr.node('a')\na:add_child(a)\n" + render_call("a")),
            at(3) + "gr.render: node 'a' (created at " + (dir_ / "scene.lua").string() +
                ":1) is its own ancestor: the scene graph has a cycle");
}

TEST_F(LuaErrors, AbsurdlyDeepGraphIsRefusedNotACrash) {
  const std::string message = error_of(
      "local top = gr.node('n0')\n"
      "for i = 1, 200000 do local n = gr.node('n' .. i) n:add_child(top) top = n end\n" +
      render_call("top"));
  EXPECT_EQ(message.rfind(at(3) + "gr.render: the scene graph is nested deeper than", 0), 0u) << message;
}

TEST_F(LuaErrors, ErrorInsideARequiredHelperNamesTheHelper) {
  const auto helper = write("helper.lua", "local M = {}\nfunction M.make() return gr.sphere() end\nreturn M\n");
  EXPECT_EQ(error_of("local h = require('helper')\nroot = h.make()\n"),
            helper.string() + ":2: gr.sphere: argument 1 (name) must be a string, got nothing");
}

TEST_F(LuaErrors, SyntaxErrorInARequiredHelperNamesBothFiles) {
  const auto helper = write("helper.lua", "local M = {}\nM.x = = 1\nreturn M\n");
  EXPECT_EQ(error_of("\nlocal h = require('helper')\n"),
            at(2) + "error loading module 'helper' from file '" + helper.string() + "':\n\t" + helper.string() +
                ":2: unexpected symbol near '='");
}

TEST_F(LuaErrors, CaughtByPcallTheErrorStillNamesTheScriptLine) {
  // pcall is a C frame between the binding and the script: the location skips it.
  const auto scene = load(
      "local ok, message = pcall(gr.sphere)\n"
      "root = gr.node('root')\n" +
      render_call("root", "message"));
  EXPECT_EQ(scene.jobs[0].output.string(), at(1) + "gr.sphere: argument 1 (name) must be a string, got nothing");
}

TEST_F(LuaErrors, MisspelledNamesSuggestTheClosestOne) {
  EXPECT_EQ(error_of("root = gr.node('root')\ns = gr.sphre('s')\n"),
            at(2) + "gr.sphre is not a gr function; did you mean gr.sphere?");
  EXPECT_EQ(error_of("m = gr.fresneldielectricmateral({0,0,0}, {1,1,1}, 10, 1, 1.5)\n"),
            at(1) + "gr.fresneldielectricmateral is not a gr function; did you mean gr.fresneldielectricmaterial?");
  EXPECT_EQ(error_of("root = gr.node('root')\nroot:translte(1, 2, 3)\n"),
            at(2) + "node:translte is not a node method; did you mean node:translate?");
  EXPECT_EQ(error_of("m = gr.material({1,1,1}, {0,0,0}, 1)\nm:set_texture(nil)\n"),
            at(2) + "material:set_texture is not a material method; did you mean material:set_material_texture?");
  EXPECT_EQ(error_of("x = gr.qqqqqqqq\n"), at(1) + "gr.qqqqqqqq is not a gr function");
  // A script may still add its own names to gr.
  EXPECT_EQ(error_of("function gr.helper() return 1 end\nassert(gr.helper() == 1)\n"), at(1).substr(0, at(1).size() - 4) +
                                                                                           ": the scene never calls gr.render");
}

TEST_F(LuaScene, ColoursFarAboveOneWarnOncePerLine) {
  const auto scene = load(
      "root = gr.node('root')\n"
      "for i = 1, 3 do m = gr.material({255, 128, 0}, {0.5, 0.5, 0.5}, 10) end\n"
      "t = gr.checkerboardtexture({1, 1, 1}, {0, 0, 0}, 1)\n"
      "l = gr.light({0, 0, 10}, {200, 200, 200}, {1, 0, 0})\n"
      "far = gr.light({0, 0, 10}, {200, 200, 200}, {0, 0, 1})\n" +
      render_call());
  ASSERT_EQ(scene.warnings.size(), 2u);
  EXPECT_EQ(scene.warnings[0], at(2) + "gr.material: kd {255, 128, 0} is far above 1; mjray colours run from 0 to 1 "
                                       "(for 0-255 values, divide by 255)");
  EXPECT_EQ(scene.warnings[1], at(4) + "gr.light: colour (with no distance falloff) {200, 200, 200} is far above 1; "
                                       "mjray colours run from 0 to 1 (for 0-255 values, divide by 255)");
}

}  // namespace
}  // namespace mjray
