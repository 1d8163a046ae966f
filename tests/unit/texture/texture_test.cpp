// Textures: Perlin noise against the reference, the checkerboard's cell edges, the noise
// patterns' ranges, bilinear image lookup with wrapping, PNG and JPEG files, and solid
// textures that follow their objects through the World.

#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <jpeglib.h>

#include "mjray/integrator/whitted_integrator.h"
#include "mjray/accel/brute_force.h"
#include "mjray/camera/camera.h"
#include "mjray/core/error.h"
#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "mjray/render/image_render.h"
#include "mjray/scene/flatten.h"
#include "mjray/texture/perlin_noise.h"
#include "mjray/texture/texture.h"
#include "support/test_job.h"
#include "support/scene_builder.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

void expect_color_near(const Color& actual, const Color& expected, float tolerance, const std::string& where = "") {
  EXPECT_NEAR(actual.r, expected.r, tolerance) << where;
  EXPECT_NEAR(actual.g, expected.g, tolerance) << where;
  EXPECT_NEAR(actual.b, expected.b, tolerance) << where;
}

// --- Perlin noise ----------------------------------------------------------------------------

TEST(PerlinNoise, MatchesTheJavaReference) {
  // From scripts/perlin_reference.py, a separate Python transcription of Perlin's Java code
  // (noise(3.14, 42, 7) = 0.136919958784 is the value usually quoted for the reference).
  struct Case {
    double p[3];
    double noise;
  };
  const Case cases[] = {
      {{0.5, 0.5, 0.5}, -0.25},
      {{3.14, 42.0, 7.0}, 0.13691995878400012},
      {{0.1, 0.2, 0.3}, 0.35122924878110723},
      {{-1.25, 2.5, -3.75}, 0.3027210235595703},
      {{10.7, -20.3, 5.9}, 0.200197453861247},
      {{255.5, 256.5, -0.5}, -0.125},
      {{1000.123, -999.877, 0.001}, 0.119810844576176},
      {{-0.3, -0.7, -0.9}, -0.4138692340995841},
      {{0.25, 0.75, 0.125}, -0.07060389698017389},
      {{17.03, 4.41, 88.8}, 0.367153166659626},
      {{-123.456, 78.9, -0.01}, 0.33389399614236004},
      {{2.0, 3.5, 4.0}, -0.5},
  };
  for (const Case& c : cases)
    EXPECT_NEAR(perlin_noise(c.p[0], c.p[1], c.p[2]), c.noise, 1e-14)
        << "(" << c.p[0] << ", " << c.p[1] << ", " << c.p[2] << ")";
}

TEST(PerlinNoise, IsZeroAtIntegerLatticePoints) {
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y)
      for (int z = -3; z <= 3; ++z) EXPECT_EQ(perlin_noise(x, y, z), 0.0) << x << "," << y << "," << z;
  EXPECT_EQ(perlin_noise(256, -257, 1e6), 0.0);
}

TEST(PerlinNoise, RepeatsEvery256Units) {
  EXPECT_NEAR(perlin_noise(0.3 + 256, 0.6, -0.2), perlin_noise(0.3, 0.6, -0.2), 1e-12);
  EXPECT_NEAR(perlin_noise(0.3, 0.6 - 512, -0.2), perlin_noise(0.3, 0.6, -0.2), 1e-12);
  EXPECT_EQ(perlin_noise(0.5 + 256, 0.25, 0.75), perlin_noise(0.5, 0.25, 0.75));
}

TEST(PerlinNoise, NonFiniteInputGivesZero) {
  EXPECT_EQ(perlin_noise(NAN, 0.5, 0.5), 0.0);
  EXPECT_EQ(perlin_noise(0.5, INFINITY, 0.5), 0.0);
}

TEST(PerlinNoise, TurbulenceAndFractalSumHalvingOctaves) {
  const double x = 0.37, y = 1.91, z = -2.3;
  EXPECT_DOUBLE_EQ(perlin_turbulence(x, y, z, 1), std::abs(perlin_noise(x, y, z)));
  EXPECT_DOUBLE_EQ(perlin_turbulence(x, y, z, 2),
                   std::abs(perlin_noise(x, y, z)) + std::abs(perlin_noise(2 * x, 2 * y, 2 * z)) / 2);
  EXPECT_DOUBLE_EQ(perlin_fractal(x, y, z, 2), perlin_noise(x, y, z) + perlin_noise(2 * x, 2 * y, 2 * z) / 2);
}

