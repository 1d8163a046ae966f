#include "mjray/io/obj_loader.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/core/error.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

// Triangles as "p/t/n p/t/n p/t/n" (0-based, "-" when absent), so failures print readably.
std::vector<std::string> triangles_of(const TriangleMesh& mesh) {
  const auto field = [](int32_t i) { return i < 0 ? std::string("-") : std::to_string(i); };
  std::vector<std::string> result;
  for (const auto& triangle : mesh.triangles) {
    std::string text;
    for (const MeshCorner& c : triangle) {
      if (!text.empty()) text += ' ';
      text += field(c.position) + "/" + field(c.uv) + "/" + field(c.normal);
    }
    result.push_back(text);
  }
  return result;
}

std::array<float, 3> xyz(const Point3& p) { return {p.x, p.y, p.z}; }
std::array<float, 3> xyz(const Normal3& n) { return {n.x, n.y, n.z}; }
std::array<float, 2> uv(const Point2& p) { return {p.u, p.v}; }

// The SceneError message parse_obj throws for `text`, or "(no error)".
std::string parse_error(std::string_view text, const std::string& name = "test.obj") {
  try {
    parse_obj(text, name);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string load_error(const std::filesystem::path& path) {
  try {
    load_obj(path);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

void write_file(const std::filesystem::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

constexpr std::string_view kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
constexpr std::string_view kFivePositions = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n";

// --- statements and index forms --------------------------------------------------------------

TEST(ObjLoader, ParsesPositionsExactlyAndIgnoresWAndColours) {
  const TriangleMesh mesh = parse_obj(
      "v 1 2 3\nv -0.5 1e-3 +4.25\nv 0.1 0.2 0.3 1.0\nv 7 8 9 0.5 0.25 1\n", "p.obj");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{1, 2, 3}));
  EXPECT_EQ(xyz(mesh.positions[1]), (std::array<float, 3>{-0.5f, 1e-3f, 4.25f}));
  EXPECT_EQ(xyz(mesh.positions[2]), (std::array<float, 3>{0.1f, 0.2f, 0.3f}));
  EXPECT_EQ(xyz(mesh.positions[3]), (std::array<float, 3>{7, 8, 9}));
  EXPECT_TRUE(mesh.triangles.empty());
  EXPECT_EQ(mesh.polygon_count, 0u);
}

TEST(ObjLoader, PositionOnlyCorners) {
  const TriangleMesh mesh = parse_obj(std::string(kTriangle) + "f 3 1 2\n", "t.obj");
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"2/-/- 0/-/- 1/-/-"}));
  EXPECT_EQ(mesh.polygon_count, 1u);
}

TEST(ObjLoader, PositionUvCorners) {
  const TriangleMesh mesh =
      parse_obj(std::string(kTriangle) + "vt 0 0\nvt 1 0\nvt 0 1\nf 1/3 2/1 3/2\n", "t.obj");
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"0/2/- 1/0/- 2/1/-"}));
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_EQ(uv(mesh.uvs[2]), (std::array<float, 2>{0, 1}));
}

TEST(ObjLoader, PositionNormalCorners) {
  const TriangleMesh mesh =
      parse_obj(std::string(kTriangle) + "vn 0 0 1\nvn 0 0 -1\nf 1//2 2//1 3//2\n", "t.obj");
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"0/-/1 1/-/0 2/-/1"}));
  ASSERT_EQ(mesh.normals.size(), 2u);
  EXPECT_EQ(xyz(mesh.normals[1]), (std::array<float, 3>{0, 0, -1}));
}

TEST(ObjLoader, FullCorners) {
  const TriangleMesh mesh = parse_obj(
      std::string(kTriangle) + "vt 0 0\nvt 1 0\nvn 0 0 1\nf 1/1/1 2/2/1 3/1/1\n", "t.obj");
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"0/0/0 1/1/0 2/0/0"}));
}

