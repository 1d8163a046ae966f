// mjray-mpi under mpirun: the same bytes as mjray for 1, 2 and 3 ranks (a corpus scene, an
// anti-aliased glass scene, a 6-frame animation, photon maps, each rank's share of the memory
// for them), a rank that cannot read a mesh ends the job
// with one message and no image, SIGINT writes the partial image and --resume finishes it to
// the same bytes, and the statistics come from rank 0 with one entry per rank. Skipped when
// Open MPI was absent at configure time (scripts/setup.sh installs it).

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mjray/io/image_reader.h"
#include "mjray/render/render_checkpoint.h"
#include "support/child_process.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

using test::read_file;
using test::write_file;

/// mpirun's arguments for `ranks` ranks of mjray-mpi on this host (as root too, beyond its cores).
std::vector<std::string> mpirun(int ranks) {
  std::vector<std::string> args = {test::mpiexec()->string(), "--quiet", "--oversubscribe"};
  if (geteuid() == 0) args.push_back("--allow-run-as-root");
  // Each test process keeps Open MPI's session files in a folder of its own: two jobs sharing
  // /tmp's can fail to start when one removes the shared folder as the other creates its own.
  struct SessionBase {
    const std::filesystem::path dir = test::make_temp_dir("ompi");
    ~SessionBase() {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  };
  static const SessionBase session_base;
  args.insert(args.end(), {"--mca", "orte_tmpdir_base", session_base.dir.string()});
  // Under the asan preset: Open MPI 4.1 itself leaks in MPI_Init/MPI_Finalize (open-mpi/ompi
  // #10048, #12584), often from components it has already unloaded, so no suppression can name
  // them. The ranks keep every other check; mjray's own tests check the shared code for leaks.
  if (const char* asan = std::getenv("ASAN_OPTIONS"))
    args.insert(args.end(), {"-x", std::string("ASAN_OPTIONS=") + asan + ":detect_leaks=0"});
  args.insert(args.end(), {"-np", std::to_string(ranks), test::mjray_mpi_binary()->string()});
  return args;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

std::string command(const std::vector<std::string>& args) {
  std::string text;
  for (const auto& a : args) {
    if (!text.empty()) text += ' ';
    text += quoted(a);
  }
  return text;
}

/// Runs `args` with stderr into `log`; the exit code.
int run(const std::vector<std::string>& args, const std::filesystem::path& log = "/dev/null") {
  const int status = std::system((command(args) + " 2> " + quoted(log.string()) + " < /dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> plus(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<std::string> mjray(const std::vector<std::string>& args) {
  return plus({test::mjray_binary().string()}, args);
}

size_t count(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

/// Small spheres (edges for anti-aliasing) behind a Fresnel glass ball.
std::string glass_scene(const std::string& output, int spheres = 60, int width = 96, int height = 64) {
  return "local root = gr.node('root')\n"
         "local m = gr.material({0.7, 0.4, 0.2}, {0.4, 0.4, 0.4}, 30)\n"
         "local g = gr.fresneldiectricmaterial({0, 0, 0}, {0.8, 0.8, 0.8}, 500, 1.0, 1.5)\n"
         "for i = 0, " + std::to_string(spheres - 1) + " do\n"
         "  local s = gr.nh_sphere('s' .. i, {(i % 60) * 0.34 - 10, math.floor(i / 60) * 0.24 - 6, -20}, 0.15)\n"
         "  s:set_material(m)\n"
         "  root:add_child(s)\n"
         "end\n"
         "local b = gr.nh_sphere('glass', {0, 0, -6}, 1.5)\n"
         "b:set_material(g)\n"
         "root:add_child(b)\n"
         "gr.render(root, " + output + ", " + std::to_string(width) + ", " + std::to_string(height) +
         ", {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60, {0.2, 0.2, 0.2},\n"
         "          {gr.light({5, 5, 10}, {0.8, 0.8, 0.8}, {1, 0, 0}),\n"
         "           gr.light({-5, 3, 8}, {0.3, 0.3, 0.3}, {1, 0, 0})})\n";
}

/// The process of rank `rank` among mpirun `parent`'s children (-1 when none is found).
pid_t rank_process(pid_t parent, int rank) {
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string stat = read_file(entry.path() / "stat");
    const size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    int ppid = -1;
    if (std::sscanf(stat.c_str() + close + 1, " %*c %d", &ppid) != 1 || ppid != parent) continue;
    std::string environment = read_file(entry.path() / "environ");
    for (char& c : environment)
      if (c == '\0') c = '\n';
    if (("\n" + environment).find("\nOMPI_COMM_WORLD_RANK=" + std::to_string(rank) + "\n") != std::string::npos)
      return pid_t(std::stoi(name));
  }
  return -1;
}

class MpiRender : public ::testing::Test {
 protected:
  void SetUp() override {
    MJRAY_REQUIRE_MPI();
    dir_ = test::make_temp_dir("mpi");
  }
  void TearDown() override {
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }
  std::filesystem::path dir_;
};

TEST_F(MpiRender, GlassSceneWithAntialiasingIsTheSameBytesForOneTwoAndThreeRanks) {
  const auto scene = write_file(dir_ / "glass.lua", glass_scene("'glass.png'", 600));
  ASSERT_EQ(run(mjray({"--quiet", "-a", "3", "-s", "2", "--output", (dir_ / "ref.png").string(), scene.string()})), 0);
  const std::string reference = read_file(dir_ / "ref.png");
  ASSERT_FALSE(reference.empty());
  // Rank counts with different threads per rank, accelerators and the pass pieces they share.
  struct Case {
    int ranks;
    std::string threads;
    std::string accel;
  };
  for (const Case& c : {Case{1, "2", "bvh"}, Case{2, "1", "bvh"}, Case{3, "1", "none"}, Case{3, "2", "grid"}}) {
    const auto out = dir_ / ("np" + std::to_string(c.ranks) + "-j" + c.threads + ".png");
    const auto log = dir_ / "log.txt";
    ASSERT_EQ(run(plus(mpirun(c.ranks), {"--quiet", "-a", "3", "-s", "2", "-j", c.threads, "--accel", c.accel,
                                         "--distribute", "tiles", "--output", out.string(), scene.string()}),
                  log), 0) << read_file(log);
    EXPECT_EQ(read_file(out), reference) << "np " << c.ranks << " -j " << c.threads << " --accel " << c.accel;
  }
}

TEST_F(MpiRender, SubdividedAntialiasingIsTheSameBytesForOneAndTwoRanks) {
  // Corners that two ranks' tiles share are traced by both, keyed by their place in the image.
  const auto scene = write_file(dir_ / "glass.lua", glass_scene("'glass.png'", 600));
  const std::vector<std::string> options = {"--quiet", "-a", "3", "--aa-method", "subdivide", "-s", "2"};
  ASSERT_EQ(run(mjray(plus(options, {"--output", (dir_ / "ref.png").string(), scene.string()}))), 0);
  const std::string reference = read_file(dir_ / "ref.png");
  ASSERT_FALSE(reference.empty());
  const auto out = dir_ / "np2.png";
  const auto log = dir_ / "log.txt";
  const std::vector<std::string> two_ranks = {"-j", "1", "--distribute", "tiles", "--output", out.string(), scene.string()};
  ASSERT_EQ(run(plus(plus(mpirun(2), options), two_ranks), log), 0) << read_file(log);
  EXPECT_EQ(read_file(out), reference);
}

/// Renders the glass scene (in `dir`) with `options` by mjray, then by mjray-mpi on each of `ranks`
/// (one thread each), and expects the same bytes.
void expect_mjray_bytes_for_ranks(const std::filesystem::path& dir, const std::vector<std::string>& options,
                                  const std::vector<int>& ranks) {
  const auto scene = write_file(dir / "glass.lua", glass_scene("'glass.png'"));
  ASSERT_EQ(run(mjray(plus(plus({"--quiet"}, options), {"--output", (dir / "ref.png").string(), scene.string()}))), 0);
  const std::string reference = read_file(dir / "ref.png");
  ASSERT_FALSE(reference.empty());
  for (const int n : ranks) {
    const auto out = dir / ("np" + std::to_string(n) + ".png");
    const auto log = dir / "log.txt";
    ASSERT_EQ(run(plus(plus(mpirun(n), {"--quiet", "-j", "1"}), plus(options, {"--output", out.string(), scene.string()})),
                  log), 0) << read_file(log);
    EXPECT_EQ(read_file(out), reference) << n << " ranks";
  }
}

TEST_F(MpiRender, PhotonMapsAreTheSameBytesForOneAndTwoRanks) {
  // Every rank builds the same caustic and global maps (photons keyed by the seed), so the
  // ranks' tiles agree with mjray's image.
  expect_mjray_bytes_for_ranks(dir_, {"--caustics", "20000", "--gi", "4000", "--seed", "3"}, {1, 2});
}

TEST_F(MpiRender, ProgressiveCausticsUnderANoiseTargetAreTheSameBytesForTwoAndThreeRanks) {
  // The noise passes' pixels are shared among the ranks, each sample reading its caustic pass.
  expect_mjray_bytes_for_ranks(dir_, {"--caustics", "5000", "--caustic-passes", "4", "--noise-threshold", "0.05",
                                       "--max-spp", "64", "--seed", "3"}, {2, 3});
}

TEST_F(MpiRender, TimeLimitIsRefusedWithTheUsageExitCode) {
  const auto scene = write_file(dir_ / "glass.lua", glass_scene("'glass.png'"));
  const auto log = dir_ / "log.txt";
  EXPECT_EQ(run(plus(mpirun(2), {"--time-limit", "5", scene.string()}), log), 2);
  EXPECT_NE(read_file(log).find("mjray: --time-limit: mjray-mpi renders to the end"), std::string::npos) << read_file(log);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "glass.png"));
}

TEST_F(MpiRender, RanksOnOneHostEachTakeTheirShareOfItsMemoryForPhotonMaps) {
  // Inside a closed matte room every photon is stored, a few times over: a billion of them
  // would need more memory than a machine has. The message names each rank's share.
  const auto scene = write_file(dir_ / "room.lua",
                                "local root = gr.node('root')\n"
                                "local room = gr.nh_sphere('room', {0, 0, 0}, 50)\n"
                                "room:set_material(gr.material({0.7, 0.7, 0.7}, {0, 0, 0}, 1))\n"
                                "root:add_child(room)\n"
                                "gr.render(root, 'room.png', 32, 32, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60, {0.2, 0.2, 0.2},\n"
                                "          {gr.light({0, 10, 0}, {0.8, 0.8, 0.8}, {1, 0, 0})})\n");
  const auto log = dir_ / "log.txt";
  EXPECT_EQ(run(plus(mpirun(2), {"-j", "1", "--gi", "1e9", scene.string()}), log), 1);
  const std::string text = read_file(log);
  EXPECT_NE(text.find("mjray: error: --gi 1000000000: the photon map would hold about "), std::string::npos) << text;
  EXPECT_NE(text.find(" available to each of the 2 processes on this machine (of "), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "room.png"));
}

TEST_F(MpiRender, AScriptThatDrawsRandomNumbersIsOneSceneOnEveryRank) {
  // Each ball's colour comes from math.random: seeded from --seed, every rank describes the
  // same scene, so the image is no patchwork of the ranks' scenes.
  const auto scene = write_file(dir_ / "random.lua",
                                "local root = gr.node('root')\n"
                                "for i = 0, 15 do\n"
                                "  local s = gr.nh_sphere('s' .. i, {(i % 4) * 2 - 3, math.floor(i / 4) * 2 - 3, -10}, 0.9)\n"
                                "  s:set_material(gr.material({math.random(), math.random(), math.random()}, {0, 0, 0}, 1))\n"
                                "  root:add_child(s)\n"
                                "end\n"
                                "gr.render(root, 'random.png', 64, 64, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.3, 0.3, 0.3},\n"
                                "          {gr.light({5, 5, 10}, {0.8, 0.8, 0.8}, {1, 0, 0})})\n");
  ASSERT_EQ(run(mjray({"--quiet", "--seed", "5", "--output", (dir_ / "ref.png").string(), scene.string()})), 0);
  const std::string reference = read_file(dir_ / "ref.png");
  ASSERT_FALSE(reference.empty());
  const auto out = dir_ / "np3.png";
  const auto log = dir_ / "log.txt";
  ASSERT_EQ(run(plus(mpirun(3), {"--quiet", "-j", "1", "--seed", "5", "--distribute", "tiles", "--output", out.string(),
                                 scene.string()}),
                log), 0) << read_file(log);
  EXPECT_EQ(read_file(out), reference);
}

TEST_F(MpiRender, FramesCropSizeDefinesAndVideoGiveWhatMjrayGives) {
  // Three frames whose spheres' count comes from -D: --frames 2-3 renders only those, at
  // --size, only the --crop window, and --video joins them, as mjray does.
  const auto scene = write_file(dir_ / "three.lua",
                                "for i = 1, 3 do\n"
                                "  local root = gr.node('root')\n"
                                "  local m = gr.material({0.7, 0.4, 0.2}, {0.4, 0.4, 0.4}, 30)\n"
                                "  for k = 0, spheres + 10 * i do\n"
                                "    local s = gr.nh_sphere('s' .. k, {(k % 10) * 0.6 - 3, math.floor(k / 10) * 0.6 - 2, -8}, 0.25)\n"
                                "    s:set_material(m)\n"
                                "    root:add_child(s)\n"
                                "  end\n"
                                "  gr.render(root, 'f' .. i .. '.png', 48, 32, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60,\n"
                                "            {0.2, 0.2, 0.2}, {gr.light({5, 5, 10}, {0.8, 0.8, 0.8}, {1, 0, 0})})\n"
                                "end\n");
  const std::vector<std::string> options = {"--quiet", "-a", "2", "--frames", "2-3", "--size", "96x64", "--crop",
                                            "10,8,70,50", "-D", "spheres=40"};
  const auto reference = dir_ / "ref", ranks = dir_ / "np2";
  ASSERT_EQ(run(mjray(plus(options, {"--outdir", reference.string(), "--video", (reference / "v.gif").string(),
                                     scene.string()}))), 0);
  const auto log = dir_ / "log.txt";
  ASSERT_EQ(run(plus(mpirun(2), plus(options, {"-j", "1", "--outdir", ranks.string(), "--video",
                                               (ranks / "v.gif").string(), scene.string()})),
                log), 0) << read_file(log);
  EXPECT_FALSE(std::filesystem::exists(reference / "f1.png"));
  EXPECT_FALSE(std::filesystem::exists(ranks / "f1.png"));
  for (const char* frame : {"f2.png", "f3.png"}) {
    const std::string bytes = read_file(ranks / frame);
    EXPECT_FALSE(bytes.empty()) << frame;
    EXPECT_EQ(bytes, read_file(reference / frame)) << frame;
    EXPECT_EQ(read_image(ranks / frame).width(), 60) << frame;
  }
  EXPECT_FALSE(read_file(ranks / "v.gif").empty());
  EXPECT_EQ(read_file(ranks / "v.gif"), read_file(reference / "v.gif"));
}

TEST_F(MpiRender, AScriptThatReadsTheClockIsRefusedOnMoreThanOneRank) {
  const auto scene = write_file(dir_ / "clock.lua", "local t = os.clock()\n" + glass_scene("'clock.png'"));
  const auto log = dir_ / "log.txt";
  EXPECT_EQ(run(plus(mpirun(2), {"-j", "1", scene.string()}), log), 1);
  EXPECT_NE(read_file(log).find("the script reads the clock (os.clock at " + scene.string() +
                                ":1), so each rank may describe another scene"),
            std::string::npos) << read_file(log);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "clock.png"));
  EXPECT_EQ(run(plus(mpirun(1), {"--quiet", "-j", "1", scene.string()}), log), 0) << read_file(log);
}