// --- checkerboard ----------------------------------------------------------------------------

const Color kWhite(0.9f, 0.9f, 0.9f), kBlack(0.08f, 0.08f, 0.08f);

TEST(TextureCheckerboard, CellsAreOneOverTheScaleWide) {
  // Like every texture the point is multiplied by the scale: 0.5 gives 2-unit cells, and
  // 0.25 (below) 4-unit cells, as Perlin features grow when their scale shrinks.
  const CheckerboardTexture board{kWhite, kBlack, 0.5f};
  EXPECT_EQ(board.evaluate({0.5f, 0.5f, 0.5f}), kWhite);
  EXPECT_EQ(board.evaluate({1.9f, 1.9f, 1.9f}), kWhite);
  EXPECT_EQ(board.evaluate({2.5f, 0.5f, 0.5f}), kBlack);
  EXPECT_EQ(board.evaluate({0.5f, 2.5f, 0.5f}), kBlack);
  EXPECT_EQ(board.evaluate({2.5f, 2.5f, 0.5f}), kWhite);
  EXPECT_EQ(board.evaluate({-0.5f, 0.5f, 0.5f}), kBlack);
  EXPECT_EQ(board.evaluate({-2.5f, 0.5f, 0.5f}), kWhite);
  EXPECT_EQ(board.evaluate({-0.5f, -0.5f, -0.5f}), kBlack);
  const CheckerboardTexture coarse{kWhite, kBlack, 0.25f};
  EXPECT_EQ(coarse.evaluate({3.9f, 0.5f, 0.5f}), kWhite);
  EXPECT_EQ(coarse.evaluate({4.1f, 0.5f, 0.5f}), kBlack);
  EXPECT_EQ(coarse.evaluate({0.5f, 7.9f, 0.5f}), kBlack);
  EXPECT_EQ(coarse.evaluate({0.5f, 8.1f, 0.5f}), kWhite);
}

TEST(TextureCheckerboard, BothSidesOfACellEdge) {
  const CheckerboardTexture board{kWhite, kBlack, 0.5f};
  // Clearly on either side of x = 2: different cells.
  EXPECT_EQ(board.evaluate({1.99f, 0.5f, 0.5f}), kWhite);
  EXPECT_EQ(board.evaluate({2.01f, 0.5f, 0.5f}), kBlack);
  // Within rounding of x = 2 on either side: the + side's cell, so a face there is one colour.
  EXPECT_EQ(board.evaluate({2.0f, 0.5f, 0.5f}), kBlack);
  EXPECT_EQ(board.evaluate({std::nextafter(2.0f, 0.f), 0.5f, 0.5f}), kBlack);
  EXPECT_EQ(board.evaluate({2.0f - 1e-5f, 0.5f, 0.5f}), kBlack);
  // The same at y = 0, the usual floor plane.
  for (const float y : {0.f, -0.f, 1e-7f, -1e-7f, -1e-5f})
    EXPECT_EQ(board.evaluate({0.5f, y, 0.5f}), kWhite) << y;
  EXPECT_EQ(board.evaluate({0.5f, -0.01f, 0.5f}), kBlack);
}

TEST(TextureCheckerboard, NonFinitePointReadsColourOne) {
  const CheckerboardTexture board{kWhite, kBlack, 1};
  EXPECT_EQ(board.evaluate({NAN, 0.5f, 0.5f}), kWhite);
}

// --- Perlin textures -------------------------------------------------------------------------

PerlinTexture perlin(PerlinPattern pattern, float scale, float multiplier = 1) {
  return {pattern, Color(0.2f, 0.4f, 0.9f), Color(0.8f, 0.1f, 0.3f), scale, multiplier};
}