TEST(ObjLoader, NegativeIndicesAreRelativeToTheElementsReadSoFar) {
  const TriangleMesh mesh = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
      "f -3 -2 -1\n"
      "v 0 0 1\n"
      "f -4 -1 -2\n"
      "vt 0 0\nvt 1 1\nvn 0 0 1\n"
      "f -2/-1/-1 -3/-2/-1 -1/-1/-1\n",
      "neg.obj");
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{
                                    "0/-/- 1/-/- 2/-/-",
                                    "0/-/- 3/-/- 2/-/-",
                                    "2/1/0 1/0/0 3/1/0",
                                }));
}

TEST(ObjLoader, QuadIsFanTriangulated) {
  const TriangleMesh mesh = parse_obj(std::string(kFivePositions) + "f 2 3 4 5\n", "q.obj");
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"1/-/- 2/-/- 3/-/-",
                                                          "1/-/- 3/-/- 4/-/-"}));
  EXPECT_EQ(mesh.polygon_count, 1u);
}

TEST(ObjLoader, PentagonIsFanTriangulatedFromItsFirstCorner) {
  const TriangleMesh mesh = parse_obj(std::string(kFivePositions) +
                                     "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                     "f 5/1 4/2 3/3 2/4 1/5\n",
                                 "pent.obj");
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{
                                    "4/0/- 3/1/- 2/2/-",
                                    "4/0/- 2/2/- 1/3/-",
                                    "4/0/- 1/3/- 0/4/-",
                                }));
  EXPECT_EQ(mesh.polygon_count, 1u);
}

TEST(ObjLoader, PolygonCountIsFacesBeforeTriangulation) {
  const TriangleMesh mesh = parse_obj(std::string(kFivePositions) +
                                     "f 1 2 3\nf 1 2 3 4\nf 1 2 3 4 5\nfo 5 4 3 2 1\n",
                                 "n.obj");
  EXPECT_EQ(mesh.polygon_count, 4u);
  EXPECT_EQ(mesh.triangles.size(), 1u + 2u + 3u + 3u);
}

TEST(ObjLoader, TextureCoordinatesKeepUAndVOnly) {
  const TriangleMesh mesh = parse_obj("vt 0.25 0.75 0.5\nvt 0.5\nvt -1.5 2e1 \n", "vt.obj");
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_EQ(uv(mesh.uvs[0]), (std::array<float, 2>{0.25f, 0.75f}));
  EXPECT_EQ(uv(mesh.uvs[1]), (std::array<float, 2>{0.5f, 0.0f}));
  EXPECT_EQ(uv(mesh.uvs[2]), (std::array<float, 2>{-1.5f, 20.0f}));
}

// --- layout: line endings, comments, whitespace, skipped statements --------------------------

TEST(ObjLoader, CrlfAndLoneCrParseLikeLf) {
  const std::string lf = "v 1 2 3\nv 4 5 6\nv 7 8 9\nvn 0 1 0\nf 1//1 2//1 3//1\n";
  const std::string crlf = "v 1 2 3\r\nv 4 5 6\r\nv 7 8 9\r\nvn 0 1 0\r\nf 1//1 2//1 3//1\r\n";
  const std::string cr = "v 1 2 3\rv 4 5 6\rv 7 8 9\rvn 0 1 0\rf 1//1 2//1 3//1\r";
  for (const std::string& text : {crlf, cr}) {
    const TriangleMesh mesh = parse_obj(text, "crlf.obj");
    ASSERT_EQ(mesh.positions.size(), 3u);
    EXPECT_EQ(xyz(mesh.positions[2]), (std::array<float, 3>{7, 8, 9}));
    EXPECT_EQ(triangles_of(mesh), triangles_of(parse_obj(lf, "lf.obj")));
  }
}