TEST_F(MpiRender, WatchIsRefusedWithTheUsageExitCode) {
  const auto scene = write_file(dir_ / "glass.lua", glass_scene("'glass.png'"));
  const auto log = dir_ / "log.txt";
  EXPECT_EQ(run(plus(mpirun(2), {"--watch", scene.string()}), log), 2);
  EXPECT_NE(read_file(log).find("mjray: --watch: mjray-mpi does not serve the live preview; run mjray --watch instead\n"),
            std::string::npos) << read_file(log);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "glass.png"));
}

TEST_F(MpiRender, CorpusSceneIsTheSameBytesForOneTwoAndThreeRanks) {
  MJRAY_REQUIRE_SHARED(shared);
  // A CS 488 scene that requires a module (buckyball.lua, read by every rank) and has instances.
  const auto scene = shared / "corpus/cs488/hmhealey-cs488a4/data/simple-cows.lua";
  ASSERT_TRUE(std::filesystem::exists(scene)) << scene;
  ASSERT_EQ(run(mjray({"--quiet", "--output", (dir_ / "ref.png").string(), scene.string()})), 0);
  const std::string reference = read_file(dir_ / "ref.png");
  ASSERT_FALSE(reference.empty());
  for (const int ranks : {1, 2, 3}) {
    const auto out = dir_ / ("np" + std::to_string(ranks) + ".png");
    const auto log = dir_ / "log.txt";
    ASSERT_EQ(run(plus(mpirun(ranks), {"--quiet", "-j", "1", "--output", out.string(), scene.string()}), log), 0)
        << read_file(log);
    EXPECT_EQ(read_file(out), reference) << ranks << " ranks";
  }
}