TEST(TexturePerlin, EveryPatternStaysBetweenItsColoursAndVaries) {
  const PerlinPattern patterns[] = {PerlinPattern::kLinear, PerlinPattern::kCosine, PerlinPattern::kMarble,
                                    PerlinPattern::kWavy, PerlinPattern::kWoodGrain};
  for (const PerlinPattern pattern : patterns) {
    const PerlinTexture texture = perlin(pattern, 1.7f, 2.5f);
    float lowest = 1, highest = 0;
    for (int i = 0; i < 4000; ++i) {
      // A scrambled walk through a 20-unit cube.
      const Point3 p(std::fmod(i * 0.7548776662f, 1.f) * 20 - 10, std::fmod(i * 0.5698402910f, 1.f) * 20 - 10,
                     std::fmod(i * 0.3141592653f, 1.f) * 20 - 10);
      const Color c = texture.evaluate(p);
      const std::string where = "pattern " + std::to_string(int(pattern)) + " at " + std::to_string(i);
      ASSERT_GE(c.r, 0.2f - 1e-6f) << where;
      ASSERT_LE(c.r, 0.8f + 1e-6f) << where;
      ASSERT_GE(c.g, 0.1f - 1e-6f) << where;
      ASSERT_LE(c.g, 0.4f + 1e-6f) << where;
      ASSERT_GE(c.b, 0.3f - 1e-6f) << where;
      ASSERT_LE(c.b, 0.9f + 1e-6f) << where;
      // Every colour lies on the segment between the two.
      const float w = (c.r - 0.2f) / 0.6f;
      ASSERT_NEAR(c.g, 0.4f - 0.3f * w, 1e-5f) << where;
      lowest = std::min(lowest, w);
      highest = std::max(highest, w);
    }
    EXPECT_LT(lowest, 0.25f) << int(pattern);
    EXPECT_GT(highest, 0.75f) << int(pattern);
  }
}

TEST(TexturePerlin, WoodGrainIsTheFractionOfTwentyTimesNoise) {
  const PerlinTexture wood = perlin(PerlinPattern::kWoodGrain, 0.5f);
  for (const Point3 p : {Point3(0.3f, 1.1f, -2.7f), Point3(5.5f, -0.25f, 3.3f), Point3(-7, 2.2f, 0.9f)}) {
    const double t = 20 * perlin_noise(double(p.x) * 0.5, double(p.y) * 0.5, double(p.z) * 0.5);
    EXPECT_NEAR(wood.weight(p), t - std::floor(t), 1e-9);
    // Cosine interpolation between the colours.
    const double w = (1 - std::cos(std::numbers::pi * (t - std::floor(t)))) / 2;
    EXPECT_NEAR(wood.evaluate(p).r, 0.2 + 0.6 * w, 1e-5);
  }
}

TEST(TexturePerlin, LinearAndCosineShareTheirWeightButNotTheirBlend) {
  const Point3 p(0.31f, 0.77f, -1.4f);
  const PerlinTexture linear = perlin(PerlinPattern::kLinear, 1), cosine = perlin(PerlinPattern::kCosine, 1);
  const double t = linear.weight(p);
  EXPECT_DOUBLE_EQ(cosine.weight(p), t);
  EXPECT_NEAR(linear.evaluate(p).r, 0.2 + 0.6 * t, 1e-6);
  EXPECT_NEAR(cosine.evaluate(p).r, 0.2 + 0.6 * (1 - std::cos(std::numbers::pi * t)) / 2, 1e-6);
}

TEST(TexturePerlin, ScaleIsAFrequency) {
  // scale 2 at p reads what scale 1 reads at 2p: the pattern looks half as large.
  for (const PerlinPattern pattern : {PerlinPattern::kMarble, PerlinPattern::kWoodGrain, PerlinPattern::kWavy}) {
    const Point3 p(0.3f, 1.25f, -0.75f), doubled(0.6f, 2.5f, -1.5f);
    EXPECT_NEAR(perlin(pattern, 2).weight(p), perlin(pattern, 1).weight(doubled), 1e-9) << int(pattern);
  }
}

TEST(TexturePerlin, WavyMultiplierScalesTheNoiseShift) {
  const Point3 p(0.3f, 1.25f, -0.75f);
  const double n = perlin_noise(0.3f, 1.25f, -0.75f);
  for (const float m : {0.f, 1.f, 4.f})
    EXPECT_NEAR(perlin(PerlinPattern::kWavy, 1, m).weight(p),
                0.5 + 0.5 * std::sin(2 * std::numbers::pi * (double(0.3f) + m * n)), 1e-9);
}

// --- image textures --------------------------------------------------------------------------

/// 2×2: red, green on the top row; blue, white on the bottom row.
ImageTexture two_by_two() {
  Image image(2, 2);
  image.at(0, 0) = {1, 0, 0};
  image.at(1, 0) = {0, 1, 0};
  image.at(0, 1) = {0, 0, 1};
  image.at(1, 1) = {1, 1, 1};
  return {image};
}