TEST(ObjLoader, CommentsBlankLinesTabsAndUnknownStatementsAreSkipped) {
  const TriangleMesh mesh = parse_obj(
      "# header comment\n"
      "  # indented comment\n"
      "#v 9 9 9\n"
      "\n"
      "   \t \n"
      "mtllib scene.mtl\n"
      "o thing\n"
      "g group one\n"
      "usemtl red\n"
      "s off\n"
      "v\t1\t2\t3\t\n"
      "  v 4 5 6   \n"
      "v 7 8 9 # trailing comment\n"
      "vp 0.5 0.5\n"
      "cstype bezier\n"
      "l 1 2\n"
      "p 3\n"
      "frobnicate 1 2 3\n"
      "f 1 2 3 # a triangle\n"
      "\tf\t3 2 1\t\r\n"
      "#f 1 1 1\n",
      "skip.obj");
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{1, 2, 3}));
  EXPECT_EQ(xyz(mesh.positions[1]), (std::array<float, 3>{4, 5, 6}));
  EXPECT_EQ(xyz(mesh.positions[2]), (std::array<float, 3>{7, 8, 9}));
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"0/-/- 1/-/- 2/-/-",
                                                          "2/-/- 1/-/- 0/-/-"}));
  EXPECT_EQ(mesh.polygon_count, 2u);
  EXPECT_TRUE(mesh.normals.empty());
  EXPECT_TRUE(mesh.uvs.empty());
}

TEST(ObjLoader, BackslashContinuesAStatement) {
  const TriangleMesh mesh = parse_obj(
      "v 1 \\\n 2 3\n"
      "v 4 5 \\\r\n6\n"
      "v 7 8 9\n"
      "g a \\\n b\n"
      "f 1 2 \\\n  3\n",
      "cont.obj");
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{1, 2, 3}));
  EXPECT_EQ(xyz(mesh.positions[1]), (std::array<float, 3>{4, 5, 6}));
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"0/-/- 1/-/- 2/-/-"}));
}

TEST(ObjLoader, EmptyTextAndMissingFinalNewlineAndByteOrderMark) {
  EXPECT_TRUE(parse_obj("", "empty.obj").positions.empty());
  const TriangleMesh mesh = parse_obj("\xEF\xBB\xBFv 1 2 3\nv 4 5 6\nv 7 8 9\nf 1 2 3", "bom.obj");
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"0/-/- 1/-/- 2/-/-"}));
}

TEST(ObjLoader, UnderflowingCoordinateRoundsToZero) {
  const TriangleMesh mesh = parse_obj("v 1e-50 -1e-400 2.5\n", "tiny.obj");
  ASSERT_EQ(mesh.positions.size(), 1u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{0, 0, 2.5f}));
}

// --- errors: each names the source and the 1-based line ---------------------------------------

TEST(ObjLoader, FaceWithFewerThanThreeCornersIsAnError) {
  EXPECT_EQ(parse_error(std::string(kTriangle) + "f 1 2\n", "two.obj"),
            "two.obj:4: face needs at least 3 corners, found 2");
  EXPECT_EQ(parse_error(std::string(kTriangle) + "\nf # nothing\n", "none.obj"),
            "none.obj:5: face needs at least 3 corners, found 0");
}

TEST(ObjLoader, IndexOutOfRangeIsAnError) {
  EXPECT_EQ(parse_error(std::string(kFivePositions) + "f 1 2 7\n", "m.obj"),
            "m.obj:6: face index 7 out of range (5 positions)");
  EXPECT_EQ(parse_error(std::string(kFivePositions) + "f -1 -2 -6\n", "m.obj"),
            "m.obj:6: face index -6 out of range (5 positions)");
  EXPECT_EQ(parse_error(std::string(kTriangle) + "vt 0 0\nvt 1 1\nf 1/1 2/2 3/3\n", "uv.obj"),
            "uv.obj:6: face index 3 out of range (2 texture coordinates)");
  EXPECT_EQ(parse_error(std::string(kTriangle) + "vn 0 0 1\nf 1//1 2//1 3//2\n", "n.obj"),
            "n.obj:5: face index 2 out of range (1 normal)");
  EXPECT_EQ(parse_error("f 1 2 3\n", "early.obj"),
            "early.obj:1: face index 1 out of range (0 positions)");
}

TEST(ObjLoader, ZeroIndexIsAnError) {
  EXPECT_EQ(parse_error(std::string(kTriangle) + "f 0 1 2\n", "zero.obj"),
            "zero.obj:4: face index 0 is invalid (OBJ indices start at 1)");
}