TEST_F(MpiRender, SixFrameAnimationIsTheSameBytesWhetherRanksTakeFramesOrTiles) {
  const auto scene = write_file(dir_ / "anim.lua", "for i = 1, 6 do\n" + glass_scene("'frame' .. i .. '.png'", 120, 48, 32) + "end\n");
  ASSERT_EQ(run(mjray({"--quiet", "-a", "2", "--outdir", (dir_ / "ref").string(), scene.string()})), 0);
  for (const int ranks : {1, 2, 3})
    for (const char* distribution : {"auto", "frames", "tiles"}) {
      const auto out = dir_ / ("np" + std::to_string(ranks) + distribution);
      const auto log = dir_ / "log.txt";
      ASSERT_EQ(run(plus(mpirun(ranks), {"--quiet", "-a", "2", "-j", "1", "--distribute", distribution, "--outdir",
                                         out.string(), scene.string()}),
                    log), 0) << read_file(log);
      for (int f = 1; f <= 6; ++f) {
        const std::string frame = "frame" + std::to_string(f) + ".png";
        const std::string bytes = read_file(out / frame);
        EXPECT_FALSE(bytes.empty()) << frame;
        EXPECT_EQ(bytes, read_file(dir_ / "ref" / frame)) << ranks << " ranks, --distribute " << distribution << ", "
                                                          << frame;
      }
    }
}