Color at_uv(const ImageTexture& t, float u, float v) { return t.evaluate({}, {u, v}); }

TEST(TextureImage, TexelCentresReadTheirTexelWithVUp) {
  const ImageTexture t = two_by_two();
  EXPECT_EQ(at_uv(t, 0.25f, 0.75f), Color(1, 0, 0));  // top left
  EXPECT_EQ(at_uv(t, 0.75f, 0.75f), Color(0, 1, 0));  // top right
  EXPECT_EQ(at_uv(t, 0.25f, 0.25f), Color(0, 0, 1));  // bottom left
  EXPECT_EQ(at_uv(t, 0.75f, 0.25f), Color(1, 1, 1));  // bottom right
}

TEST(TextureImage, BilinearBetweenTexelCentres) {
  const ImageTexture t = two_by_two();
  EXPECT_EQ(at_uv(t, 0.5f, 0.75f), Color(0.5f, 0.5f, 0));     // between the top two
  EXPECT_EQ(at_uv(t, 0.25f, 0.5f), Color(0.5f, 0, 0.5f));     // between the left two
  EXPECT_EQ(at_uv(t, 0.5f, 0.5f), Color(0.5f, 0.5f, 0.5f));   // all four
  EXPECT_EQ(at_uv(t, 0.375f, 0.75f), Color(0.75f, 0.25f, 0));  // a quarter of the way
}

TEST(TextureImage, RepeatsOutsideTheUnitSquare) {
  const ImageTexture t = two_by_two();
  EXPECT_EQ(at_uv(t, 1.25f, 0.75f), Color(1, 0, 0));
  EXPECT_EQ(at_uv(t, -0.75f, 0.75f), Color(1, 0, 0));
  EXPECT_EQ(at_uv(t, 0.25f, 2.25f), Color(0, 0, 1));
  // The edge u = 0 blends the last column with the first.
  EXPECT_EQ(at_uv(t, 0, 0.75f), Color(0.5f, 0.5f, 0));
  EXPECT_EQ(at_uv(t, 1, 0.75f), Color(0.5f, 0.5f, 0));
}

TEST(TextureImage, NonFiniteUvAndEmptyImageAreSafe) {
  EXPECT_EQ(at_uv(two_by_two(), NAN, 0.5f), at_uv(two_by_two(), 0, 0));
  EXPECT_EQ(at_uv(ImageTexture{}, 0.5f, 0.5f), Color());
}

/// Writes an 8-bit RGB (components 3) or grey (components 1) JPEG with libjpeg.
void write_jpeg(const fs::path& path, int width, int height, int components, const std::vector<unsigned char>& data) {
  FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  jpeg_compress_struct info{};
  jpeg_error_mgr error{};
  info.err = jpeg_std_error(&error);
  jpeg_create_compress(&info);
  jpeg_stdio_dest(&info, file);
  info.image_width = JDIMENSION(width);
  info.image_height = JDIMENSION(height);
  info.input_components = components;
  info.in_color_space = components == 3 ? JCS_RGB : JCS_GRAYSCALE;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, 100, TRUE);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    auto* row = const_cast<unsigned char*>(data.data() + size_t(info.next_scanline) * size_t(width * components));
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::fclose(file);
}

TEST(TextureImage, LoadsAPng) {
  const fs::path dir = test::make_temp_dir("texture");
  Image image(2, 2);
  image.at(0, 0) = {1, 0, 0};
  image.at(1, 0) = {0, 1, 0};
  image.at(0, 1) = {0, 0, 1};
  image.at(1, 1) = {51 / 255.f, 102 / 255.f, 153 / 255.f};
  write_image(image, dir / "t.png");
  const ImageTexture t{read_image(dir / "t.png")};
  EXPECT_EQ(at_uv(t, 0.25f, 0.75f), Color(1, 0, 0));
  EXPECT_EQ(at_uv(t, 0.75f, 0.25f), Color(0.2f, 0.4f, 0.6f));
}