TEST(ObjLoader, HugeIndexIsAnErrorNotAnOverflow) {
  EXPECT_EQ(parse_error(std::string(kTriangle) + "f 1 2 99999999999999999999\n", "big.obj"),
            "big.obj:4: face index 99999999999999999999 out of range (3 positions)");
  EXPECT_EQ(parse_error(std::string(kTriangle) + "f 1 2 2147483648\n", "big.obj"),
            "big.obj:4: face index 2147483648 out of range (3 positions)");
  EXPECT_EQ(parse_error(std::string(kTriangle) + "f 1 2 -2147483648\n", "big.obj"),
            "big.obj:4: face index -2147483648 out of range (3 positions)");
}

TEST(ObjLoader, MalformedCornerIsAnError) {
  const std::string prefix = std::string(kTriangle) + "vt 0 0\nvn 0 0 1\n";
  EXPECT_EQ(parse_error(prefix + "f 1 2 3x\n", "c.obj"), "c.obj:6: bad face corner '3x'");
  EXPECT_EQ(parse_error(prefix + "f 1/a 2 3\n", "c.obj"), "c.obj:6: bad face corner '1/a'");
  EXPECT_EQ(parse_error(prefix + "f 1/1/1/1 2 3\n", "c.obj"),
            "c.obj:6: bad face corner '1/1/1/1'");
  EXPECT_EQ(parse_error(prefix + "f one 2 3\n", "c.obj"), "c.obj:6: bad face corner 'one'");
  EXPECT_EQ(parse_error(prefix + "f 1 +2 3\n", "c.obj"), "c.obj:6: bad face corner '+2'");
}

TEST(ObjLoader, NonNumericCoordinateIsAnError) {
  EXPECT_EQ(parse_error("v 0 0 0\nv 1 abc 3\n", "bad.obj"),
            "bad.obj:2: v coordinate 'abc' is not a number");
  EXPECT_EQ(parse_error("vn 1 2 3x\n", "bad.obj"), "bad.obj:1: vn coordinate '3x' is not a number");
  EXPECT_EQ(parse_error("# c\nvt 0.5 v\n", "bad.obj"),
            "bad.obj:2: vt coordinate 'v' is not a number");
  EXPECT_EQ(parse_error("v 1,5 2 3\n", "bad.obj"), "bad.obj:1: v coordinate '1,5' is not a number");
}

TEST(ObjLoader, MissingCoordinateIsAnError) {
  EXPECT_EQ(parse_error("v 1 2\n", "few.obj"), "few.obj:1: v needs 3 coordinates, found 2");
  EXPECT_EQ(parse_error("v 1 2 # 3\n", "few.obj"), "few.obj:1: v needs 3 coordinates, found 2");
  EXPECT_EQ(parse_error("\nvn\n", "few.obj"), "few.obj:2: vn needs 3 coordinates, found 0");
  EXPECT_EQ(parse_error("vt\n", "few.obj"), "few.obj:1: vt needs at least 1 coordinate, found 0");
}

TEST(ObjLoader, NonFiniteOrOverflowingCoordinateIsAnError) {
  EXPECT_EQ(parse_error("v nan 0 0\n", "inf.obj"), "inf.obj:1: v coordinate 'nan' is not finite");
  EXPECT_EQ(parse_error("v 0 -inf 0\n", "inf.obj"),
            "inf.obj:1: v coordinate '-inf' is not finite");
  EXPECT_EQ(parse_error("v 0 0 1e39\n", "inf.obj"),
            "inf.obj:1: v coordinate '1e39' is out of range");
  EXPECT_EQ(parse_error("v 0 0 1e999\n", "inf.obj"),
            "inf.obj:1: v coordinate '1e999' is out of range");
}

TEST(ObjLoader, ErrorLinesCountEveryKindOfLineEnd) {
  EXPECT_EQ(parse_error("# a\r\n\r\nv 1 2 3\r\nv x 2 3\r\n", "crlf.obj"),
            "crlf.obj:4: v coordinate 'x' is not a number");
  EXPECT_EQ(parse_error("# a\r\rv 1 2 3\rv x 2 3\r", "cr.obj"),
            "cr.obj:4: v coordinate 'x' is not a number");
  EXPECT_EQ(parse_error("v 1 \\\n 2 3\ng a \\\n b\nv 1 2 \\\n x\n", "cont.obj"),
            "cont.obj:6: v coordinate 'x' is not a number");
}

