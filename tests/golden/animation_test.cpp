// Animations through the program: --frames renders just the calls asked for, with the bytes of
// a full run; -D passes values to the script; --video makes a movie of the frames (counted with
// ffprobe), checking ffmpeg before anything renders; progress and statistics name the frame;
// and the shipped bouncing ball is what its header says.

#include <cstdio>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "mjray/io/image_reader.h"
#include "mjray/lua/scene_loader.h"
#include "support/corpus_scenes.h"
#include "support/program_run.h"
#include "support/reference_image.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

/// A ball moving right over `frames` gr.render calls named frame_01.png, frame_02.png, ...
std::string moving_ball(int frames, int width = 30, int height = 20) {
  return "local root = gr.node('root')\n"
         "local ball = gr.nh_sphere('ball', {0, 0, 0}, 0.6)\n"
         "ball:set_material(gr.material({0.2, 0.4, 0.8}, {0.5, 0.5, 0.5}, 40))\n"
         "root:add_child(ball)\n"
         "for frame = 1, " + std::to_string(frames) + " do\n"
         "  ball:translate(0.3, 0, 0)\n"
         "  gr.render(root, string.format('frame_%02d.png', frame), " + std::to_string(width) + ", " +
         std::to_string(height) + ", {1, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,\n"
         "            {0.2, 0.2, 0.2}, {gr.light({2, 3, 5}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n"
         "end\n";
}

/// The names in a folder, sorted, space-separated.
std::string listing(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : " ") + n;
  return out;
}

