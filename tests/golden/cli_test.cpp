// The real mjray program: exit codes, messages on stderr, and where images land. Each run
// starts in "/" so nothing depends on the test's working directory.

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mjray/core/large_page_heap.h"

#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string out;  ///< stdout
  std::string err;  ///< stderr
};

using test::read_file;

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::vector<std::string> plus(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// A tiny lit sphere; `output` is a Lua expression naming the image.
std::string tiny_scene(const std::string& output = "'out.png'", int width = 8, int height = 6) {
  return "root = gr.node('root')\n"
         "s = gr.nh_sphere('s', {0, 0, 0}, 1)\n"
         "s:set_material(gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 20))\n"
         "root:add_child(s)\n"
         "gr.render(root, " + output + ", " + std::to_string(width) + ", " + std::to_string(height) +
         ", {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.2, 0.2, 0.2}, {gr.light({2, 3, 5}, {1, 1, 1}, {1, 0, 0})})\n";
}

class GoldenCli : public test::ScratchFolderTest {
 protected:

  /// Runs `mjray ARGS` from "/" (after the shell command `setup`), capturing both streams into
  /// files of the run folder.
  RunResult run(const std::vector<std::string>& args, const std::string& setup = "") {
    const fs::path out = logs_ / "stdout.txt", err = logs_ / "stderr.txt";
    std::string command = "cd / && " + (setup.empty() ? "" : setup + " && ") + quoted(test::mjray_binary().string());
    for (const auto& arg : args) command.append(" ").append(quoted(arg));
    command += " >" + quoted(out.string()) + " 2>" + quoted(err.string()) + " </dev/null";
    const int status = std::system(command.c_str());
    RunResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_file(out);
    result.err = read_file(err);
    return result;
  }

  /// The names in a folder, sorted, space-separated.
  static std::string listing(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : " ") + n;
    return out;
  }

  const fs::path logs_ = test::make_temp_dir("cli-logs");
};