// --- files ---------------------------------------------------------------------------------

TEST(ObjLoader, MissingFileErrorNamesTheFile) {
  const auto path = test::make_temp_dir("obj-missing") / "no_such_mesh.obj";
  EXPECT_EQ(load_error(path),
            path.string() + ": cannot open OBJ file: No such file or directory");
}

TEST(ObjLoader, DirectoryIsAnErrorNamingIt) {
  const auto dir = test::make_temp_dir("obj-dir");
  EXPECT_EQ(load_error(dir), dir.string() + ": cannot read OBJ file: Is a directory");
}

TEST(ObjLoader, LoadsAFileAndNamesItInErrors) {
  const auto dir = test::make_temp_dir("obj-file");
  write_file(dir / "good.obj", "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf -4 -3 -2 -1\r\n");
  const TriangleMesh mesh = load_obj(dir / "good.obj");
  EXPECT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(triangles_of(mesh), (std::vector<std::string>{"0/-/- 1/-/- 2/-/-",
                                                          "0/-/- 2/-/- 3/-/-"}));

  write_file(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n");
  EXPECT_EQ(load_error(dir / "bad.obj"),
            (dir / "bad.obj").string() + ":4: face index 4 out of range (3 positions)");
}

TEST(ObjLoader, AFileReadInPiecesOfAnySizeGivesTheMeshAndLinesOfTheWholeText) {
  // Every kind of line end, continued statements, a comment ending in a backslash, a line
  // longer than most pieces and a byte-order mark: each may fall on a piece's edge.
  std::string text = "\xEF\xBB\xBFv 0 0 0\r\nv 1 0 0\rv 1 1 0\nv 0 1 \\\r\n  0.5\n# a comment \\\n";
  text += "vt 0.25 0.75\r\nvn 0 0 1\rf 1/1/1 2/1/1 \\ \n 3/1/1 4/1/1\r\n\n\n";
  for (int i = 0; i < 40; ++i) text += "v " + std::to_string(i) + " 2 3\r\nf -1 \\\r\n-2 -3\n";
  text += "# " + std::string(300, 'x') + "\n";
  const TriangleMesh whole = parse_obj(text, "t.obj");
  ASSERT_EQ(whole.positions.size(), 44u);
  ASSERT_EQ(whole.triangles.size(), 42u);
  const std::string bad = text + "v 1 2 3\nf 1 2 x\n";
  const std::string bad_error = parse_error(bad, "t.obj");
  ASSERT_EQ(bad_error, "t.obj:135: bad face corner 'x'");

  const auto dir = test::make_temp_dir("obj-pieces");
  write_file(dir / "t.obj", text);
  write_file(dir / "bad.obj", bad);
  for (const size_t piece : {size_t(1), size_t(2), size_t(3), size_t(5), size_t(7), size_t(16), size_t(33), size_t(64),
                             size_t(301), size_t(1000), kObjPieceBytes}) {
    ObjSummary summary;
    const TriangleMesh mesh = load_obj(dir / "t.obj", &summary, piece);
    ASSERT_EQ(mesh.positions.size(), whole.positions.size()) << piece;
    for (size_t i = 0; i < mesh.positions.size(); ++i) EXPECT_EQ(xyz(mesh.positions[i]), xyz(whole.positions[i])) << piece;
    EXPECT_EQ(triangles_of(mesh), triangles_of(whole)) << piece;
    EXPECT_EQ(mesh.uvs.size(), 1u) << piece;
    EXPECT_EQ(mesh.normals.size(), 1u) << piece;
    EXPECT_EQ(mesh.polygon_count, whole.polygon_count) << piece;
    EXPECT_EQ(summary.statements, 87u) << piece;
    EXPECT_EQ(summary.unknown_statements, 0u) << piece;
    try {
      load_obj(dir / "bad.obj", nullptr, piece);
      ADD_FAILURE() << piece;
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()), (dir / "bad.obj").string() + bad_error.substr(5)) << piece;
    }
  }
  std::filesystem::remove_all(dir);
}