TEST(TextureImage, LoadsAnRgbAndAGreyJpeg) {
  const fs::path dir = test::make_temp_dir("texture");
  // 16×16 in four flat 8×8 quadrants (JPEG's blocks), so that compression keeps each colour.
  const unsigned char quadrant[4][3] = {{200, 30, 30}, {30, 200, 30}, {30, 30, 200}, {220, 220, 220}};
  std::vector<unsigned char> rgb, grey;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const auto* q = quadrant[(y / 8) * 2 + x / 8];
      rgb.insert(rgb.end(), q, q + 3);
      grey.push_back(x < 8 ? 60 : 180);
    }
  write_jpeg(dir / "colour.jpg", 16, 16, 3, rgb);
  write_jpeg(dir / "grey.jpeg", 16, 16, 1, grey);
  const ImageTexture colour{read_image(dir / "colour.jpg")};
  ASSERT_EQ(colour.image.width(), 16);
  ASSERT_EQ(colour.image.height(), 16);
  const float tolerance = 6 / 255.f;
  expect_color_near(at_uv(colour, 0.25f, 0.75f), Color(200, 30, 30) / 255.f, tolerance, "top left");
  expect_color_near(at_uv(colour, 0.75f, 0.75f), Color(30, 200, 30) / 255.f, tolerance, "top right");
  expect_color_near(at_uv(colour, 0.25f, 0.25f), Color(30, 30, 200) / 255.f, tolerance, "bottom left");
  expect_color_near(at_uv(colour, 0.75f, 0.25f), Color(220, 220, 220) / 255.f, tolerance, "bottom right");
  const ImageTexture g{read_image(dir / "grey.jpeg")};
  expect_color_near(at_uv(g, 0.25f, 0.5f), Color(60, 60, 60) / 255.f, 2 / 255.f, "grey left");
  expect_color_near(at_uv(g, 0.75f, 0.5f), Color(180, 180, 180) / 255.f, 2 / 255.f, "grey right");
}

TEST(TextureImage, CorruptJpegIsAClearError) {
  const fs::path dir = test::make_temp_dir("texture");
  std::vector<unsigned char> rgb(16 * 16 * 3, 128);
  write_jpeg(dir / "whole.jpg", 16, 16, 3, rgb);
  // Keep the signature and cut the rest short.
  {
    std::FILE* in = std::fopen((dir / "whole.jpg").c_str(), "rb");
    ASSERT_NE(in, nullptr);
    unsigned char head[40];
    const size_t got = std::fread(head, 1, sizeof head, in);
    std::fclose(in);
    std::FILE* out = std::fopen((dir / "cut.jpg").c_str(), "wb");
    std::fwrite(head, 1, got, out);
    std::fclose(out);
  }
  try {
    read_image(dir / "cut.jpg");
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("cannot read '" + (dir / "cut.jpg").string() + "': libjpeg: ", 0), 0u)
        << e.what();
  }
}

// --- textures in the world -------------------------------------------------------------------

/// The texture colour the integrator would use where `ray` first meets `world`.
std::optional<Color> textured_kd(const World& world, const Ray& ray) {
  const BruteForce accel(world.primitives);
  const auto hit = accel.intersect(ray, {});
  if (!hit) return std::nullopt;
  const SurfaceInteraction si = world.interaction(ray, *hit);
  return phong_of(world.materials[si.material]).kd_at(si);
}

Material marble_material(TextureSpace space = TextureSpace::kObject) {
  PhongMaterial m{{1, 1, 1}, {0, 0, 0}, 1};
  m.texture = std::make_shared<const Texture>(
      PerlinTexture{PerlinPattern::kMarble, Color(1, 1, 1), Color(0.1f, 0.1f, 0.2f), 2.5f});
  m.texture_space = space;
  return m;
}

TEST(TextureWorld, SolidTexturesReadTheWorldPointByDefault) {
  // The same world point through a sphere placed two ways reads the same colour, the
  // texture's at that world point.
  const Material world_marble = marble_material(TextureSpace::kWorld);
  const Point3 target(2.2f, 1.1f, -0.4f);
  for (const Transform& world_from_node :
       {Transform(), Transform::translate({0.5f, -0.3f, 0.2f}) * Transform::rotate(2, 40) * Transform::scale(1.4f, 0.8f, 1)}) {
    RenderJob job;
    // A big sphere whose surface passes through the target.
    const Point3 node_target = world_from_node.inverse()(target);
    const Point3 centre = node_target + Vector3(0, -3, 0);
    job.root = test::group({test::sphere(centre, 3, world_marble)}, world_from_node);
    const World world = flatten(job);
    const Vector3 in = normalize(world_from_node(Vector3(0, -1, 0)));
    const auto kd = textured_kd(world, {target - in * 5, in});
    ASSERT_TRUE(kd);
    expect_color_near(*kd, std::get<PerlinTexture>(*phong_of(world_marble).texture).evaluate(target), 2e-3f);
  }
}