TEST_F(GoldenCli, GoodSceneExitsZeroAndWritesTheImageBesideTheScript) {
  const auto scene = write("scene.lua", tiny_scene("'out.png'", 8, 6));
  const RunResult r = run({"--quiet", scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ASSERT_TRUE(fs::exists(dir_ / "out.png"));
  const Image image = read_image(dir_ / "out.png");
  EXPECT_EQ(image.width(), 8);
  EXPECT_EQ(image.height(), 6);
  EXPECT_EQ(listing(dir_), "out.png scene.lua");  // no temporary files left
}

TEST_F(GoldenCli, UnderALimitOnAddressSpaceAManySphereSceneRendersAsWithout) {
  // AddressSanitizer reserves terabytes of shadow memory: no limit on address space fits it.
  if (kSanitizerAllocator) GTEST_SKIP() << "AddressSanitizer needs more address space than any such limit";
  // Enough nodes that the heap grows: its large-page reserve must fit within the limit.
  const std::string scene_text = "root = gr.node('root')\n"
                                 "m = gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 20)\n"
                                 "for i = 0, 4999 do\n"
                                 "  local s = gr.nh_sphere('s' .. i, {(i % 100) * 0.1 - 5, (i // 100) * 0.1 - 2.5, -5}, 0.04)\n"
                                 "  s:set_material(m)\n"
                                 "  root:add_child(s)\n"
                                 "end\n"
                                 "gr.render(root, 'out.png', 32, 24, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.2, 0.2, 0.2},\n"
                                 "          {gr.light({2, 3, 5}, {1, 1, 1}, {1, 0, 0})})\n";
  const auto scene = write("scene.lua", scene_text);
  const RunResult plain = run({"--quiet", "--output", (dir_ / "plain.png").string(), scene.string()});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const RunResult limited = run({"--quiet", scene.string()}, "ulimit -v 200000");
  EXPECT_EQ(limited.exit_code, 0) << limited.err;
  EXPECT_EQ(limited.err, "");
  EXPECT_EQ(read_file(dir_ / "out.png"), read_file(dir_ / "plain.png"));
}

TEST_F(GoldenCli, RunningOutOfMemorySaysSoAndExitsOne) {
  if (kSanitizerAllocator) GTEST_SKIP() << "AddressSanitizer needs more address space than any such limit";
  // 11000 x 11000 pixels: within the image size limit, but some 4 GiB of buffers.
  const auto scene = write("scene.lua", tiny_scene("'out.png'", 11000, 11000));
  const RunResult r = run({"--quiet", scene.string()}, "ulimit -v 2000000");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: out of memory\n");
  EXPECT_EQ(listing(dir_), "scene.lua");
}

TEST_F(GoldenCli, SceneErrorExitsOneNamingTheScriptLine) {
  const auto scene = write("scene.lua", "root = gr.node('root')\nm = gr.material({1, 0}, {0, 0, 0}, 10)\n");
  const RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() +
                       ":2: gr.material: argument 1 (kd) must be a table of 3 numbers, got a table of 2 values\n");
}

TEST_F(GoldenCli, MissingSceneFileExitsOne) {
  const RunResult r = run({(dir_ / "absent.lua").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + (dir_ / "absent.lua").string() + ": cannot open the scene file (no such file)\n");
}

TEST_F(GoldenCli, BadCommandLinesExitTwo) {
  const auto scene = write("scene.lua", tiny_scene());
  const std::string hint = "(run 'mjray --help' for the options)\n";
  RunResult r = run({"--bogus", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: unknown option '--bogus'\n" + hint);
  r = run({scene.string(), "-r"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: -r needs a value\n" + hint);
  r = run({});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: no scene file given\n" + hint);
  r = run({"-g", "many", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: -g expects a whole number from 0 to 4096, got 'many'\n" + hint);
  r = run({"--transform-order", "sideways", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: --transform-order expects pre, post or auto, got 'sideways'\n" + hint);
  r = run({"-D", "size=1", "--define", "size=2", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: --define size=2: size is already defined (as size=1); define it once\n" + hint);
  r = run({"--scene-timeout", "-1", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: --scene-timeout expects a number of seconds from 0 (no limit) to 1000000, got '-1'\n" + hint);
  r = run({"-a", "2", "--noise-threshold", "0.01", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("mjray: --noise-threshold and -a cannot be used together", 0), 0u) << r.err;
  r = run({"--watch", "--time-limit", "10", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("mjray: --time-limit and --watch cannot be used together", 0), 0u) << r.err;
  r = run({"--noise-threshold", "2", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: --noise-threshold expects a number in (0, 1], or 0 for off, got '2'\n" + hint);
  EXPECT_EQ(listing(dir_), "scene.lua");  // nothing rendered
}

TEST_F(GoldenCli, AllowReadLetsAStrangersSceneReadAFolderOfModels) {
  const fs::path models = test::make_temp_dir("cli-models");
  test::write_file(models / "kit/tri.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
  write("scene.lua", "local t = gr.mesh('t', '" + (models / "kit/tri.obj").string() + "')\n" + tiny_scene());
  // From the scene's folder: run from "/", every file would be in the working directory's tree.
  const std::string from_scene_folder = "cd " + quoted(dir_.string());
  RunResult r = run({(dir_ / "scene.lua").string()}, from_scene_folder);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(":1: gr.mesh: '" + (models / "kit/tri.obj").string() + "' is outside the folders a scene may read"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  r = run({"--allow-read", models.string(), (dir_ / "scene.lua").string()}, from_scene_folder);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "out.png"));
  r = run({"--allow-read", (models / "absent").string(), (dir_ / "scene.lua").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("mjray: --allow-read expects a folder, and '" + (models / "absent").string() + "' is not one\n", 0),
            0u) << r.err;
}

TEST_F(GoldenCli, AScriptThatReadsTheClockIsNotResumed) {
  // Its scene may differ from run to run: a resume would splice two scenes into one image.
  write("scene.lua", "local wobble = os.time() % 2\n" + tiny_scene());
  RunResult r = run({"--quiet", (dir_ / "scene.lua").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run({"--quiet", "--resume", (dir_ / "scene.lua").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + (dir_ / "scene.lua").string() + ": --resume: the script reads the clock (os.time at " +
                       (dir_ / "scene.lua").string() + ":1), so the scene it describes may differ from the one the "
                       "interrupted run rendered; render without --resume\n");
}

TEST_F(GoldenCli, TimeLimitWritesWhatIsDoneAndResumeFinishesTheSameImage) {
  // Some seconds of work on one thread, stopped after a quarter of a second.
  const auto scene = write("scene.lua", tiny_scene("'out.png'", 640, 480));
  const std::vector<std::string> options = {"-j", "1", "--noise-threshold", "0.01", scene.string()};
  RunResult r = run(plus({"--quiet", "--output", (dir_ / "whole.png").string()}, options));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run(plus({"--time-limit", "0.25"}, options));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("mjray: time limit: wrote the partial image " + (dir_ / "out.png").string() + " (first pass, "),
            std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(dir_ / "out.png.mjray-state"));
  std::string stopped;
  for (const auto& [key, value] : read_image_metadata(dir_ / "out.png"))
    if (key == "mjray stopped") stopped = value;
  EXPECT_EQ(stopped.rfind("time limit in the first pass, ", 0), 0u) << stopped;
  EXPECT_NE(read_file(dir_ / "out.png"), read_file(dir_ / "whole.png"));
  // --resume goes on from the state to the image an unlimited run makes.
  r = run(plus({"--quiet", "--resume"}, options));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir_ / "out.png"), read_file(dir_ / "whole.png"));
  EXPECT_FALSE(fs::exists(dir_ / "out.png.mjray-state"));
}

TEST_F(GoldenCli, HelpAndVersionExitZero) {
  RunResult r = run({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("usage: mjray [options] scene.lua\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("--unsafe-lua"), std::string::npos);
  r = run({"-h"});
  EXPECT_EQ(r.exit_code, 0);
  r = run({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind("mjray ", 0), 0u) << r.out;
}

TEST_F(GoldenCli, OutputToAnUnwritablePathExitsOneAndLeavesNoTemporaryFile) {
  const auto scene = write("scene.lua", tiny_scene());
  write("blocker", "a regular file, not a folder");
  const fs::path target = dir_ / "blocker" / "out.png";
  const RunResult r = run({"--quiet", "--output", target.string(), scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("mjray: error: cannot write '" + target.string() + "': ", 0), 0u) << r.err;
  EXPECT_EQ(listing(dir_), "blocker scene.lua");
  EXPECT_EQ(read_file(dir_ / "blocker"), "a regular file, not a folder");
}

TEST_F(GoldenCli, ExistingImageIsUntouchedWhenTheSceneFails) {
  write("out.png", "previous image bytes");
  const auto scene = write("scene.lua", tiny_scene() + "\nerror('late failure')\n");
  const RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() + ":7: late failure\n");
  EXPECT_EQ(read_file(dir_ / "out.png"), "previous image bytes");
  EXPECT_EQ(listing(dir_), "out.png scene.lua");
}

TEST_F(GoldenCli, OutputOptionNamesTheImage) {
  const auto scene = write("scene.lua", tiny_scene("'ignored.png'", 5, 4));
  const fs::path target = dir_ / "chosen.ppm";
  const RunResult r = run({"--quiet", "--output", target.string(), scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_image(target).width(), 5);
  EXPECT_FALSE(fs::exists(dir_ / "ignored.png"));
}

TEST_F(GoldenCli, OutdirIsCreated) {
  const auto scene = write("scene.lua", tiny_scene("'sub/frame.png'", 3, 2));
  const fs::path outdir = dir_ / "new" / "deeper";
  const RunResult r = run({"--quiet", "--outdir", outdir.string(), scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(outdir / "frame.png"));
  EXPECT_EQ(read_image(outdir / "frame.png").height(), 2);
}

TEST_F(GoldenCli, OutdirThatIsAFileFailsBeforeRendering) {
  const auto scene = write("scene.lua", tiny_scene());
  write("blocker", "x");
  const RunResult r = run({"--quiet", "--outdir", (dir_ / "blocker").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("mjray: error: cannot create the output folder '" + (dir_ / "blocker").string() + "': ", 0), 0u)
      << r.err;
}

TEST_F(GoldenCli, StatsJsonThatCannotBeWrittenFailsBeforeRendering) {
  const auto scene = write("scene.lua", tiny_scene());
  fs::create_directory(dir_ / "taken.json");
  RunResult r = run({"--quiet", "--stats-json", (dir_ / "taken.json").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: cannot write '" + (dir_ / "taken.json").string() + "': it is a folder\n");
  EXPECT_EQ(listing(dir_), "scene.lua taken.json");  // no image
  write("blocker", "x");
  r = run({"--quiet", "--stats-json", (dir_ / "blocker" / "s.json").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("mjray: error: cannot write '" + (dir_ / "blocker" / "s.json").string() +
                            "': cannot create its folder '" + (dir_ / "blocker").string() + "': ", 0), 0u) << r.err;
  EXPECT_EQ(listing(dir_), "blocker scene.lua taken.json");
  // A missing folder is made, as --output's is.
  r = run({"--quiet", "--stats-json", (dir_ / "new" / "s.json").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir_ / "new" / "s.json").front(), '[');
}

TEST_F(GoldenCli, ANulInAnOutputNameLeavesTheFileBeforeItAlone) {
  // The system would read 'notes.txt\0.png' as notes.txt: the scene would replace it.
  write("notes.txt", "my notes");
  const auto scene = write("scene.lua", tiny_scene("'notes.txt\\0.png'"));
  const RunResult r = run({"--quiet", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("gr.render: argument 2 (output file) must be a string without control characters"),
            std::string::npos) << r.err;
  EXPECT_EQ(read_file(dir_ / "notes.txt"), "my notes");
  EXPECT_EQ(listing(dir_), "notes.txt scene.lua");
}

TEST_F(GoldenCli, AResumeStateThatCannotBeReadIsAClearError) {
  const auto scene = write("scene.lua", tiny_scene());
  fs::create_directory(dir_ / "out.png.mjray-state");
  const RunResult r = run({"--quiet", "--resume", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + (dir_ / "scene.lua").string() + ":5: gr.render: cannot write '" +
                       (dir_ / "out.png.mjray-state").string() +
                       "': something of that name is there, and it is not an mjray resume state; move it away (the "
                       "resume state that an interrupted render writes beside its image)\n");
}

TEST_F(GoldenCli, NodesWithoutAMaterialAreNamedThreeAtATime) {
  const auto scene_of = [&](int nodes) {
    return write("scene.lua", "root = gr.node('root')\n"
                              "for i = 1, " + std::to_string(nodes) + " do root:add_child(gr.nh_sphere('s' .. i, "
                              "{i, 0, -5}, 0.5)) end\n"
                              "gr.render(root, 'out.png', 4, 4, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.2, 0.2, 0.2}, "
                              "{gr.light({2, 3, 5}, {1, 1, 1}, {1, 0, 0})})\n");
  };
  const std::string at = "mjray: warning: " + (dir_ / "scene.lua").string() + ":2: '";
  const std::string first_three = at + "s1' has no material; rendering it grey\n" + at +
                                  "s2' has no material; rendering it grey\n" + at +
                                  "s3' has no material; rendering it grey\n";
  RunResult r = run({"--quiet", scene_of(3).string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, first_three);
  r = run({"--quiet", scene_of(4).string()});
  EXPECT_EQ(r.err, first_three + "mjray: warning: 1 more node has no material; rendering it grey too\n");
  r = run({"--quiet", scene_of(300).string()});
  EXPECT_EQ(r.err, first_three + "mjray: warning: 297 more nodes have no material; rendering them grey too\n");
}

TEST_F(GoldenCli, OutputWithASceneThatRendersTwiceIsAnError) {
  const auto scene = write("scene.lua", tiny_scene("'a.png'") + tiny_scene("'b.png'"));
  const RunResult r = run({"--quiet", "--output", (dir_ / "one.png").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() +
                       ": --output names one file but the scene renders 2 images; use --outdir\n");
  EXPECT_EQ(listing(dir_), "scene.lua");
}

TEST_F(GoldenCli, AnimationWritesEveryFrame) {
  const auto scene = write("scene.lua",
                           "root = gr.node('root')\n"
                           "ball = gr.nh_sphere('b', {0, 0, 0}, 0.5)\n"
                           "root:add_child(ball)\n"
                           "for i = 1, 3 do\n"
                           "  ball:translate(0.1, 0, 0)\n"
                           "  gr.render(root, 'frame' .. i .. '.png', 4, 4, {0,0,5}, {0,0,-1}, {0,1,0}, 50, {0.2,0.2,0.2},\n"
                           "            {gr.light({0, 0, 5}, {1, 1, 1}, {1, 0, 0})})\n"
                           "end\n");
  const RunResult r = run({"--quiet", scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(listing(dir_), "frame1.png frame2.png frame3.png scene.lua");
}

TEST_F(GoldenCli, OriginalShortOptionsAreAccepted) {
  const auto scene = write("scene.lua", tiny_scene("'out.png'", 4, 3));
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"-g", "4", "-s", "2", "-a", "2", "-r", "2", "-f", "2"}, {"-o"}, {"-g", "0"}, {"-j", "2", "--seed", "7"}}) {
    std::vector<std::string> all = args;
    all.push_back("--quiet");
    all.push_back(scene.string());
    const RunResult r = run(all);
    EXPECT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
  }
  EXPECT_EQ(read_image(dir_ / "out.png").width(), 4);
}

TEST_F(GoldenCli, GetoptConventionsAttachedValuesAndGroupedFlags) {
  const auto scene = write("scene.lua", tiny_scene("'out.png'", 4, 3));
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"-r4", "-a4", "-s4", "-f2"}, {"-og", "5"}, {"-og5"}, {"-j2", "--seed=7", "--threads=1"}, {"--"}}) {
    std::vector<std::string> all = args;
    all.insert(all.begin(), "--quiet");
    all.push_back(scene.string());
    const RunResult r = run(all);
    EXPECT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
  }
  // The grouped -o still asks for the grid: the statistics name it.
  const RunResult r = run({"-og", "5", "--quiet", "--stats", scene.string()});
  EXPECT_NE(r.err.find("(grid 3³, 1 primitives)"), std::string::npos) << r.err;  // -o: 3·∛1 voxels
  const std::string hint = "(run 'mjray --help' for the options)\n";
  EXPECT_EQ(run({"-ox", scene.string()}).err, "mjray: unknown option '-x' in '-ox'\n" + hint);
  EXPECT_EQ(run({"-r"}).err, "mjray: -r needs a value\n" + hint);
  EXPECT_EQ(run({"-rx", scene.string()}).err, "mjray: -r expects a whole number from 0 to 1000, got 'x'\n" + hint);
  EXPECT_EQ(run({"--stats=yes", scene.string()}).err, "mjray: --stats takes no value, got '--stats=yes'\n" + hint);
}

TEST_F(GoldenCli, OWithAFileNameSuggestsOutput) {
  const auto scene = write("scene.lua", tiny_scene());
  const RunResult r = run({"-o", "out.png", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: -o takes no value: did you mean --output out.png? (-o asks for the uniform grid of optimal "
                   "size)\n(run 'mjray --help' for the options)\n");
  EXPECT_EQ(listing(dir_), "scene.lua");
}

TEST_F(GoldenCli, GridOptionsWithAnotherAcceleratorWarn) {
  const auto scene = write("scene.lua", tiny_scene());
  RunResult r = run({"--accel", "bvh", "-g", "10", "--quiet", scene.string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.err, "mjray: warning: -g has no effect with --accel bvh (it sizes the grid of --accel grid)\n");
  r = run({"--accel", "none", "-o", "--quiet", scene.string()});
  EXPECT_EQ(r.err, "mjray: warning: -o has no effect with --accel none (it sizes the grid of --accel grid)\n");
  r = run({"--accel", "grid", "-g", "10", "--quiet", scene.string()});
  EXPECT_EQ(r.err, "");
}

TEST_F(GoldenCli, AGridSmallerThanAskedForWarnsAndStatisticsReportItsSize) {
  const auto scene = write("scene.lua", tiny_scene());
  const std::string json = (dir_ / "stats.json").string();
  RunResult r = run({"--accel", "grid", "-g", "1000", "--quiet", "--stats", "--stats-json", json, scene.string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.err.rfind("mjray: warning: grid resolution 1000 is above the limit of 256 voxels per axis; the grid "
                        "uses 256³ voxels\n", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("(grid 256³, 1 primitives)"), std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(json)).at(0)["grid_resolution"], 256) << read_file(json);
  r = run({"--accel", "grid", "-g", "7", "--quiet", "--stats", "--stats-json", json, scene.string()});
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(grid 7³, 1 primitives)"), std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(json)).at(0)["grid_resolution"], 7);
  r = run({"--accel", "bvh", "--quiet", "--stats-json", json, scene.string()});
  EXPECT_EQ(nlohmann::json::parse(read_file(json)).at(0)["grid_resolution"], 0);
}

TEST_F(GoldenCli, SubdivisionTracesEachTilesPixelCornersOnceAndTheStatisticsSaySo) {
  // -a 1: cells of a whole pixel, so every pixel is the mean of its four corners and nothing
  // splits. 40×20 pixels in 16-pixel tiles: 16, 16 and 8 wide, 16 and 4 high; each tile traces
  // its (w + 1)(h + 1) corners, those on a tile's border again for the tile beside it.
  const auto scene = write("scene.lua", tiny_scene("'out.png'", 40, 20));
  const std::string json = (dir_ / "stats.json").string();
  const RunResult r = run({"-a", "1", "--aa-method", "subdivide", "--quiet", "--stats", "--stats-json", json, scene.string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("  rays      " + std::to_string((17 + 17 + 9) * (17 + 5)) + " primary"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("  pixels    subdivided from their corners in the first pass (--aa-method subdivide)\n"),
            std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(json)).at(0)["antialias_method"], "subdivide") << read_file(json);
}

TEST_F(GoldenCli, TileSizeChangesHowTheImageIsCutNotTheImage) {
  const auto scene = write("scene.lua", tiny_scene("'out.png'", 40, 20));
  const auto render = [&](std::vector<std::string> extra, const std::string& name) {
    std::vector<std::string> args = {"-a", "2", "--quiet", "--output", (dir_ / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(scene.string());
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_image(dir_ / name).pixels();
  };
  const auto tiles_of_16 = render({}, "16.png");
  EXPECT_EQ(render({"--tile-size", "7"}, "7.png"), tiles_of_16);
  EXPECT_EQ(render({"--tile-size", "1", "-j", "3"}, "1.png"), tiles_of_16);
  // One tile of 64: each pixel corner is traced once (16-pixel tiles trace their borders twice).
  const RunResult one_tile = run({"-a", "1", "--aa-method", "subdivide", "--tile-size", "64", "--quiet", "--stats",
                                  "--output", (dir_ / "64.png").string(), scene.string()});
  EXPECT_NE(one_tile.err.find("  rays      " + std::to_string(41 * 21) + " primary"), std::string::npos) << one_tile.err;
  const RunResult zero = run({"--tile-size", "0", scene.string()});
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_EQ(zero.err, "mjray: --tile-size expects a whole number from 1 to 4096, got '0'\n"
                      "(run 'mjray --help' for the options)\n");
}

TEST_F(GoldenCli, HelpListsEveryAcceleratorOfThisBuild) {
  const RunResult r = run({"--help"});
#ifdef MJRAY_HAVE_EMBREE
  EXPECT_NE(r.out.find("--accel KIND         acceleration structure: bvh (default), grid, none, embree\n"), std::string::npos)
      << r.out;
#else
  EXPECT_NE(r.out.find("(embree: not in this build)"), std::string::npos) << r.out;
#endif
}

TEST_F(GoldenCli, StatisticsPrintOnlyWhenAskedAndQuietLeavesOnlyThem) {
  const auto scene = write("scene.lua", tiny_scene());
  const std::string image = (dir_ / "out.png").string();
  RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.err.find("mjray: wrote " + image + "\n"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("primary"), std::string::npos) << r.err;
  r = run({"--stats", scene.string()});
  EXPECT_NE(r.err.find("mjray: wrote " + image + "\n  time "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("  rays      48 primary"), std::string::npos) << r.err;
  r = run({"--quiet", scene.string()});
  EXPECT_EQ(r.err, "");
  r = run({"--quiet", "--stats", scene.string()});
  EXPECT_EQ(r.err.rfind("mjray: wrote " + image + "\n  time ", 0), 0u) << r.err;
  // Under a noise target: 16 samples in each of the 48 pixels first, then the noise passes.
  r = run({"--quiet", "--stats", "--noise-threshold", "0.001", scene.string()});
  EXPECT_NE(r.err.find("  rays      "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" refinements in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" noise passes (--noise-threshold)\n"), std::string::npos) << r.err;
}

TEST_F(GoldenCli, SrgbOutputDecodesImageTexturesSoTheyKeepTheirValues) {
  // A uniform texture of value 128 on a box that fills the view, lit by ambient 1 only: the
  // image shows the texture as it is stored, with either gamma.
  Image texture(2, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) texture.at(x, y) = Color(128 / 255.0f, 64 / 255.0f, 200 / 255.0f);
  write_image(texture, dir_ / "grey.png");
  const auto scene = write("scene.lua",
                           "m = gr.material({1, 1, 1}, {0, 0, 0}, 1)\n"
                           "m:set_material_texture(gr.filetexture('grey.png'))\n"
                           "wall = gr.nh_box('wall', {-50, -50, -110}, 100)\n"
                           "wall:set_material(m)\n"
                           "gr.render(wall, 'out.png', 4, 4, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 30, {1, 1, 1},\n"
                           "          {gr.light({0, 0, 5}, {0, 0, 0}, {1, 0, 0})})\n");
  for (const char* gamma : {"linear", "srgb"}) {
    const RunResult r = run({"--quiet", "--gamma", gamma, scene.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image image = read_image(dir_ / "out.png");
    // read_image gives v/255 of the stored bytes.
    EXPECT_NEAR(image.at(2, 2).r * 255, 128, 1) << gamma;
    EXPECT_NEAR(image.at(2, 2).g * 255, 64, 1) << gamma;
    EXPECT_NEAR(image.at(2, 2).b * 255, 200, 1) << gamma;
  }
}

TEST_F(GoldenCli, SandboxIsOnByDefaultAndUnsafeLuaLiftsIt) {
  const auto scene = write("scene.lua", "os.execute('true')\n" + tiny_scene());
  RunResult r = run({"--quiet", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() +
                       ":1: os.execute is not allowed: scene scripts run sandboxed; run mjray with --unsafe-lua to "
                       "allow it\n");
  r = run({"--quiet", "--unsafe-lua", scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(GoldenCli, RelativeSceneNameResolvesAgainstTheWorkingDirectory) {
  write("scene.lua", tiny_scene("'rel.png'", 3, 3));
  const std::string command = "cd " + quoted(dir_.string()) + " && " + quoted(test::mjray_binary().string()) +
                              " --quiet scene.lua >/dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0);
  EXPECT_TRUE(fs::exists(dir_ / "rel.png"));
}

TEST_F(GoldenCli, RenderShWorksFromAnyFolderWithOptionsInAnyOrder) {
  write("scenes/a.lua", tiny_scene("'a.png'", 3, 3));
  write("scenes/b.lua", tiny_scene("'b.png'", 3, 3));
  const std::string prefix = "cd " + quoted(dir_.string()) + " && MJRAY_BINARY=" + quoted(test::mjray_binary().string()) +
                             " " + quoted((test::source_dir() / "render.sh").string());
  EXPECT_EQ(std::system((prefix + " -s 2 --quiet scenes/a.lua >/dev/null 2>&1").c_str()), 0);
  EXPECT_EQ(std::system((prefix + " scenes/b.lua -a 2 --quiet >/dev/null 2>&1").c_str()), 0);
  EXPECT_TRUE(fs::exists(dir_ / "scenes/a.png"));
  EXPECT_TRUE(fs::exists(dir_ / "scenes/b.png"));
}

}  // namespace
}  // namespace mjray
