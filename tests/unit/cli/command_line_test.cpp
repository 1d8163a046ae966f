// The command line of the camera, image and animation options: what each means for the job
// options, and the message a mistake gets.

#include "cli.h"

#include <gtest/gtest.h>

namespace mjray {
namespace {

CommandLine parse(std::vector<std::string> args) {
  args.push_back("scene.lua");
  return parse_command_line(args);
}

std::string usage_error(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CommandLine, CameraImageAndAnimationOptionsReachTheJobOptions) {
  const CommandLine cl = parse({"--spp", "16", "--aperture=0.05", "--focus-distance", "4.5", "--size", "320x180",
                                "--crop", "10,20,110,70", "--frames", "3-9:2", "-Dframe=7", "--define", "name=a=b",
                                "--bit-depth", "16", "--jpeg-quality", "75", "--video", "out/m.MP4", "--fps", "30"});
  const JobOptions& o = cl.run.job;
  EXPECT_EQ(o.render.samples_per_pixel, 16);
  EXPECT_EQ(o.view.aperture_radius, 0.05f);
  EXPECT_EQ(o.view.focus_distance, 4.5f);
  EXPECT_EQ(o.view.width, 320);
  EXPECT_EQ(o.view.height, 180);
  ASSERT_TRUE(o.render.crop);
  EXPECT_EQ(o.render.crop->x0, 10);
  EXPECT_EQ(o.render.crop->y0, 20);
  EXPECT_EQ(o.render.crop->x1, 110);
  EXPECT_EQ(o.render.crop->y1, 70);
  ASSERT_TRUE(o.frames);
  EXPECT_EQ(o.frames->first, 3);
  EXPECT_EQ(o.frames->last, 9);
  EXPECT_EQ(o.frames->step, 2);
  EXPECT_EQ(cl.run.load.defines, (std::vector<std::pair<std::string, std::string>>{{"frame", "7"}, {"name", "a=b"}}));
  EXPECT_EQ(o.outputs.encoding.bit_depth, 16);
  EXPECT_EQ(o.outputs.encoding.jpeg_quality, 75);
  EXPECT_EQ(cl.run.report.video, std::filesystem::path("out/m.MP4"));
  EXPECT_EQ(cl.run.report.fps, 30);
  EXPECT_TRUE(cl.warnings.empty());
}

TEST(CommandLine, DefaultsChangeNothing) {
  const JobOptions o = parse({}).run.job;
  EXPECT_EQ(o.render.samples_per_pixel, 1);
  EXPECT_EQ(o.render.antialias_method, AntialiasMethod::kGrid);
  EXPECT_FALSE(o.view.aperture_radius || o.view.focus_distance || o.view.width || o.render.crop || o.frames);
  EXPECT_EQ(o.outputs.encoding.bit_depth, 8);
  const CommandLine one = parse({"--frames", "5"});
  EXPECT_EQ(one.run.job.frames->first, 5);
  EXPECT_EQ(one.run.job.frames->last, 5);
  EXPECT_EQ(parse({"--aperture", "0"}).run.job.view.aperture_radius, 0.f);
}

TEST(CommandLine, AaMethodReachesTheRenderSettings) {
  const JobOptions o = parse({"-a", "3", "--aa-method", "subdivide"}).run.job;
  EXPECT_EQ(o.render.antialias_method, AntialiasMethod::kSubdivide);
  EXPECT_TRUE(o.render.subdivides());
  EXPECT_FALSE(parse({"--aa-method", "subdivide"}).run.job.render.subdivides());  // without -a, nothing to do
  EXPECT_EQ(parse({"-a", "3", "--aa-method", "grid"}).run.job.render.antialias_method, AntialiasMethod::kGrid);
}

TEST(CommandLine, MistakesSayWhatIsExpected) {
  EXPECT_EQ(usage_error({"--spp", "0"}), "--spp expects a whole number from 1 to 4096, got '0'");
  EXPECT_EQ(usage_error({"--aperture", "-1"}), "--aperture expects a lens radius of at least 0, got '-1'");
  EXPECT_EQ(usage_error({"--focus-distance", "0"}), "--focus-distance expects a distance above 0, got '0'");
  EXPECT_EQ(usage_error({"--size", "640"}),
            "--size expects WIDTHxHEIGHT with whole numbers from 1 to 65536 (e.g. 640x360), got '640'");
  EXPECT_EQ(usage_error({"--size", "0x10"}).rfind("--size expects WIDTHxHEIGHT", 0), 0u);
  EXPECT_EQ(usage_error({"--size", "65536x65536"}),
            "--size 65536x65536 has more than 134217728 pixels (e.g. 16384x8192), the most mjray renders");
  for (const char* crop : {"1,2,3", "5,0,5,10", "0,0,10,-1", "a,b,c,d", "0,0,70000,5"})
    EXPECT_EQ(usage_error({"--crop", crop}).rfind("--crop expects X0,Y0,X1,Y1", 0), 0u) << crop;
  EXPECT_EQ(usage_error({"--aa-method", "recursive"}), "--aa-method expects grid or subdivide, got 'recursive'");
  EXPECT_EQ(usage_error({"--bit-depth", "12"}), "--bit-depth expects 8 or 16, got '12'");
  EXPECT_EQ(usage_error({"--jpeg-quality", "101"}), "--jpeg-quality expects a whole number from 1 to 100, got '101'");
  EXPECT_EQ(usage_error({"--fps", "0"}), "--fps expects a whole number from 1 to 1000, got '0'");
  EXPECT_EQ(usage_error({"-D", "=3"}).rfind("-D expects NAME=VALUE", 0), 0u);
  EXPECT_EQ(usage_error({"--define", "while=3"}).rfind("--define expects NAME=VALUE", 0), 0u);
}

TEST(CommandLine, FpsWithoutAVideoIsNamedAsDoingNothing) {
  EXPECT_EQ(parse({"--fps", "12"}).warnings, std::vector<std::string>{"--fps has no effect without --video"});
}

TEST(CommandLine, OptimalGridOverridesAGridSizeAndSaysSo) {
  for (const auto& args : {std::vector<std::string>{"-o", "-g", "20"}, std::vector<std::string>{"-g", "20", "-o"}}) {
    const CommandLine cl = parse(args);
    EXPECT_EQ(cl.warnings, std::vector<std::string>{"-g has no effect with -o (-o chooses the grid's size itself)"});
    const JobOptions& o = cl.run.job;
    EXPECT_EQ(o.accel.kind, "grid");
    EXPECT_EQ(o.accel.grid_size, 0);  // the optimal size
  }
}

}  // namespace
}  // namespace mjray
