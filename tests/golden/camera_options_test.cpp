// --spp, --size, --crop, the lens and the output formats through renders and the program: the
// same image for any thread count, a crop that is exactly its window of the whole image
// (anti-aliasing included), a resolution change that keeps the camera, and EXR, 16-bit PNG,
// PNG and JPEG written from the same film.

#include <ImfFloatAttribute.h>
#include <ImfRgbaFile.h>

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "mjray/io/image_reader.h"
#include "mjray/render/image_render.h"
#include "support/program_run.h"
#include "support/scene_builder.h"
#include "support/scratch_files.h"
#include "support/test_job.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

/// Spheres over a floor under an area light: edges for anti-aliasing, a penumbra for --spp.
RenderJob edge_scene(int width, int height) {
  RenderJob job;
  std::vector<std::shared_ptr<const SceneNode>> nodes = {test::mesh(test::floor_quad(20))};
  for (int i = 0; i < 5; ++i)
    nodes.push_back(test::sphere({float(i) * 1.1f - 2.2f, 0.5f, -float(i % 2)}, 0.5f,
                                 PhongMaterial{{0.9f, 0.3f + 0.1f * float(i), 0.2f}, {0.5f, 0.5f, 0.5f}, 40}));
  job.root = test::group(nodes);
  job.width = width;
  job.height = height;
  job.camera = {{0, 2, 6}, {0, -0.3f, -1}, {0, 1, 0}, 45};
  job.ambient = {0.15f, 0.15f, 0.15f};
  job.lights = {AreaLight{{-2, 5, 2}, {1, 0, 0}, {0, 0, 1}, {0.8f, 0.8f, 0.8f}, {1, 0, 0}}};
  return job;
}

/// The window [x0, x1) × [y0, y1) of `image`.
Image window_of(const Image& image, const PixelRect& r) {
  Image window(r.x1 - r.x0, r.y1 - r.y0);
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) window.at(x - r.x0, y - r.y0) = image.at(x, y);
  return window;
}

TEST(CameraOptions, ACropIsItsWindowOfTheWholeImageBitForBit) {
  for (const auto& [aa, spp, aperture, method] :
       {std::tuple{0, 1, 0.f, AntialiasMethod::kGrid}, {3, 1, 0.f, AntialiasMethod::kGrid},
        {2, 4, 0.08f, AntialiasMethod::kGrid}, {3, 1, 0.f, AntialiasMethod::kSubdivide},
        {2, 2, 0.08f, AntialiasMethod::kSubdivide}}) {
    JobOptions options = test::oracle_options({4, 4, 2});
    options.render.antialias_samples = aa;
    options.render.antialias_method = method;
    options.render.samples_per_pixel = spp;
    options.view.aperture_radius = aperture;
    options.view.focus_distance = 6;
    const Image whole = test::TestJob(edge_scene(64, 48), options).render();
    for (const PixelRect crop : {PixelRect{0, 0, 10, 10}, PixelRect{20, 13, 41, 29}, PixelRect{50, 40, 64, 48},
                                 PixelRect{31, 0, 32, 48}}) {
      options.render.crop = crop;
      const Image cropped = test::TestJob(edge_scene(64, 48), options).render();
      EXPECT_EQ(cropped.pixels(), window_of(whole, crop).pixels())
          << "-a " << aa << (options.render.subdivides() ? " subdivided" : "") << " --spp " << spp
          << " crop " << crop.x0 << "," << crop.y0 << "," << crop.x1 << "," << crop.y1;
    }
  }
}