// --- the shared test meshes (../shared/models, facts from SOURCES.md) -----------------------

TEST(ObjLoader, CornellBoxOriginalCrlfNegativeQuads) {
  MJRAY_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load_obj(shared / "models/small/cornell/CornellBox-Original.obj");
  EXPECT_EQ(mesh.positions.size(), 72u);
  EXPECT_EQ(mesh.polygon_count, 18u);
  ASSERT_EQ(mesh.triangles.size(), 36u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{-1.01f, 0.0f, 0.99f}));
  EXPECT_EQ(xyz(mesh.positions[71]), (std::array<float, 3>{0.23f, 1.98f, 0.16f}));  // tabs
  const auto triangles = triangles_of(mesh);
  EXPECT_EQ(triangles[0], "0/-/- 1/-/- 2/-/-");
  EXPECT_EQ(triangles[1], "0/-/- 2/-/- 3/-/-");
  EXPECT_EQ(triangles[35], "68/-/- 70/-/- 71/-/-");
}

TEST(ObjLoader, CornellBoxEmbree) {
  MJRAY_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load_obj(shared / "models/small/cornell/cornell_box.obj");
  EXPECT_EQ(mesh.positions.size(), 76u);
  EXPECT_EQ(mesh.polygon_count, 18u);
  ASSERT_EQ(mesh.triangles.size(), 36u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{552.8f, 0.0f, 0.0f}));
  const auto triangles = triangles_of(mesh);
  EXPECT_EQ(triangles[0], "0/-/- 1/-/- 2/-/-");
  EXPECT_EQ(triangles[1], "0/-/- 2/-/- 3/-/-");
  EXPECT_EQ(triangles[35], "72/-/- 74/-/- 75/-/-");
}

TEST(ObjLoader, SuzanneQuadsWithNormals) {
  MJRAY_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load_obj(shared / "models/medium/suzanne.obj");
  EXPECT_EQ(mesh.positions.size(), 507u);
  EXPECT_EQ(mesh.normals.size(), 507u);
  EXPECT_EQ(mesh.polygon_count, 500u);
  ASSERT_EQ(mesh.triangles.size(), 968u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{-2.056562f, 1.415748f, 4.869517f}));
  EXPECT_EQ(xyz(mesh.normals[0]), (std::array<float, 3>{0.744549f, -0.641131f, 0.186007f}));
  const auto triangles = triangles_of(mesh);
  EXPECT_EQ(triangles[0], "0/-/0 2/-/2 44/-/44");
  EXPECT_EQ(triangles[1], "0/-/0 44/-/44 46/-/46");
}

TEST(ObjLoader, SpotControlMeshPentagonsWithUvs) {
  MJRAY_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load_obj(shared / "models/small/spot/spot_control_mesh.obj");
  EXPECT_EQ(mesh.positions.size(), 188u);
  EXPECT_EQ(mesh.uvs.size(), 267u);
  EXPECT_EQ(mesh.polygon_count, 180u);
  ASSERT_EQ(mesh.triangles.size(), 372u);
  EXPECT_EQ(uv(mesh.uvs[0]), (std::array<float, 2>{0.789172f, 0.670062f}));
  // Face 37 (line 492) is the first pentagon: "f 38/43 51/60 53/61 36/38 37/37".
  const auto triangles = triangles_of(mesh);
  EXPECT_EQ(triangles[72], "37/42/- 50/59/- 52/60/-");
  EXPECT_EQ(triangles[73], "37/42/- 52/60/- 35/37/-");
  EXPECT_EQ(triangles[74], "37/42/- 35/37/- 36/36/-");
}