/// A scene that loads tri.obj from its folder.
std::string mesh_scene() {
  return "local root = gr.node('root')\n"
         "local t = gr.mesh('tri', 'tri.obj')\n"
         "t:set_material(gr.material({0.7, 0.4, 0.2}, {0.4, 0.4, 0.4}, 30))\n"
         "root:add_child(t)\n"
         "gr.render(root, 'm.png', 32, 32, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.2, 0.2, 0.2},\n"
         "          {gr.light({5, 5, 10}, {0.8, 0.8, 0.8}, {1, 0, 0})})\n";
}

TEST_F(MpiRender, ARankThatCannotReadAMeshEndsTheJobWithOneMessageAndNoImage) {
  // Two "hosts": the same scene in two folders, the mesh only in the first (rank 0's).
  write_file(dir_ / "a/tri.obj", "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
  write_file(dir_ / "a/m.lua", mesh_scene());
  write_file(dir_ / "b/m.lua", mesh_scene());
  std::vector<std::string> args = mpirun(1);
  args.resize(args.size() - 3);  // the same mpirun, as two application contexts
  const std::string mpi = test::mjray_mpi_binary()->string();
  args = plus(args, {"-np", "1", "-wdir", (dir_ / "a").string(), mpi, "m.lua", ":", "-np", "1", "-wdir",
                     (dir_ / "b").string(), mpi, "m.lua"});
  const auto log = dir_ / "log.txt";
  EXPECT_NE(run(args, log), 0);
  const std::string text = read_file(log);
  EXPECT_EQ(count(text, "mjray: error: rank 1 ("), 1u) << text;
  EXPECT_EQ(count(text, "'tri.obj'"), 1u) << text;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "a/m.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "b/m.png"));

  // Every rank missing it: the one message, not one per rank, and no rank named.
  EXPECT_NE(run(plus(mpirun(3), {(dir_ / "b/m.lua").string()}), log), 0);
  EXPECT_EQ(count(read_file(log), "mjray: error: "), 1u) << read_file(log);
  EXPECT_EQ(count(read_file(log), "'tri.obj'"), 1u) << read_file(log);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "b/m.png"));
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir_ / "b", ec))
    EXPECT_TRUE(e.path().filename() == "m.lua") << "left behind: " << e.path();
}