TEST(TextureWorld, ScaledCubeAndBoxOfTheSameExtentReadTheSameCheckerboard) {
  // The original's rule: a 4×1×4 slab as a scaled gr.cube and as an nh_box (cut to the same
  // top) show the same 4×4 cells of a 1-unit checkerboard, whatever their own frames.
  PhongMaterial m{{1, 1, 1}, {0, 0, 0}, 1};
  const CheckerboardTexture board{kWhite, kBlack, 1};
  m.texture = std::make_shared<const Texture>(board);
  auto cube = std::make_shared<SceneNode>();
  cube->name = "slab";
  cube->shape = UnitCube{};
  cube->material = std::make_shared<Material>(m);
  RenderJob scaled, boxed;
  scaled.root = test::group({cube}, Transform::translate({-2, -1, -2}) * Transform::scale(4, 1, 4));
  boxed.root = test::box({-2, -4, -2}, {2, 0, 2}, m);
  const World a = flatten(scaled), b = flatten(boxed);
  for (int i = 0; i < 16; ++i) {
    const Point3 target(-1.5f + float(i % 4), 0, -1.5f + float(i / 4));
    const Ray down{target + Vector3(0, 3, 0), {0, -1, 0}};
    const auto from_cube = textured_kd(a, down), from_box = textured_kd(b, down);
    ASSERT_TRUE(from_cube && from_box);
    EXPECT_EQ(*from_cube, *from_box) << target.x << "," << target.z;
    EXPECT_EQ(*from_cube, board.evaluate(target)) << target.x << "," << target.z;
  }
}

TEST(TextureWorld, ObjectSpaceTexturesMoveWithTheirObjects) {
  // An nh_sphere (centre (1, 2, 3), radius 2) under two different parent transforms, hit at
  // the same point of its node frame: (1, 2, 3) + 2·d for a unit d.
  const Vector3 d = normalize(Vector3(0.3f, 0.5f, 0.8f));
  const Point3 node_point = Point3(1, 2, 3) + d * 2;
  const Transform placements[] = {Transform(),
                                  Transform::translate({10, -4, 7}) * Transform::rotate(1, 35) * Transform::scale(3, 3, 3)};
  std::vector<Color> seen;
  for (const Transform& world_from_node : placements) {
    RenderJob job;
    job.root = test::group({test::sphere({1, 2, 3}, 2, marble_material())}, world_from_node);
    const World world = flatten(job);
    const Point3 target = world_from_node(node_point);
    const Vector3 outward = normalize(world_from_node(d));
    const auto kd = textured_kd(world, {target + outward * 5, -outward});
    ASSERT_TRUE(kd);
    seen.push_back(*kd);
  }
  expect_color_near(seen[1], seen[0], 2e-3f);
  // And the colour is the texture's at the node-frame point, not at the unit sphere's point.
  expect_color_near(seen[0], std::get<PerlinTexture>(*phong_of(marble_material()).texture).evaluate(node_point), 2e-3f);
}

TEST(TextureWorld, MeshTexturesMoveWithTheirMesh) {
  const Transform placements[] = {Transform(), Transform::translate({-3, 1, 2}) * Transform::rotate(0, 20)};
  std::vector<Color> seen;
  for (const Transform& world_from_node : placements) {
    RenderJob job;
    job.root = test::mesh(test::floor_quad(10), marble_material(), world_from_node);
    const World world = flatten(job);
    const Point3 target = world_from_node(Point3(1.3f, 0, -2.1f));
    const Vector3 up = normalize(world_from_node(Vector3(0, 1, 0)));
    const auto kd = textured_kd(world, {target + up * 3, -up});
    ASSERT_TRUE(kd);
    seen.push_back(*kd);
  }
  expect_color_near(seen[1], seen[0], 2e-3f);
}