TEST(ObjLoader, SponzaThreeComponentUvs) {
  MJRAY_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load_obj(shared / "models/large/sponza/sponza.obj");
  EXPECT_EQ(mesh.positions.size(), 39999u);
  EXPECT_EQ(mesh.normals.size(), 39999u);
  EXPECT_EQ(mesh.uvs.size(), 71396u);
  EXPECT_EQ(mesh.polygon_count, 66454u);
  ASSERT_EQ(mesh.triangles.size(), 66454u);
  EXPECT_EQ(uv(mesh.uvs[0]), (std::array<float, 2>{0.036923f, 1.0f}));  // "vt  0.036923 1 0"
  EXPECT_EQ(xyz(mesh.normals[0]), (std::array<float, 3>{-1, 0, 0}));
  EXPECT_EQ(triangles_of(mesh)[0], "0/0/0 1/1/1 2/2/2");
}

TEST(ObjLoader, Venus43kCrlfWithSplitNormals) {
  MJRAY_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load_obj(shared / "models/medium/venus_43k.obj");
  EXPECT_EQ(mesh.positions.size(), 19847u);
  EXPECT_EQ(mesh.normals.size(), 22155u);
  ASSERT_EQ(mesh.triangles.size(), 43357u);
  EXPECT_EQ(xyz(mesh.normals[0]), (std::array<float, 3>{-0.999890f, 0.014212f, 0.004264f}));
  EXPECT_EQ(triangles_of(mesh).back(), "15524/-/15722 13150/-/15566 14143/-/16066");
}

TEST(ObjLoader, FullResolutionDragon) {
  MJRAY_REQUIRE_SHARED(shared);
  const TriangleMesh mesh = load_obj(shared / "models/large/dragon_vrip.obj");
  EXPECT_EQ(mesh.positions.size(), 437645u);
  EXPECT_EQ(mesh.polygon_count, 871414u);
  ASSERT_EQ(mesh.triangles.size(), 871414u);
  EXPECT_EQ(xyz(mesh.positions[0]), (std::array<float, 3>{0.032027f, 0.056575f, -0.0503644f}));
  EXPECT_EQ(triangles_of(mesh).back(), "435598/-/- 435560/-/- 435559/-/-");
}