TEST_F(MpiRender, ARankThatReadADifferentSceneIsNamedAndNothingRenders) {
  // The same script name on two "hosts", one of them edited: rank 0 names rank 1 and the file.
  write_file(dir_ / "a/tri.obj", "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
  write_file(dir_ / "b/tri.obj", "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
  write_file(dir_ / "a/m.lua", mesh_scene());
  std::string edited = mesh_scene();
  edited.replace(edited.find("0.7, 0.4, 0.2"), 13, "0.2, 0.4, 0.7");
  write_file(dir_ / "b/m.lua", edited);
  std::vector<std::string> args = mpirun(1);
  args.resize(args.size() - 3);
  const std::string mpi = test::mjray_mpi_binary()->string();
  args = plus(args, {"-np", "1", "-wdir", (dir_ / "a").string(), mpi, "m.lua", ":", "-np", "1", "-wdir",
                     (dir_ / "b").string(), mpi, "m.lua"});
  const auto log = dir_ / "log.txt";
  EXPECT_NE(run(args, log), 0);
  const std::string text = read_file(log);
  EXPECT_EQ(count(text, "mjray: error: "), 1u) << text;
  EXPECT_NE(text.find("rank 1 ("), std::string::npos) << text;
  EXPECT_NE(text.find("read a different scene or different files than rank 0"), std::string::npos) << text;
  EXPECT_NE(text.find("m.lua"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "a/m.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "b/m.png"));
}

TEST_F(MpiRender, SigintWritesThePartialImageAndResumeUnderMpiFinishesItToTheSameBytes) {
  // Brute force on one thread per rank keeps the render running long enough to interrupt.
  const auto scene = write_file(dir_ / "slow.lua", glass_scene("'slow.png'", 3000, 150, 100));
  ASSERT_EQ(run(mjray({"--quiet", "-a", "4", "--output", (dir_ / "ref.png").string(), scene.string()})), 0);

  // Interrupted during the anti-aliasing pass, whose pieces the ranks share. mpirun forwards
  // progress lines late and signals the ranks late on a busy machine: a run that finished
  // before the signal reached it proves nothing, and is tried again (at most 3 times).
  std::string log_text;
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::filesystem::remove(dir_ / "slow.png");
    test::ChildProcess first(plus(mpirun(2), {"-a", "4", "--accel", "none", "-j", "1", scene.string()}));
    ASSERT_TRUE(first.wait_for("(anti-aliasing pass 1)")) << first.log();
    first.interrupt(SIGINT);
    const int code = first.exit_code();
    log_text = first.log();
    if (log_text.find("mjray: wrote ") != std::string::npos) continue;  // finished first
    // mpirun kills the ranks 1 s after it passes Ctrl-C on: on a machine busier than that,
    // rank 0 may not have written in time (the next test shows that nothing torn is left).
    if (log_text.find("mjray: interrupted: wrote") == std::string::npos) continue;
    EXPECT_NE(code, 0) << log_text;  // Open MPI's mpirun returns 1 after it forwards SIGINT
    break;
  }
  ASSERT_NE(log_text.find("mjray: interrupted: wrote the partial image"), std::string::npos)
      << log_text << "\n(the render finished before the interrupt each time? make the scene slower)";
  ASSERT_TRUE(std::filesystem::exists(dir_ / "slow.png.mjray-state"));
  EXPECT_EQ(read_checkpoint(dir_ / "slow.png.mjray-state").antialias_pass, 1);
  EXPECT_NE(read_file(dir_ / "slow.png"), read_file(dir_ / "ref.png"));

  const auto log = dir_ / "log.txt";
  ASSERT_EQ(run(plus(mpirun(3), {"--quiet", "--resume", "-a", "4", "-j", "1", scene.string()}), log), 0)
      << read_file(log);
  EXPECT_EQ(read_file(dir_ / "slow.png"), read_file(dir_ / "ref.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "slow.png.mjray-state"));
}

TEST_F(MpiRender, AKilledRankEndsTheJobWithoutATornImageAndWhatWasWrittenResumes) {
  const auto scene = write_file(dir_ / "slow.lua", glass_scene("'slow.png'", 3000, 150, 100));
  ASSERT_EQ(run(mjray({"--quiet", "-a", "3", "--output", (dir_ / "ref.png").string(), scene.string()})), 0);

  test::ChildProcess job(plus(mpirun(2), {"-a", "3", "--accel", "none", "-j", "1", scene.string()}));
  ASSERT_TRUE(job.wait_for("% done")) << job.log();
  const pid_t worker = rank_process(job.pid(), 1);
  ASSERT_GT(worker, 0) << "rank 1 not found among mpirun's children";
  kill(worker, SIGKILL);
  EXPECT_NE(job.exit_code(), 0) << job.log();
  EXPECT_NE(job.log().find("rank 1"), std::string::npos) << job.log();  // mpirun names the rank that died
  // mpirun stops rank 0 with SIGTERM: it writes the partial image and its state (each file
  // whole, by rename), or, stopped before that, nothing. Either way --resume finishes it.
  const bool partial = std::filesystem::exists(dir_ / "slow.png");
  EXPECT_EQ(std::filesystem::exists(dir_ / "slow.png.mjray-state"), partial);
  if (partial) {
    const Image image = read_image(dir_ / "slow.png");  // throws on a torn file
    EXPECT_EQ(image.width(), 150);
    EXPECT_EQ(image.height(), 100);
  }
  const auto log = dir_ / "log.txt";
  ASSERT_EQ(run(plus(mpirun(2), {"--quiet", "--resume", "-a", "3", "-j", "1", scene.string()}), log), 0)
      << read_file(log);
  EXPECT_EQ(read_file(dir_ / "slow.png"), read_file(dir_ / "ref.png")) << (partial ? "resumed" : "rendered afresh");
}

TEST_F(MpiRender, StatisticsComeFromRankZeroWithOneEntryPerRank) {
  const auto scene = write_file(dir_ / "glass.lua", glass_scene("'glass.png'"));
  const auto json = dir_ / "stats.json";
  const auto log = dir_ / "log.txt";
  ASSERT_EQ(run(plus(mpirun(3), {"-j", "1", "--stats", "--stats-json", json.string(), scene.string()}), log), 0)
      << read_file(log);
  const std::string text = read_file(json);
  const auto jobs = nlohmann::json::parse(text);
  ASSERT_EQ(jobs.size(), 1u) << text;
  const auto& ranks = jobs[0]["ranks"];
  ASSERT_EQ(ranks.size(), 3u) << text;
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(ranks[size_t(r)]["rank"], r) << text;
    for (const char* key : {"seconds_load", "seconds_build", "bytes_sent", "host"})
      EXPECT_TRUE(ranks[size_t(r)].contains(key)) << key << " in " << text;
  }
  // Progress and the final line come once, from rank 0.
  EXPECT_EQ(count(read_file(log), "mjray: wrote "), 1u) << read_file(log);
}

}  // namespace
}  // namespace mjray