TEST(CameraOptions, ACropWithAntialiasingTracesOnlyItsWindowAndTheMarginItsDecisionsReach) {
  RenderSettings settings;
  settings.crop = PixelRect{20, 13, 41, 29};
  EXPECT_EQ(rendered_region(64, 48, settings).pixel_count(), 21 * 16);
  settings.antialias_samples = 2;  // 4 passes, each looking 2 pixels further
  const PixelRect region = rendered_region(64, 48, settings);
  EXPECT_EQ(region.x0, 12);
  EXPECT_EQ(region.y0, 5);
  EXPECT_EQ(region.x1, 49);
  EXPECT_EQ(region.y1, 37);
  settings.crop = PixelRect{0, 40, 64, 48};
  EXPECT_EQ(rendered_region(64, 48, settings).y1, 48);
  EXPECT_EQ(rendered_region(64, 48, settings).x0, 0);
}

/// A scene script of a lit sphere in front of a floor, written into `dir`.
fs::path sphere_script(const fs::path& dir, const std::string& output, int width, int height) {
  return test::write_file(dir / "scene.lua",
                          "local root = gr.node('root')\n"
                          "local s = gr.nh_sphere('s', {0, 0.8, 0}, 0.8)\n"
                          "s:set_material(gr.material({0.8, 0.3, 0.2}, {0.5, 0.5, 0.5}, 30))\n"
                          "root:add_child(s)\n"
                          "local f = gr.nh_box('f', {-10, -20, -10}, 20)\n"
                          "f:set_material(gr.material({0.6, 0.6, 0.6}, {0, 0, 0}, 1))\n"
                          "root:add_child(f)\n"
                          "gr.render(root, '" + output + "', " + std::to_string(width) + ", " + std::to_string(height) +
                              ", {0, 2, 6}, {0, -0.3, -1}, {0, 1, 0}, 40, {0.2, 0.2, 0.2},\n"
                          "          {gr.arealight({-2, 5, 2}, {0.8, 0.8, 0.8}, {1, 0, 0}, {-1, 5, 2}, {-2, 5, 3})})\n");
}

class CameraOptionsProgram : public test::ScratchFolderTest {};