// Every mesh in SOURCES.md: counts, and the bounding box its table gives to 4 decimals.
TEST(ObjLoader, AllSharedModelsMatchSources) {
  MJRAY_REQUIRE_SHARED(shared);
  struct Expected {
    const char* file;
    size_t positions, polygons, triangles, normals, uvs;
    std::array<float, 3> lo, hi;
  };
  const Expected table[] = {
      {"small/teapot.obj", 3644, 6320, 6320, 0, 0, {-3.0f, 0.0f, -2.0f}, {3.434f, 3.15f, 2.0f}},
      {"small/teapot_bezier16.obj", 9248, 16256, 16256, 9248, 9248, {-3.0f, 0.0f, -2.0f},
       {3.4335f, 3.15f, 2.0f}},
      {"small/teapot_low_npm.obj", 792, 992, 992, 0, 0, {-16.0703f, -7.875f, -10.0f},
       {16.0703f, 7.875f, 10.0f}},
      {"small/bunny_low_npm.obj", 1839, 3674, 3674, 0, 0, {-4.9585f, -0.0031f, -3.7298f},
       {4.9488f, 9.6547f, 3.8106f}},
      {"small/bunny_low_vn.obj", 3301, 6598, 6598, 6598, 0, {-0.7757f, -0.7689f, -0.5971f},
       {0.7762f, 0.767f, 0.5991f}},
      {"small/bunny.obj", 35947, 69451, 69451, 0, 0, {-0.0947f, 0.033f, -0.0619f},
       {0.061f, 0.1873f, 0.0588f}},
      {"small/spot/spot_triangulated.obj", 2930, 5856, 5856, 0, 3225,
       {-0.4716f, -0.7368f, -0.6689f}, {0.4716f, 0.9536f, 1.049f}},
      {"small/spot/spot_quadrangulated.obj", 2930, 2928, 5856, 0, 3225,
       {-0.4716f, -0.7368f, -0.6689f}, {0.4716f, 0.9536f, 1.049f}},
      {"small/spot/spot_control_mesh.obj", 188, 180, 372, 0, 267, {-0.586f, -0.7591f, -0.6962f},
       {0.586f, 0.984f, 1.0778f}},
      {"small/cornell/CornellBox-Original.obj", 72, 18, 36, 0, 0, {-1.02f, 0.0f, -1.04f},
       {1.0f, 1.99f, 0.99f}},
      {"small/cornell/cornell_box.obj", 76, 18, 36, 0, 0, {0.0f, 0.0f, 0.0f},
       {556.0f, 548.8f, 559.2f}},
      {"medium/armadillo.obj", 14587, 29170, 29170, 0, 0, {-0.4344f, -0.5716f, -0.3748f},
       {0.4031f, 0.4263f, 0.378f}},
      {"medium/dragon_vrip_res4.obj", 5205, 11102, 11102, 0, 0, {-0.1076f, 0.0528f, -0.0498f},
       {0.0952f, 0.1963f, 0.0408f}},
      {"medium/dragon_vrip_res3.obj", 22998, 47794, 47794, 0, 0, {-0.1077f, 0.0528f, -0.0501f},
       {0.096f, 0.1966f, 0.0408f}},
      {"medium/suzanne.obj", 507, 500, 968, 507, 0, {-3.8612f, 0.2673f, 3.2523f},
       {-1.1269f, 2.2361f, 4.9555f}},
      {"medium/venus/venus.obj", 759, 1492, 1492, 946, 758, {-3.853f, -2.839f, -7.952f},
       {3.823f, 2.736f, 7.698f}},
      {"medium/venus_43k.obj", 19847, 43357, 43357, 22155, 0, {-658.3528f, -848.7864f, -848.6679f},
       {659.6111f, 3717.4912f, 474.8859f}},
      {"large/dragon_vrip_res2.obj", 100250, 202520, 202520, 0, 0, {-0.1082f, 0.0527f, -0.0503f},
       {0.0964f, 0.1971f, 0.0411f}},
      {"large/dragon_vrip.obj", 437645, 871414, 871414, 0, 0, {-0.1083f, 0.0527f, -0.0504f},
       {0.0966f, 0.1972f, 0.0412f}},
      {"large/lucy.obj", 49987, 99970, 99970, 0, 0, {225.906f, -605.89f, -145.348f},
       {1156.03f, 991.332f, 388.421f}},
      {"large/happy_buddha.obj", 49950, 100000, 100000, 0, 0, {-0.461f, -1.0022f, -0.3239f},
       {0.3522f, 0.9775f, 0.4902f}},
      {"large/sponza/sponza.obj", 39999, 66454, 66454, 39999, 71396,
       {-17.4028f, -0.9067f, -7.7985f}, {17.4172f, 15.6533f, 7.8015f}},
  };
  for (const Expected& e : table) {
    SCOPED_TRACE(e.file);
    const TriangleMesh mesh = load_obj(shared / "models" / e.file);
    EXPECT_EQ(mesh.positions.size(), e.positions);
    EXPECT_EQ(mesh.polygon_count, e.polygons);
    EXPECT_EQ(mesh.triangles.size(), e.triangles);
    EXPECT_EQ(mesh.normals.size(), e.normals);
    EXPECT_EQ(mesh.uvs.size(), e.uvs);
    ASSERT_FALSE(mesh.positions.empty());
    Point3 lo = mesh.positions[0], hi = mesh.positions[0];
    for (const Point3& p : mesh.positions) {
      lo = min(lo, p);
      hi = max(hi, p);
    }
    for (int axis = 0; axis < 3; ++axis) {
      // Rounding to 4 decimals, plus half a float ulp for both the file's and the table's value.
      const auto tolerance = [](float x) { return 5.01e-5f + 1.2e-7f * std::abs(x); };
      EXPECT_NEAR(lo[axis], e.lo[axis], tolerance(e.lo[axis])) << "axis " << axis;
      EXPECT_NEAR(hi[axis], e.hi[axis], tolerance(e.hi[axis])) << "axis " << axis;
    }
  }
}

}  // namespace
}  // namespace mjray