TEST(TextureWorld, CheckerboardOnAScaledCubeFaceOnACellBoundaryDoesNotFlicker) {
  // A gr.cube scaled to a 40×2×40 floor whose top lies on y = 0, a cell boundary of the
  // world-space checkerboard: world hit points scatter across it by rounding, and every one
  // must read the cell above.
  PhongMaterial m{{0.9f, 0.9f, 0.9f}, {0, 0, 0}, 1};
  const CheckerboardTexture board{kWhite, kBlack, 1};
  m.texture = std::make_shared<const Texture>(board);
  auto cube = std::make_shared<SceneNode>();
  cube->name = "floor";
  cube->shape = UnitCube{};
  cube->material = std::make_shared<Material>(m);
  RenderJob job;
  job.root = test::group({cube}, Transform::translate({-20.3f, -2, -20.7f}) * Transform::rotate(1, 0) * Transform::scale(40, 2, 40));
  const World world = flatten(job);
  for (int i = 0; i < 400; ++i) {
    const float x = -15 + 0.0737f * float(i), z = 9 - 0.0417f * float(i);
    const Point3 target(x, 0, z);
    const Vector3 dir = normalize(Vector3(0.4f, -1, 0.3f + 0.001f * float(i)));
    const auto kd = textured_kd(world, {target - dir * 40, dir});
    ASSERT_TRUE(kd);
    EXPECT_EQ(*kd, board.evaluate({x, 0.5f, z})) << x << "," << z;
  }
}

TEST(TextureWorld, CheckerboardFloorOnACellBoundaryDoesNotFlicker) {
  // spheres.lua's floor: an nh_box whose top face is y = 0, with 2-unit cells.
  PhongMaterial m{{0.9f, 0.9f, 0.9f}, {0, 0, 0}, 1};
  const CheckerboardTexture board{kWhite, kBlack, 0.5f};
  m.texture = std::make_shared<const Texture>(board);
  RenderJob job;
  job.root = test::box({-200, -400, -200}, {200, 0, 200}, m);
  const World world = flatten(job);
  for (int i = 0; i < 200; ++i) {
    const float x = -15 + 0.1537f * float(i), z = 9 - 0.0917f * float(i);
    // Slanted rays, as a camera sees the floor.
    const Point3 target(x, 0, z);
    const Vector3 dir = normalize(Vector3(0.4f, -1, 0.3f + 0.001f * float(i)));
    const auto kd = textured_kd(world, {target - dir * 40, dir});
    ASSERT_TRUE(kd);
    EXPECT_EQ(*kd, board.evaluate({x, 1, z})) << x << "," << z;
  }
}

TEST(TextureShading, TextureReplacesKdForAmbientAndDiffuse) {
  // Looking straight down at a checkerboard floor (1-unit cells), ambient light only.
  PhongMaterial m{{0, 0, 0}, {0, 0, 0}, 1};
  const CheckerboardTexture board{Color(0.2f, 0.4f, 0.6f), Color(0.8f, 0.6f, 0.4f), 1};
  m.texture = std::make_shared<const Texture>(board);
  RenderJob job;
  job.width = job.height = 9;
  job.camera = {{0, 10, 0}, {0, -1, 0}, {0, 0, -1}, 60};
  job.root = test::mesh(test::floor_quad(100), m);
  job.ambient = {0.5f, 1, 1};
  job.lights = {PointLight{{0, 3, 0}, {0, 0, 0}, {1, 0, 0}}};
  const Image image = test::render(job);
  // Pixel centres land 1.28 units apart, clear of the cell edges; the centre one at the origin.
  const double half = std::tan(std::numbers::pi / 6) * 10;
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i) {
      const Point3 p(float((2 * (i + 0.5) / 9 - 1) * half), 0, float(-(1 - 2 * (j + 0.5) / 9) * half));
      expect_color_near(image.at(i, j), job.ambient * board.evaluate(p), 1e-6f,
                        std::to_string(i) + "," + std::to_string(j));
    }
  expect_color_near(image.at(4, 4), Color(0.1f, 0.4f, 0.6f), 1e-6f);
  expect_color_near(image.at(5, 4), Color(0.4f, 0.6f, 0.4f), 1e-6f);
  // A point light adds kd·cosθ·I with the texture's kd too.
  job.ambient = {0, 0, 0};
  job.lights = {PointLight{{0, 3, 0}, {1, 1, 1}, {1, 0, 0}}};
  const Image lit_image = test::render(job);
  expect_color_near(lit_image.at(4, 4), Color(0.2f, 0.4f, 0.6f), 1e-5f);
}

}  // namespace
}  // namespace mjray