TEST_F(CameraOptionsProgram, SuperSampledImagesAreTheSameBytesForAnyThreadCount) {
  const fs::path scene = sphere_script(dir_, "spp.png", 48, 32);
  std::string reference;
  for (const char* threads : {"1", "2", "3"}) {
    const fs::path out = dir_ / (std::string("j") + threads + ".png");
    const auto r = test::run_mjray({"--quiet", "--spp", "5", "-a", "2", "-s", "2", "--aperture", "0.1",
                                    "--focus-distance", "6", "-j", threads, "--output", out.string(), scene.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    if (reference.empty()) reference = test::read_file(out);
    EXPECT_EQ(test::read_file(out), reference) << "-j " << threads;
  }
  const auto plain = test::run_mjray({"--quiet", "-a", "2", "-s", "2", "--output", (dir_ / "plain.png").string(), scene.string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(read_image(dir_ / "plain.png").pixels(), read_image(dir_ / "j1.png").pixels());
}

TEST_F(CameraOptionsProgram, CropWritesJustTheWindowWithTheWholeImagesPixels) {
  const fs::path scene = sphere_script(dir_, "whole.png", 60, 40);
  ASSERT_EQ(test::run_mjray({"--quiet", "-a", "3", scene.string()}).exit_code, 0);
  const auto r = test::run_mjray({"--quiet", "-a", "3", "--crop", "12,5,47,33", "--output", (dir_ / "crop.png").string(),
                                  scene.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image crop = read_image(dir_ / "crop.png");
  EXPECT_EQ(crop.width(), 35);
  EXPECT_EQ(crop.height(), 28);
  EXPECT_EQ(crop.pixels(), window_of(read_image(dir_ / "whole.png"), {12, 5, 47, 33}).pixels());
}

TEST_F(CameraOptionsProgram, ACropOutsideTheImageIsRefusedBeforeRendering) {
  const fs::path scene = sphere_script(dir_, "whole.png", 60, 40);
  const auto r = test::run_mjray({"--quiet", "--crop", "0,0,61,10", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() + ":8: --crop 0,0,61,10 reaches outside this gr.render's 60x40 "
                   "image (the window must lie within 0,0,60,40)\n");
  EXPECT_FALSE(fs::exists(dir_ / "whole.png"));
  EXPECT_EQ(test::run_mjray({"--quiet", "--size", "80x40", "--crop", "0,0,61,10", scene.string()}).exit_code, 0);
}

TEST_F(CameraOptionsProgram, SizeKeepsTheCameraAndTheVerticalFieldOfView) {
  const fs::path scene = sphere_script(dir_, "view.png", 64, 48);
  ASSERT_EQ(test::run_mjray({"--quiet", scene.string()}).exit_code, 0);
  // Twice as wide, as high: the middle 64 columns are the original image.
  const auto r = test::run_mjray({"--quiet", "--size", "128x48", "--output", (dir_ / "wide.png").string(), scene.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image original = read_image(dir_ / "view.png"), wide = read_image(dir_ / "wide.png");
  ASSERT_EQ(wide.width(), 128);
  ASSERT_EQ(wide.height(), 48);
  int differing = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      const Color a = original.at(x, y), b = wide.at(x + 32, y);
      differing += std::abs(a.r - b.r) > 1.5f / 255 || std::abs(a.g - b.g) > 1.5f / 255 || std::abs(a.b - b.b) > 1.5f / 255;
    }
  EXPECT_LE(differing, 64 * 48 / 100) << "the wide image's middle is not the original view";
  // Half the size: the same view, each pixel the mean of the original's four (away from edges).
  ASSERT_EQ(test::run_mjray({"--quiet", "--size", "32x24", "--output", (dir_ / "half.png").string(), scene.string()}).exit_code, 0);
  const Image half = read_image(dir_ / "half.png");
  ASSERT_EQ(half.width(), 32);
  double error = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) {
      const float mean = (original.at(2 * x, 2 * y).g + original.at(2 * x + 1, 2 * y).g + original.at(2 * x, 2 * y + 1).g +
                          original.at(2 * x + 1, 2 * y + 1).g) / 4;
      error += std::abs(half.at(x, y).g - mean);
    }
  EXPECT_LT(error / (32 * 24), 0.03);
}

TEST_F(CameraOptionsProgram, ResumeRefusesAnImageMadeWithOtherSamplingOrAnotherWindow) {
  const fs::path scene = sphere_script(dir_, "r.png", 24, 16);
  ASSERT_EQ(test::run_mjray({"--quiet", "--spp", "2", scene.string()}).exit_code, 0);
  EXPECT_EQ(test::run_mjray({"--quiet", "--resume", "--spp", "2", scene.string()}).exit_code, 0);
  auto r = test::run_mjray({"--quiet", "--resume", "--spp", "3", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--spp: 2 then, 3 now"), std::string::npos) << r.err;
  r = test::run_mjray({"--quiet", "--resume", "--spp", "2", "--crop", "0,0,8,8", scene.string()});
  EXPECT_NE(r.err.find("--crop: whole image then, 0,0,8,8 now"), std::string::npos) << r.err;
  r = test::run_mjray({"--quiet", "--resume", "--spp", "2", "--aperture", "0.2", "--focus-distance", "5", scene.string()});
  EXPECT_NE(r.err.find("lens: pinhole then, aperture 0.2, focus 5 now"), std::string::npos) << r.err;
  r = test::run_mjray({"--quiet", "--resume", "--spp", "2", "--size", "12x8", scene.string()});
  EXPECT_NE(r.err.find("size: 24x16 then, 12x8 now"), std::string::npos) << r.err;
}

TEST_F(CameraOptionsProgram, ALensWithoutAFocusDistanceIsRefusedBeforeRendering) {
  const fs::path scene = sphere_script(dir_, "lens.png", 24, 16);
  const auto r = test::run_mjray({"--quiet", "--aperture", "0.2", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(":8: the lens has an aperture (radius 0.2) but no focus distance: give --focus-distance D"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "lens.png"));
}

TEST_F(CameraOptionsProgram, TheOutputsExtensionPicksTheFormatFromTheSameFilm) {
  // A light bright enough that the highlight and the lit floor go above 1.
  test::write_file(dir_ / "scene.lua",
                   "local root = gr.node('root')\n"
                   "local s = gr.nh_sphere('s', {0, 0.8, 0}, 0.8)\n"
                   "s:set_material(gr.material({0.8, 0.3, 0.2}, {0.9, 0.9, 0.9}, 30))\n"
                   "root:add_child(s)\n"
                   "local f = gr.nh_box('f', {-10, -20, -10}, 20)\n"
                   "f:set_material(gr.material({0.6, 0.6, 0.6}, {0, 0, 0}, 1))\n"
                   "root:add_child(f)\n"
                   "gr.render(root, 'out.png', 40, 30, {0, 2, 6}, {0, -0.3, -1}, {0, 1, 0}, 40, {0.2, 0.2, 0.2},\n"
                   "          {gr.light({-2, 5, 4}, {3, 3, 3}, {1, 0, 0})})\n");
  const fs::path scene = dir_ / "scene.lua";
  for (const std::vector<std::string>& extra : {std::vector<std::string>{"--output", (dir_ / "film.exr").string()},
                                               {"--output", (dir_ / "deep.png").string(), "--bit-depth", "16"},
                                               {"--output", (dir_ / "eight.png").string()},
                                               {"--output", (dir_ / "small.jpg").string(), "--jpeg-quality", "80"}}) {
    std::vector<std::string> args = {"--quiet", "-a", "1"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(scene.string());
    const auto r = test::run_mjray(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const Image film = read_image(dir_ / "film.exr"), deep = read_image(dir_ / "deep.png", {.keep_16_bits = true}),
              eight = read_image(dir_ / "eight.png"), jpeg = read_image(dir_ / "small.jpg");
  float brightest = 0;
  for (size_t i = 0; i < film.pixels().size(); ++i) {
    const Color& c = film.pixels()[i];
    brightest = std::max({brightest, c.r, c.g, c.b});
    for (const auto& [linear, sixteen, eight_bit] : {std::tuple{c.r, deep.pixels()[i].r, eight.pixels()[i].r},
                                                     {c.g, deep.pixels()[i].g, eight.pixels()[i].g},
                                                     {c.b, deep.pixels()[i].b, eight.pixels()[i].b}}) {
      // The EXR holds the film as half floats (11 significant bits); the PNGs clamp it to 1.
      const float clamped = std::min(linear, 1.f);
      EXPECT_NEAR(sixteen, clamped, clamped * 0x1p-11f + 1.0f / 65535) << "pixel " << i;
      EXPECT_NEAR(eight_bit, clamped, clamped * 0x1p-11f + 0.5f / 255 + 1e-6f) << "pixel " << i;
    }
  }
  EXPECT_GT(brightest, 1.5f) << "the EXR keeps values above 1";
  EXPECT_EQ(jpeg.width(), 40);
  EXPECT_EQ(test::read_file(dir_ / "deep.png")[24], 16) << "the IHDR's bit depth";
  EXPECT_EQ(test::read_file(dir_ / "eight.png")[24], 8);
  // The EXR's header: the job's settings (what --resume compares) and the render time.
  Imf::RgbaInputFile exr((dir_ / "film.exr").c_str());
  const auto* seconds = exr.header().findTypedAttribute<Imf::FloatAttribute>("renderSeconds");
  ASSERT_NE(seconds, nullptr);
  EXPECT_GE(seconds->value(), 0.f);
  std::string settings;
  for (const auto& [key, value] : read_image_metadata(dir_ / "film.exr")) settings += key + ": " + value + "\n";
  EXPECT_NE(settings.find("--spp"), std::string::npos) << settings;
  EXPECT_NE(settings.find("lens"), std::string::npos) << settings;
}

}  // namespace
}  // namespace mjray