/// What a shell command prints on stdout.
std::string output_of(const std::string& command) {
  std::string text;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[512];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
    pclose(pipe);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

class Animation : public test::ScratchFolderTest {};

TEST_F(Animation, FramesThreeToFiveAreExactlyThoseOfAFullRun) {
  const fs::path scene = write("scene.lua", moving_ball(6));
  ASSERT_EQ(test::run_mjray({"--quiet", "-a", "2", "--outdir", (dir_ / "all").string(), scene.string()}).exit_code, 0);
  auto r = test::run_mjray({"--quiet", "-a", "2", "--frames", "3-5", "--outdir", (dir_ / "some").string(), scene.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(listing(dir_ / "some"), "frame_03.png frame_04.png frame_05.png");
  for (const char* frame : {"frame_03.png", "frame_04.png", "frame_05.png"})
    EXPECT_EQ(test::read_file(dir_ / "some" / frame), test::read_file(dir_ / "all" / frame)) << frame;
  // A step, and one call alone (which --output may then name).
  ASSERT_EQ(test::run_mjray({"--quiet", "--frames", "1-6:2", "--outdir", (dir_ / "odd").string(), scene.string()}).exit_code, 0);
  EXPECT_EQ(listing(dir_ / "odd"), "frame_01.png frame_03.png frame_05.png");
  r = test::run_mjray({"--quiet", "-a", "2", "--frames", "4", "--output", (dir_ / "four.png").string(), scene.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_image(dir_ / "four.png").pixels(), read_image(dir_ / "all/frame_04.png").pixels());
}

TEST_F(Animation, FramesBeyondTheScriptOrMalformedAreRefused) {
  const fs::path scene = write("scene.lua", moving_ball(4));
  auto r = test::run_mjray({"--quiet", "--frames", "3-7", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() + ": --frames 3-7 asks for gr.render calls the scene does not make: it makes 4\n");
  EXPECT_EQ(listing(dir_), "scene.lua");
  for (const char* bad : {"0-3", "5-2", "2-4:0", "a-b", "3-", "1-2:3:4", "1,2"}) {
    r = test::run_mjray({"--frames", bad, scene.string()});
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("--frames expects A-B or A-B:STEP"), std::string::npos) << r.err;
  }
}

TEST_F(Animation, DefinesAreGlobalsOfTheScriptNumbersWhereTheyReadAsOne) {
  const fs::path scene = write("scene.lua",
                               "assert(math.type(frame) == 'integer', 'frame is ' .. math.type(frame))\n"
                               "assert(math.type(clock) == 'float' and clock == 0.25)\n"
                               "assert(type(name) == 'string')\n"
                               "local root = gr.node('root')\n"
                               "local s = gr.nh_sphere('s', {clock, 0, 0}, 1)\n"
                               "s:set_material(gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 20))\n"
                               "root:add_child(s)\n"
                               "gr.render(root, string.format('%s_%03d.png', name, frame), 8, 6, {0, 0, 5}, {0, 0, -1},\n"
                               "          {0, 1, 0}, 50, {0.2, 0.2, 0.2}, {gr.light({2, 3, 5}, {1, 1, 1}, {1, 0, 0})})\n");
  auto r = test::run_mjray({"--quiet", "-D", "frame=7", "-Dclock=0.25", "--define", "name=ball", "-D", "extra=1", scene.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "ball_007.png")) << listing(dir_);
  // Resume keeps the image only for the same values.
  r = test::run_mjray({"--resume", "-D", "frame=7", "-Dclock=0.25", "--define", "name=ball", "-D", "extra=1", scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = test::run_mjray({"--resume", "-D", "frame=7", "-Dclock=0.25", "--define", "name=ball", "-D", "extra=2", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("(-D extra: 1 then, 2 now)"), std::string::npos) << r.err;
  // A name that is not a Lua name is the command line's mistake; replacing a global, the scene's.
  r = test::run_mjray({"-D", "1st=2", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("-D expects NAME=VALUE with NAME a Lua name"), std::string::npos) << r.err;
  EXPECT_EQ(test::run_mjray({"-D", "end=2", scene.string()}).exit_code, 2);
  EXPECT_EQ(test::run_mjray({"-D", "frame", scene.string()}).exit_code, 2);
  r = test::run_mjray({"-D", "gr=2", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("-D gr=2 would replace the global 'gr' that mjray or Lua defines (a table)"), std::string::npos) << r.err;
}

TEST_F(Animation, VideoHoldsOneFrameForEachImageAtTheFramesPerSecondAsked) {
  if (output_of("command -v ffprobe").empty()) GTEST_SKIP() << "ffprobe (Debian package ffmpeg) is not installed";
  // An odd size: H.264 needs even sides, which the encoder pads to.
  const fs::path scene = write("scene.lua", moving_ball(7, 31, 21));
  for (const char* name : {"movie.mp4", "movie.gif", "movie.webm"}) {
    const fs::path video = dir_ / (std::string("video-") + name) / name;
    fs::create_directories(video.parent_path());
    const auto r = test::run_mjray({"--quiet", "--frames", "2-7", "--fps", "12", "--outdir", (dir_ / "frames").string(),
                                    "--video", video.string(), scene.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string probe = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                              "stream=nb_read_frames,r_frame_rate -of csv=p=0 " + test::shell_quoted(video.string());
    // "NUM/DEN,FRAMES". A GIF counts its frame delays in hundredths of a second, so 12 fps is
    // 8 or 9 hundredths a frame: near 12, not exactly.
    const std::string answer = output_of(probe);
    int num = 0, den = 0, count = 0;
    ASSERT_EQ(std::sscanf(answer.c_str(), "%d/%d,%d", &num, &den, &count), 3) << answer;
    EXPECT_EQ(count, 6) << name;
    if (std::string(name) == "movie.gif")
      EXPECT_NEAR(double(num) / den, 12, 0.6) << answer;
    else
      EXPECT_EQ(answer, "12/1,6") << name;
    EXPECT_EQ(listing(video.parent_path()), name) << "no scratch files are left";
  }
}

TEST_F(Animation, MissingFfmpegIsFoundBeforeAnythingRenders) {
  const fs::path scene = write("scene.lua", moving_ball(3));
  const auto r = test::run_mjray({"--quiet", "--video", (dir_ / "movie.mp4").string(), scene.string()}, "/", "PATH=/nonexistent");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--video needs ffmpeg, and there is none on PATH"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir_), "scene.lua");
  const auto bad = test::run_mjray({"--video", (dir_ / "movie.avi").string(), scene.string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--video expects a file ending in .mp4, .webm or .gif"), std::string::npos) << bad.err;
}

TEST_F(Animation, VideoFramesOfDifferentSizesOrFormatsAreRefusedBeforeAnythingRenders) {
  std::string script = moving_ball(2);
  script += "gr.render(root, 'frame_03.png', 20, 20, {1, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,\n"
            "          {0.2, 0.2, 0.2}, {gr.light({2, 3, 5}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n"
            "gr.render(root, 'frame_04.jpg', 30, 20, {1, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50,\n"
            "          {0.2, 0.2, 0.2}, {gr.light({2, 3, 5}, {0.9, 0.9, 0.9}, {1, 0, 0})})\n";
  const fs::path scene = write("scene.lua", script);
  const std::string video = (dir_ / "movie.mp4").string();
  auto r = test::run_mjray({"--quiet", "--frames", "1-3", "--video", video, scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("its frames must share one size, and '"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is 30x20 but '"), std::string::npos) << r.err;
  r = test::run_mjray({"--quiet", "--frames", "1-4:3", "--video", video, scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("its frames must share one image format"), std::string::npos) << r.err;
  EXPECT_EQ(listing(dir_), "scene.lua");
  // --size makes them one size again.
  r = test::run_mjray({"--quiet", "--frames", "1-3", "--size", "16x12", "--video", video, scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(video));
}

TEST_F(Animation, ProgressAndStatisticsNameEachFrameAndAddUpAtTheEnd) {
  const fs::path scene = write("scene.lua", moving_ball(3));
  auto r = test::run_mjray({"--outdir", (dir_ / "a").string(), scene.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* frame : {"1", "2", "3"}) {
    EXPECT_TRUE(std::regex_search(r.err, std::regex(std::string("mjray: frame ") + frame + "/3: +100% done"))) << r.err;
    const std::string image = (dir_ / "a" / (std::string("frame_0") + frame + ".png")).string();
    EXPECT_TRUE(std::regex_search(r.err, std::regex("mjray: wrote " + image + " \\(frame " + frame + "/3, [0-9.]+s\\)\n")))
        << r.err;
  }
  EXPECT_TRUE(std::regex_search(r.err, std::regex("mjray: rendered 3 frames in [0-9.]+s\n$"))) << r.err;
  // --stats: a line per frame, then the paragraph over all of them.
  r = test::run_mjray({"--quiet", "--stats", "--frames", "2-3", "--outdir", (dir_ / "b").string(), scene.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(mjray: wrote \S+frame_02.png \(frame 2/3\): [0-9.]+s \(build [0-9.]+s, render [0-9.]+s\), [0-9]+ rays at)")))
      << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex(R"(mjray: rendered 2 frames in [0-9.]+s\n  time  .*\n  rays      1200 primary)")))
      << r.err;
}

// --- the shipped animation -------------------------------------------------------------------

const fs::path kBouncingBall = test::source_dir() / "scenes/animation/bouncing_ball.lua";

TEST(BouncingBall, IsAtLeastFourSecondsAt640x360WithItsVideoCommandInTheHeader) {
  const SceneDescription scene = load_scene(kBouncingBall, {});
  EXPECT_GE(scene.jobs.size(), 96u);
  for (const RenderJob& job : scene.jobs) {
    EXPECT_EQ(job.width, 640);
    EXPECT_EQ(job.height, 360);
  }
  const std::string header = test::header_options(kBouncingBall);
  EXPECT_NE(header.find("--video out/bouncing_ball.mp4"), std::string::npos) << header;
  EXPECT_NE(header.find("--outdir out/bouncing_ball"), std::string::npos) << header;
}

TEST(BouncingBall, ContactFramesMatchTheirReferences) {
  // The drop, the first contact's squash, a stretch leaving the floor, a later bounce and the rest.
  test::expect_references(kBouncingBall, "scenes/bouncing_ball", {0, 19, 22, 48, 95});
}

TEST(BouncingBall, RendersAFewFramesAsItsHeaderSaysAtAPreviewSize) {
  const auto out = test::make_temp_dir("bouncing-ball");
  const auto r = test::run_mjray({"--quiet", "-s", "2", "--size", "64x36", "--frames", "1-96:32", "--outdir", out.string(),
                                  kBouncingBall.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(listing(out), "ball_001.png ball_033.png ball_065.png");
  EXPECT_EQ(read_image(out / "ball_033.png").width(), 64);
  fs::remove_all(out);
}

}  // namespace
}  // namespace mjray
