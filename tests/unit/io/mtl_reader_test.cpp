// MTL files as exporters write them, and the OBJ statements that name materials.

#include "mjray/io/mtl_reader.h"

#include <gtest/gtest.h>

#include "mjray/core/error.h"
#include "mjray/geometry/mesh_split.h"
#include "mjray/io/obj_loader.h"

namespace mjray {
namespace {

TEST(MtlReader, ReadsTheStatementsMjrayMapsThroughCommentsTabsAndLineEnds) {
  const auto materials = parse_mtl(
      "# exported\r\n"
      "newmtl red wall\r\n"
      "\tKa 0.1 0.1 0.1   # ambient: not read\r\n"
      "\tKd 0.63 0.065 0.05\r\n"
      "  Ks 0.5\n"
      "Ns 200\n"
      "Ke 17 12 4\n"
      "illum 2\n"
      "newmtl glass\n"
      "Ni 1.45\n"
      "d -halo 0.4\n"
      "Tf 0.9 1 0.9\n"
      "illum 7\n"
      "map_Kd -s 1 1 1 -o 0 0 0 textures/wood grain.png\n"
      "map_Bump bumps.png\n"
      "Pr 0.5\n",
      "room.mtl");
  ASSERT_EQ(materials.size(), 2u);
  const MtlMaterial& wall = materials[0];
  EXPECT_EQ(wall.name, "red wall");
  EXPECT_EQ(wall.line, 2);
  EXPECT_EQ(*wall.kd, Color(0.63f, 0.065f, 0.05f));
  EXPECT_EQ(*wall.ks, Color(0.5f, 0.5f, 0.5f));  // one value: a grey
  EXPECT_EQ(*wall.ns, 200);
  EXPECT_EQ(*wall.ke, Color(17, 12, 4));
  EXPECT_EQ(*wall.illum, 2);
  EXPECT_FALSE(wall.d);
  const MtlMaterial& glass = materials[1];
  EXPECT_EQ(*glass.ni, 1.45f);
  EXPECT_EQ(*glass.d, 0.4f);
  EXPECT_EQ(*glass.tf, Color(0.9f, 1, 0.9f));
  EXPECT_EQ(*glass.illum, 7);
  EXPECT_EQ(glass.map_kd->file, "grain.png");  // the last word: names with spaces are not read
  EXPECT_EQ(glass.map_kd->line, 14);
  EXPECT_EQ(glass.map_bump->file, "bumps.png");
}

TEST(MtlReader, MalformedValuesNameTheFileAndLine) {
  const auto error = [](const std::string& text) {
    try {
      parse_mtl(text, "m.mtl");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error("newmtl a\nKd 0.5 red 0.2\n"), "m.mtl:2: 'Kd' needs a number, found 'red'");
  EXPECT_EQ(error("Kd 1 1 1\n"), "m.mtl:1: 'Kd' before any newmtl");
  EXPECT_EQ(error("newmtl a\n\nNs\n"), "m.mtl:3: 'Ns' needs a number");
  EXPECT_EQ(error("newmtl a\nKd 0.5 0.2\n"), "m.mtl:2: 'Kd' needs 1 or 3 numbers, found 2");
  EXPECT_EQ(error("newmtl a\nillum 3e9\n"), "m.mtl:2: 'illum' needs a whole number from 0 to 10");
  EXPECT_EQ(error("newmtl\n"), "m.mtl:1: newmtl needs a material name");
  EXPECT_EQ(error("Ka 1 1 1\nfoo bar\n"), "(no error)");  // statements it does not map are passed over
}

TEST(MtlReader, SpectralAndXyzColoursAreWarnedOfAndPassedOver) {
  std::vector<std::string> warnings;
  const auto materials = parse_mtl("newmtl a\nKd 0.2 0.3 0.4\nKs spectral metal.rfl\nTf xyz 1 1 1\n", "m.mtl", &warnings);
  ASSERT_EQ(materials.size(), 1u);
  EXPECT_FALSE(materials[0].ks);
  EXPECT_FALSE(materials[0].tf);
  EXPECT_EQ(warnings, (std::vector<std::string>{"m.mtl:3: 'Ks spectral' colours are not read; give r g b",
                                                "m.mtl:4: 'Tf xyz' colours are not read; give r g b"}));
}

TEST(ObjMaterials, UsemtlNamesEachFaceAndMtllibNamesTheFiles) {
  const TriangleMesh mesh = parse_obj(
      "mtllib a.mtl b.mtl\n"
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "f 1 2 3\n"
      "usemtl red\n"
      "f 1 2 3 4\n"
      "usemtl green \t leaf\n"
      "f 2 3 4\n"
      "usemtl red\n"
      "f 1 3 4\n",
      "m.obj");
  ASSERT_EQ(mesh.material_libraries.size(), 2u);
  EXPECT_EQ(mesh.material_libraries[1].file, "b.mtl");
  EXPECT_EQ(mesh.material_libraries[1].line, 1);
  EXPECT_EQ(mesh.material_names, (std::vector<std::string>{"red", "green leaf"}));
  EXPECT_EQ(mesh.material_name_lines, (std::vector<int>{7, 9}));
  constexpr uint32_t kNone = TriangleMesh::kNoMaterial;
  EXPECT_EQ(mesh.triangle_materials, (std::vector<uint32_t>{kNone, 0, 0, 1, 0}));

  // Split: one mesh per material, in index order, faces without one last, vertices renumbered.
  const std::vector<MaterialPart> parts = split_by_material(mesh);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].material, 0u);
  EXPECT_EQ(parts[0].mesh.triangles.size(), 3u);
  EXPECT_EQ(parts[0].mesh.positions.size(), 4u);
  EXPECT_EQ(parts[1].material, 1u);
  ASSERT_EQ(parts[1].mesh.positions.size(), 3u);
  EXPECT_EQ(parts[1].mesh.positions[0], Point3(1, 0, 0));  // vertex 2 of the file, first used
  EXPECT_EQ(parts[1].mesh.triangles[0][0].position, 0);
  EXPECT_EQ(parts[2].material, kNone);
  EXPECT_EQ(parts[2].mesh.triangles.size(), 1u);

  // A file without usemtl has no names, and splits into itself.
  const TriangleMesh plain = parse_obj("mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "p.obj");
  EXPECT_TRUE(plain.triangle_materials.empty());
  EXPECT_EQ(split_by_material(plain).size(), 1u);
}

}  // namespace
}  // namespace mjray
