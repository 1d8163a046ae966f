// The original project's gr.* extensions: what they build, and their argument errors with
// scene.lua:LINE.

#include <gtest/gtest.h>

#include <filesystem>

#include "support/lua_script_test.h"
#include "support/test_job.h"

namespace mjray {
namespace {

const std::string kRender =
    "gr.render(root, 'out.png', 4, 3, {0,0,10}, {0,0,-1}, {0,1,0}, 50, {0.1,0.1,0.1}, lights)\n";

class LuaExtensions : public test::LuaScriptTest {
 protected:
  /// The material of the single sphere a script puts under root.
  Material material_of(const std::string& material_expression) {
    const auto d = load("root = gr.node('root')\ns = gr.sphere('s')\ns:set_material(" + material_expression +
                        ")\nroot:add_child(s)\nlights = {gr.light({0,0,10}, {1,1,1}, {1,0,0})}\n" + kRender);
    return *d.jobs.at(0).root->children.at(0)->material;
  }
};

TEST_F(LuaExtensions, MaterialsKeepTheirArgumentsInOrder) {
  const auto reflective = std::get<ReflectiveMaterial>(material_of("gr.reflectivematerial({0.1,0.2,0.3}, {0.4,0.5,0.6}, 25, 0.75)"));
  EXPECT_EQ(reflective.base.kd, Color(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(reflective.base.ks, Color(0.4f, 0.5f, 0.6f));
  EXPECT_EQ(reflective.base.shininess, 25);
  EXPECT_EQ(reflective.reflectivity, 0.75f);

  const auto refracted = std::get<RefractiveMaterial>(material_of("gr.refractedmaterial({0,0,0}, {1,1,1}, 100, 1.0, 1.5)"));
  EXPECT_EQ(refracted.reflectivity, 0);
  EXPECT_EQ(refracted.eta_outside, 1.0f);
  EXPECT_EQ(refracted.eta_inside, 1.5f);

  const auto blend = std::get<RefractiveMaterial>(material_of("gr.reflectrefractmaterial({0,0,0}, {1,1,1}, 100, 0.25, 1.1, 1.33)"));
  EXPECT_EQ(blend.reflectivity, 0.25f);
  EXPECT_EQ(blend.eta_outside, 1.1f);
  EXPECT_EQ(blend.eta_inside, 1.33f);

  for (const char* name : {"fresneldiectricmaterial", "fresneldielectricmaterial"}) {
    const auto glass = std::get<FresnelMaterial>(material_of(std::string("gr.") + name + "({0,0,0}, {1,1,1}, 100, 1.0, 1.52)"));
    EXPECT_EQ(glass.eta_inside, 1.52f) << name;
  }

  const auto glossy = std::get<GlossyMaterial>(material_of("gr.glossyreflectivematerial({0,0,0}, {1,1,1}, 10, 0.8, 9)"));
  EXPECT_EQ(glossy.reflectivity, 0.8f);
  EXPECT_EQ(glossy.samples, 9);
}

TEST_F(LuaExtensions, AreaLightIsACornerAndTwoEdges) {
  const auto d = load("root = gr.node('root')\n"
                      "lights = {gr.arealight({1,5,1}, {0.5,0.6,0.7}, {1,0.1,0}, {3,5,1}, {1,5,4})}\n" + kRender);
  const auto& light = std::get<AreaLight>(d.jobs.at(0).lights.at(0));
  EXPECT_EQ(light.corner, Point3(1, 5, 1));
  EXPECT_EQ(light.edge1, Vector3(2, 0, 0));
  EXPECT_EQ(light.edge2, Vector3(0, 0, 3));
  EXPECT_EQ(light.colour, Color(0.5f, 0.6f, 0.7f));
  EXPECT_EQ(light.falloff[1], 0.1f);
}

TEST_F(LuaExtensions, ExtendedMeshKeepsNormalsAndUvsOnlyWhenAsked) {
  write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n");
  const auto d = load("root = gr.node('root')\n"
                      "a = gr.extendedmesh('a', true, read_extended_obj('quad.obj'))\n"
                      "b = gr.extendedmesh('b', false, read_extended_obj('quad.obj'))\n"
                      "root:add_child(a)\nroot:add_child(b)\n"
                      "lights = {gr.light({0,0,10}, {1,1,1}, {1,0,0})}\n" + kRender);
  const auto& with_uvs = *d.jobs.at(0).root->children.at(0)->mesh;
  const auto& without = *d.jobs.at(0).root->children.at(1)->mesh;
  EXPECT_EQ(with_uvs.uvs.size(), 3u);
  EXPECT_EQ(with_uvs.triangles[0][1].uv, 1);
  EXPECT_EQ(with_uvs.normals.size(), 1u);
  EXPECT_EQ(without.uvs.size(), 0u);
  EXPECT_EQ(without.triangles[0][1].uv, -1);
  EXPECT_EQ(without.triangles[0][1].normal, 0);
}

// A reader written in Lua, as the original project's readobj.lua was: v/vt/vn/f lines into
// tables whose face corners are 0-based {position, uv, normal}.
const std::string kLuaReader = R"(
function read_extended_obj(name)
  local mesh = {positions = {}, normals = {}, uvs = {}, faces = {}}
  local function numbers(rest)
    local t = {}
    for n in rest:gmatch('%S+') do t[#t + 1] = tonumber(n) end
    return t
  end
  for line in io.lines(name) do
    local kind, rest = line:match('^(%S+)%s+(.*)$')
    if kind == 'v' then table.insert(mesh.positions, numbers(rest))
    elseif kind == 'vn' then table.insert(mesh.normals, numbers(rest))
    elseif kind == 'vt' then table.insert(mesh.uvs, numbers(rest))
    elseif kind == 'f' then
      local face = {}
      for corner in rest:gmatch('%S+') do
        local p, t, n = corner:match('^(%d+)/(%d*)/(%d*)$')
        face[#face + 1] = {tonumber(p) - 1, t ~= '' and tonumber(t) - 1 or -1, n ~= '' and tonumber(n) - 1 or -1}
      end
      table.insert(mesh.faces, face)
    end
  end
  return mesh
end
)";

const std::string kTexturedQuadObj =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn -0.3 -0.3 1\nvn 0.3 -0.3 1\nvn 0.3 0.3 1\nvn -0.3 0.3 1\nf 1/1/1 2/2/2 3/3/3 4/4/4\n";

TEST_F(LuaExtensions, ASceneOwnReadobjWinsAndItsTablesMakeTheSameMeshAsTheBuiltInReader) {
  write("quad.obj", kTexturedQuadObj);
  write("readobj.lua", kLuaReader);
  const std::string scene_tail =
      "root = gr.node('root')\n"
      "m = gr.extendedmesh('m', true, data)\n"
      "m:set_material(gr.material({0.8,0.6,0.2}, {0.5,0.5,0.5}, 20))\n"
      "root:add_child(m)\n"
      "lights = {gr.light({1,2,6}, {1,1,1}, {1,0,0})}\n" + kRender;
  const SceneDescription own =
      load("require('readobj')\ndata = read_extended_obj('quad.obj')\nassert(type(data) == 'table')\n" + scene_tail);
  std::filesystem::remove(dir_ / "readobj.lua");
  const SceneDescription builtin =
      load("require('readobj')\ndata = read_extended_obj('quad.obj')\nassert(type(data) == 'userdata')\n" + scene_tail);
  const TriangleMesh& a = *own.jobs.at(0).root->children.at(0)->mesh;
  const TriangleMesh& b = *builtin.jobs.at(0).root->children.at(0)->mesh;
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.uvs, b.uvs);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.polygon_count, 1u);
  EXPECT_EQ(a.triangles.size(), 2u);

  // The same mesh as the same four tables returned one by one, or as entries 1..4.
  for (const char* call : {"gr.extendedmesh('m', true, t.positions, t.normals, t.uvs, t.faces)",
                           "gr.extendedmesh('m', true, {t.positions, t.normals, t.uvs, t.faces})"}) {
    write("readobj.lua", kLuaReader);
    const SceneDescription d = load("require('readobj')\nt = read_extended_obj('quad.obj')\nroot = gr.node('root')\n"
                                    "root:add_child(" + std::string(call) + ")\nlights = {gr.light({1,2,6}, {1,1,1}, {1,0,0})}\n" + kRender);
    EXPECT_EQ(d.jobs.at(0).root->children.at(0)->mesh->triangles, b.triangles) << call;
  }

  // And it renders the same pixels, smooth normals and all.
  EXPECT_EQ(test::TestJob(own, 0, test::oracle_options()).render().pixels(),
            test::TestJob(builtin, 0, test::oracle_options()).render().pixels());
}

TEST_F(LuaExtensions, SetSmoothNormalsGivesAFileMeshVertexNormalsAndKeepsTheTransformOrder) {
  // A unit cube: 8 shared vertices, no vn.
  write("cube.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
        "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
  const auto d = load("root = gr.node('root')\n"
                      "a = gr.mesh('a', 'cube.obj')\nb = gr.mesh('b', 'cube.obj')\nc = gr.mesh('c', 'cube.obj')\n"
                      "a:set_smooth_normals(180)\nb:set_smooth_normals(180)\nc:set_smooth_normals(30)\n"
                      "a:translate(1, 0, 0)\na:rotate('y', 30)\n"
                      "root:add_child(a)\nroot:add_child(b)\nroot:add_child(c)\n"
                      "lights = {gr.light({0,0,10}, {1,1,1}, {1,0,0})}\n" + kRender);
  const auto& nodes = d.jobs.at(0).root->children;
  EXPECT_EQ(nodes.at(0)->mesh->normals.size(), 8u);   // one per corner of the cube
  EXPECT_EQ(nodes.at(0)->mesh, nodes.at(1)->mesh);    // the same mesh and angle: computed once
  EXPECT_EQ(nodes.at(2)->mesh->normals.size(), 24u);  // 30°: every right-angled edge a crease
  EXPECT_FALSE(d.jobs.at(0).post_multiplied);
}

TEST_F(LuaExtensions, SetSmoothNormalsRefusesANodeWithoutAMeshAndAnAngleOutOfRange) {
  EXPECT_EQ(error_of("s = gr.sphere('ball')\n\ns:set_smooth_normals(30)\n"),
            at(3) + "node:set_smooth_normals: 'ball' is not a mesh (gr.mesh or gr.extendedmesh)");
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(error_of("m = gr.mesh('m', 'tri.obj')\nm:set_smooth_normals(0)\n"),
            at(2) + "node:set_smooth_normals: max_angle_degrees must be more than 0 and at most 180, got the number 0");
  EXPECT_EQ(error_of("m = gr.mesh('m', 'tri.obj')\nm:set_smooth_normals(181)\n"),
            at(2) + "node:set_smooth_normals: max_angle_degrees must be more than 0 and at most 180, got the number 181");
  EXPECT_EQ(error_of("m = gr.mesh('m', 'tri.obj')\nm:set_smooth_normals('smooth')\n"),
            at(2) + "node:set_smooth_normals: argument 1 (max_angle_degrees) must be a number, got the string 'smooth'");
}

TEST_F(LuaExtensions, WrongArgumentsNameTheCallAndLine) {
  EXPECT_EQ(error_of("\nm = gr.reflectivematerial({1,1}, {1,1,1}, 10, 0.5)\n"),
            at(2) + "gr.reflectivematerial: argument 1 (kd) must be a table of 3 numbers, got a table of 2 values");
  EXPECT_EQ(error_of("m = gr.reflectivematerial({1,1,1}, {1,1,1}, 10, 1.5)\n"),
            at(1) + "gr.reflectivematerial: argument 4 (reflectivity) must be a number from 0 to 1, got the number 1.5");
  EXPECT_EQ(error_of("\n\nm = gr.refractedmaterial({0,0,0}, {1,1,1}, 10, 1.0, 0)\n"),
            at(3) + "gr.refractedmaterial: argument 5 (eta_t) must be a positive index of refraction, got the number 0");
  EXPECT_EQ(error_of("m = gr.fresneldiectricmaterial({0,0,0}, {1,1,1}, 10, 'glass', 1.5)\n"),
            at(1) + "gr.fresneldiectricmaterial: argument 4 (eta_i) must be a number, got the string 'glass'");
  EXPECT_EQ(error_of("m = gr.glossyreflectivematerial({0,0,0}, {1,1,1}, 10, 0.5, 2.5)\n"),
            at(1) + "gr.glossyreflectivematerial: argument 5 (samples) must be a whole number from 1 to 4096, got the number 2.5");
  EXPECT_EQ(error_of("l = gr.arealight({0,5,0}, {1,1,1}, {1,0,0}, {1,5,0}, {2,5,0})\n"),
            at(1) + "gr.arealight: the three corners lie on one line, so the light has no area");
  EXPECT_EQ(error_of("l = gr.arealight({0,5,0}, {1,1,1}, {1,0,0}, {1,5,0})\n"),
            at(1) + "gr.arealight: argument 5 (corner2) must be a table of 3 numbers, got nothing");
  EXPECT_EQ(error_of("\nm = gr.extendedmesh('m', true, 'quad.obj')\n"),
            at(2) + "gr.extendedmesh: argument 3 (mesh data) must be the result of read_extended_obj('file.obj'), or a "
                    "table of positions, normals, uvs and faces, got the string 'quad.obj'");
  EXPECT_EQ(error_of("\nm = gr.extendedmesh('m', true, {})\n"), at(2) + "gr.extendedmesh: the mesh needs a faces table");
  EXPECT_EQ(error_of("m = gr.extendedmesh('m', true, {positions = {{0,0,0},{1,0,0},{0,1,0}}, faces = {{0,1,3}}})\n"),
            at(1) + "gr.extendedmesh: face 1 corner 3 has position index 3 outside 0..2");
  EXPECT_EQ(error_of("m = gr.extendedmesh('m', true, {positions = {{0,0,0},{1,0,0},{0,1,0}}, faces = {{{0,0},1,2}}})\n"),
            at(1) + "gr.extendedmesh: face 1 corner 1 has uv index 0, but the mesh has no uvs");
  EXPECT_EQ(error_of("m = gr.extendedmesh('m', true, {positions = {{0,0,0},{1,0,0},{0,1,0}}, faces = {{{0,-2},1,2}}})\n"),
            at(1) + "gr.extendedmesh: face 1 corner 1 uv index must be 0 or more (-1 or nil: none), got -2");
  EXPECT_EQ(error_of("m = gr.extendedmesh('m', true, {positions = {{0,0,0},{1,0}}, faces = {{0,1,1}}})\n"),
            at(1) + "gr.extendedmesh: positions entry 2 must be a table of 3 numbers, got a table of 2 values");
  EXPECT_EQ(error_of("d = read_extended_obj('missing.obj')\n"), at(1) + "read_extended_obj: cannot find 'missing.obj' (looked in the scene's folder, its parent folders, "
                                                            "their Assets/ folders and the working directory)");
}

}  // namespace
}  // namespace mjray
