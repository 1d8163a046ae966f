// The render as a user lives it: identical images for any thread count and tile size, stop and
// resume to the same bytes (through a stop hook and a real SIGINT), statistics and progress.

#include <csignal>
#include <cstring>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "mjray/render/image_render.h"
#include "mjray/render/image_sampler.h"
#include "mjray/render/render_checkpoint.h"
#include "support/child_process.h"
#include "support/scene_builder.h"
#include "support/test_job.h"
#include "support/scratch_files.h"
#include "support/spawn.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

RenderJob busy_scene(int size) {
  RenderJob job;
  std::vector<std::shared_ptr<const SceneNode>> nodes = {
      test::mesh(test::floor_quad(50), ReflectiveMaterial{{{0.5f, 0.5f, 0.5f}, {0.2f, 0.2f, 0.2f}, 10}, 0.3f})};
  for (int i = 0; i < 6; ++i)
    nodes.push_back(test::sphere({float(i) - 2.5f, 0.5f, float(i % 3) - 1}, 0.45f,
                                 PhongMaterial{{0.2f + 0.1f * float(i), 0.5f, 0.8f - 0.1f * float(i)}, {0.5f, 0.5f, 0.5f}, 40}));
  job.root = test::group(nodes);
  job.width = job.height = size;
  job.camera = {{0, 3, 7}, {0, -0.4f, -1}, {0, 1, 0}, 50};
  job.ambient = {0.1f, 0.1f, 0.1f};
  job.lights = {PointLight{{3, 6, 5}, {0.9f, 0.9f, 0.9f}, {1, 0, 0}},
                AreaLight{{-4, 5, 2}, {1, 0, 0}, {0, 0, 1}, {0.4f, 0.4f, 0.4f}, {1, 0, 0}}};
  return job;
}

JobOptions busy_options() {
  JobOptions o;
  o.integrator = {4, 4, 2};
  return o;
}

struct Fixture {
  test::TestJob job{busy_scene(64), busy_options()};
  const Camera& camera = job.prepared().camera();
  const Integrator& integrator = job.prepared().integrator();
};

TEST(GoldenRender, IdenticalForAnyThreadCountTileSizeAndAntialiasing) {
  Fixture f;
  for (const auto& [aa, method] :
       {std::pair{0, AntialiasMethod::kGrid}, {3, AntialiasMethod::kGrid}, {3, AntialiasMethod::kSubdivide}}) {
    RenderSettings base;
    base.threads = 1;
    base.antialias_samples = aa;
    base.antialias_method = method;
    const Image reference = render_image(f.camera, 64, 64, f.integrator, base);
    for (const auto& [threads, tile] : {std::pair{2, 16}, {3, 16}, {2, 5}, {3, 64}}) {
      RenderSettings s = base;
      s.threads = threads;
      s.tile_size = tile;
      EXPECT_EQ(render_image(f.camera, 64, 64, f.integrator, s).pixels(), reference.pixels())
          << threads << " threads, tile " << tile << ", -a " << aa << (base.subdivides() ? " subdivided" : "");
    }
  }
}

TEST(GoldenRender, StopAfterSomeTilesThenResumeGivesTheSameImage) {
  Fixture f;
  for (const auto& [aa, method] :
       {std::pair{0, AntialiasMethod::kGrid}, {3, AntialiasMethod::kGrid}, {3, AntialiasMethod::kSubdivide}}) {
    RenderSettings s;
    s.threads = 2;
    s.tile_size = 8;
    s.antialias_samples = aa;
    s.antialias_method = method;
    const Image reference = render_image(f.camera, 64, 64, f.integrator, s);
    for (const int stop_after : {1, 17, 40}) {
      ImageRender first(f.camera, 64, 64, f.integrator, s);
      first.stop_after_tiles(stop_after);
      ASSERT_FALSE(first.run());
      // Through the file format, as a real resume does.
      const auto dir = test::make_temp_dir("resume");
      write_checkpoint(first.checkpoint(), dir / "state");
      ImageRender second(f.camera, 64, 64, f.integrator, s);
      second.resume_from(read_checkpoint(dir / "state"));
      ASSERT_TRUE(second.run());
      EXPECT_EQ(second.image().pixels(), reference.pixels())
          << "stopped after " << stop_after << ", -a " << aa << (s.subdivides() ? " subdivided" : "");
      std::filesystem::remove_all(dir);
    }
  }
}

TEST(GoldenRender, AStoppedFirstPassEndsBetweenRowsAndKeepsTheRowsItDid) {
  // What a stopped MPI rank relies on to end at once: first_pass looks at its stop token
  // before each row, so a request made while a row renders ends the tile after that row.
  Fixture f;
  for (const auto& [aa, method] : {std::pair{0, AntialiasMethod::kGrid}, {3, AntialiasMethod::kSubdivide}}) {
    RenderSettings s;
    s.antialias_samples = aa;
    s.antialias_method = method;
    const ImageSampler sampler(f.camera, f.integrator, 64, 64, s);
    TraceState state;
    Film whole(64, 64);
    ASSERT_TRUE(sampler.first_pass({0, 0, 64, 4}, whole, state));

    std::stop_source stop;
    Film film(64, 64);
    ASSERT_TRUE(sampler.first_pass({0, 0, 64, 1}, film, state, stop.get_token()));
    stop.request_stop();
    EXPECT_FALSE(sampler.first_pass({0, 1, 64, 4}, film, state, stop.get_token()));
    for (int x = 0; x < 64; ++x) {
      EXPECT_EQ(film.at(x, 0).weight, whole.at(x, 0).weight) << x;
      EXPECT_EQ(film.at(x, 0).sum.r, whole.at(x, 0).sum.r) << x;
      for (int y = 1; y < 4; ++y) EXPECT_EQ(film.at(x, y).weight, 0.0f) << x << "," << y;
    }
  }
}

TEST(GoldenRender, StopDuringAntialiasingThenResumeGivesTheSameImage) {
  Fixture f;
  RenderSettings s;
  s.antialias_samples = 4;
  const Image reference = render_image(f.camera, 64, 64, f.integrator, s);
  ImageRender first(f.camera, 64, 64, f.integrator, s);
  // Stop from another thread as soon as anti-aliasing has begun.
  std::thread stopper([&] {
    while (first.progress().antialias_pass == 0) std::this_thread::yield();
    first.request_stop();
  });
  const bool finished = first.run();
  stopper.join();
  ImageRender second(f.camera, 64, 64, f.integrator, s);
  if (!finished) second.resume_from(first.checkpoint());
  ASSERT_TRUE(finished || second.run());
  EXPECT_EQ((finished ? first.image() : second.image()).pixels(), reference.pixels());
}

TEST(GoldenRender, StatisticsCountWhatTheSceneImplies) {
  // One point light over a floor that fills the view: every primary ray hits the floor
  // and casts exactly one shadow ray (the light is above the floor everywhere).
  RenderJob job;
  job.root = test::mesh(test::floor_quad(1000));
  job.width = 40;
  job.height = 30;
  job.camera = {{0, 5, 0}, {0, -1, 0}, {0, 0, -1}, 60};
  job.lights = {PointLight{{0, 10, 0}, {1, 1, 1}, {1, 0, 0}}};
  RenderStats stats;
  test::TestJob(job, JobOptions{}).render(&stats);
  EXPECT_EQ(stats.rays.primary, 40u * 30u);
  EXPECT_EQ(stats.rays.shadow, 40u * 30u);
  EXPECT_EQ(stats.rays.secondary, 0u);
  EXPECT_EQ(stats.pixels_supersampled, 0u);
}

// --- through the program -------------------------------------------------------------------

using test::read_file;

/// A scene slow enough to interrupt under brute force: many spheres.
std::filesystem::path write_slow_scene(const std::filesystem::path& dir) {
  std::ofstream scene(dir / "scene.lua");
  scene << "local root = gr.node('root')\n"
           "local m = gr.material({0.7, 0.4, 0.2}, {0.4, 0.4, 0.4}, 30)\n"
           "for i = 0, 2999 do\n"
           "  local s = gr.nh_sphere('s' .. i, {(i % 60) * 0.34 - 10, math.floor(i / 60) * 0.24 - 6, -20}, 0.15)\n"
           "  s:set_material(m)\n"
           "  root:add_child(s)\n"
           "end\n"
           "gr.render(root, 'slow.png', 360, 240, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60, {0.2, 0.2, 0.2},\n"
           "          {gr.light({5, 5, 10}, {0.8, 0.8, 0.8}, {1, 0, 0})})\n";
  return dir / "scene.lua";
}

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(GoldenRender, RealSigintKeepsThePartialImageAndResumeFinishesItIdentically) {
  const auto dir = test::make_temp_dir("sigint");
  const auto scene = write_slow_scene(dir);
  const std::string mjray = test::mjray_binary().string();
  ASSERT_EQ(run("'" + mjray + "' --quiet --output '" + (dir / "reference.png").string() + "' '" + scene.string() + "'"), 0);

  // Start a slow brute-force render and interrupt it after a moment: it must stop with 130,
  // leaving a partial image and a state file.
  const pid_t pid =
      test::spawn({mjray, "--quiet", "--accel", "none", "-j", "1", "--output", (dir / "slow.png").string(), scene.string()});
  ASSERT_GE(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 130) << "the render finished before the interrupt; make the scene slower";
  ASSERT_TRUE(std::filesystem::exists(dir / "slow.png"));
  ASSERT_TRUE(std::filesystem::exists(dir / "slow.png.mjray-state"));
  EXPECT_NE(read_file(dir / "slow.png"), read_file(dir / "reference.png"));

  // A different option refuses the state instead of producing a wrong image.
  const auto log = dir / "log.txt";
  EXPECT_EQ(run("'" + mjray + "' --quiet --resume -r 2 --output '" + (dir / "slow.png").string() + "' '" +
                scene.string() + "' 2> '" + log.string() + "'"), 1);
  EXPECT_NE(read_file(log).find("different scene or different options"), std::string::npos) << read_file(log);

  // One flipped bit in a finished pixel: refused, and the state and the image are kept.
  const std::string state = read_file(dir / "slow.png.mjray-state"), partial = read_file(dir / "slow.png");
  std::string damaged = state;
  damaged[damaged.size() - 100] ^= 0x10;
  test::write_file(dir / "slow.png.mjray-state", damaged);
  EXPECT_EQ(run("'" + mjray + "' --quiet --resume --output '" + (dir / "slow.png").string() + "' '" + scene.string() +
                "' 2> '" + log.string() + "'"), 1);
  EXPECT_EQ(read_file(log), "mjray: error: " + (dir / "slow.png.mjray-state").string() +
                                ": the resume state file is damaged (the checksum of its pixels and progress does not "
                                "match); it is kept as it is: remove it, or render without --resume\n");
  EXPECT_EQ(read_file(dir / "slow.png.mjray-state"), damaged);
  EXPECT_EQ(read_file(dir / "slow.png"), partial);
  test::write_file(dir / "slow.png.mjray-state", state);

  ASSERT_EQ(run("'" + mjray + "' --quiet --resume --output '" + (dir / "slow.png").string() + "' '" + scene.string() + "'"), 0);
  EXPECT_EQ(read_file(dir / "slow.png"), read_file(dir / "reference.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "slow.png.mjray-state"));
  std::filesystem::remove_all(dir);
}

/// A glass ball and a light and nothing to catch the light: with `--caustics 1e9` its photon
/// pass traces a billion photons (minutes) but stores none, so it is slow and small.
std::filesystem::path write_slow_to_prepare_scene(const std::filesystem::path& dir) {
  std::ofstream(dir / "scene.lua")
      << "local root = gr.node('root')\n"
         "local ball = gr.nh_sphere('ball', {0, 0, 0}, 1)\n"
         "ball:set_material(gr.fresneldiectricmaterial({0, 0, 0}, {0.5, 0.5, 0.5}, 50, 1, 1.5))\n"
         "root:add_child(ball)\n"
         "gr.render(root, 'out.png', 16, 16, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0, 0, 0},\n"
         "          {gr.light({0, 4, 0}, {1, 1, 1}, {1, 0, 0})})\n";
  return dir / "scene.lua";
}

TEST(GoldenRender, InterruptWhilePreparingEndsAtOnceAndWritesNothing) {
  const auto dir = test::make_temp_dir("prepare-interrupt");
  const auto scene = write_slow_to_prepare_scene(dir);
  const auto image = dir / "out.png";
  for (const int sig : {SIGINT, SIGTERM}) {
    const pid_t pid = test::spawn({test::mjray_binary().string(), "--quiet", "--caustics", "1e9", "-j", "1", "--output",
                                   image.string(), scene.string()});
    ASSERT_GE(pid, 0);
    // The script runs in milliseconds; by now the photon pass is mostly under way (were it
    // not, the interrupt would end the script the same way).
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    kill(pid, sig);
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (waitpid(pid, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > deadline) {
        test::kill_and_reap(pid);
        FAIL() << strsignal(sig) << " during the photon pass did not end mjray within 20 s";
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    // An exit of its own with 130, not death by the signal.
    ASSERT_TRUE(WIFEXITED(status)) << strsignal(sig);
    EXPECT_EQ(WEXITSTATUS(status), 130) << strsignal(sig);
    // Nothing was rendered, so there is no partial image or state to resume from.
    EXPECT_FALSE(std::filesystem::exists(image)) << strsignal(sig);
    EXPECT_FALSE(std::filesystem::exists(image.string() + ".mjray-state")) << strsignal(sig);
  }
  std::filesystem::remove_all(dir);
}

TEST(GoldenRender, ProgressLinesAreMonotoneAndEndAt100AndStatsJsonHasEveryKey) {
  const auto dir = test::make_temp_dir("progress");
  const auto scene = write_slow_scene(dir);
  const auto log = dir / "log.txt", json = dir / "stats.json";
  ASSERT_EQ(run("'" + test::mjray_binary().string() + "' -a 2 --stats-json '" + json.string() + "' --output '" +
                (dir / "x.png").string() + "' '" + scene.string() + "' 2> '" + log.string() + "'"), 0);
  const std::string text = read_file(log);
  std::regex line(R"(mjray: +(\d+)% done)");
  int previous = -1, count = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), line); it != std::sregex_iterator(); ++it) {
    const int percent = std::stoi((*it)[1]);
    EXPECT_GE(percent, previous) << text;
    previous = percent;
    ++count;
  }
  EXPECT_GE(count, 1) << text;
  EXPECT_EQ(previous, 100) << text;

  const std::string stats = read_file(json);
  const auto jobs = nlohmann::json::parse(stats);
  ASSERT_TRUE(jobs.is_array()) << stats;
  for (const char* key : {"seconds_total", "seconds_parse", "seconds_build", "seconds_render", "primitives", "accel",
                          "threads", "rays_primary", "rays_secondary", "rays_shadow", "rays_per_second",
                          "pixels_supersampled", "peak_rss_bytes", "grid_resolution"})
    EXPECT_TRUE(jobs.at(0).contains(key)) << key << " missing from " << stats;
  EXPECT_EQ(jobs.at(0)["primitives"], 3000) << stats;
  std::filesystem::remove_all(dir);
}

// --- resume, progress and anti-aliasing through the program ---------------------------------

/// A field of `count` small spheres; their edges make anti-aliasing work. Brute force on one
/// thread makes it slow enough to interrupt (1200 spheres at 150 x 100: about 0.7 s).
std::string sphere_field(int count, int width, int height, const std::string& output) {
  return "local root = gr.node('root')\n"
         "local m = gr.material({0.7, 0.4, 0.2}, {0.4, 0.4, 0.4}, 30)\n"
         "for i = 0, " + std::to_string(count - 1) + " do\n"
         "  local s = gr.nh_sphere('s' .. i, {(i % 60) * 0.34 - 10, math.floor(i / 60) * 0.24 - 6, -20}, 0.15)\n"
         "  s:set_material(m)\n"
         "  root:add_child(s)\n"
         "end\n"
         "gr.render(root, " + output + ", " + std::to_string(width) + ", " + std::to_string(height) +
         ", {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 60, {0.2, 0.2, 0.2},\n"
         "          {gr.light({5, 5, 10}, {0.8, 0.8, 0.8}, {1, 0, 0})})\n";
}

/// mjray running in the background with its stderr readable line by line.
class Child : public test::ChildProcess {
 public:
  explicit Child(std::vector<std::string> args) : ChildProcess(with_program(std::move(args))) {}

 private:
  static std::vector<std::string> with_program(std::vector<std::string> args) {
    args.insert(args.begin(), test::mjray_binary().string());
    return args;
  }
};

/// pixels_supersampled of the first image in a --stats-json file.
long long supersampled_in(const std::filesystem::path& json) {
  const auto jobs = nlohmann::json::parse(read_file(json), nullptr, false);
  return jobs.is_array() && !jobs.empty() ? jobs[0].value("pixels_supersampled", -1LL) : -1;
}

/// Runs mjray with `args` on an animation of sphere_field(1200, 150, 100, …) frames named
/// frame<i>.<extension> in `dir`, and interrupts it while it renders frame 2: frame 1 is then
/// written and frame 2 has its state. Where the interrupt lands depends on the machine: while
/// frame 2 is prepared (a few milliseconds; mjray then ends with nothing of it written) or after
/// it is done (0.2 to 0.7 s on one thread). Such a try is made again with a longer or shorter wait.
void interrupt_in_frame_two(const std::vector<std::string>& args, const std::filesystem::path& dir,
                            const std::string& extension) {
  const auto frame = [&](int i) { return dir / ("frame" + std::to_string(i) + "." + extension); };
  const auto state = [&](int i) { return std::filesystem::path(frame(i).string() + ".mjray-state"); };
  auto wait = std::chrono::milliseconds(100);
  std::string tries;
  for (int attempt = 0; attempt < 6; ++attempt) {
    for (int i = 1; i <= 3; ++i) {
      std::filesystem::remove(frame(i));
      std::filesystem::remove(state(i));
    }
    Child first(args);
    ASSERT_TRUE(first.wait_for("mjray: wrote " + frame(1).string())) << first.log();
    std::this_thread::sleep_for(wait);
    first.interrupt();
    const int code = first.exit_code();
    tries += first.log();
    if (code == 0) {  // all done before the interrupt
      wait /= 2;
      continue;
    }
    ASSERT_EQ(code, 130) << first.log();
    if (std::filesystem::exists(state(2))) return;
    if (std::filesystem::exists(frame(2))) {
      wait /= 2;
      continue;
    }
    // Nothing of frame 2: the interrupt came while it was prepared, which takes milliseconds;
    // not after 400 ms, unless the state was not written.
    ASSERT_LT(wait, std::chrono::milliseconds(400)) << "no state for frame 2:\n" << first.log();
    wait *= 2;
  }
  FAIL() << "no try was interrupted while frame 2 rendered:\n" << tries;
}

TEST(GoldenRender, ResumeFinishesAnInterruptedAnimationIdentically) {
  const auto dir = test::make_temp_dir("animation");
  std::string script = sphere_field(1200, 150, 100, "'frame' .. i .. '.png'");
  script = "for i = 1, 3 do\n" + script + "end\n";
  const auto scene = test::write_file(dir / "scene.lua", script);
  const std::string mjray = test::mjray_binary().string();
  ASSERT_EQ(run("'" + mjray + "' --quiet --outdir '" + (dir / "reference").string() + "' '" + scene.string() + "'"), 0);

  // Interrupted in frame 2: frame 1 complete, frame 2 partial with its state, frame 3 absent.
  ASSERT_NO_FATAL_FAILURE(interrupt_in_frame_two({"--accel", "none", "-j", "1", scene.string()}, dir, "png"));
  ASSERT_FALSE(std::filesystem::exists(dir / "frame3.png"));
  const auto frame1_time = std::filesystem::last_write_time(dir / "frame1.png");

  Child resumed({"--resume", scene.string()});
  EXPECT_EQ(resumed.exit_code(), 0) << resumed.log();
  EXPECT_NE(resumed.log().find("mjray: kept " + (dir / "frame1.png").string() + " (complete)\n"), std::string::npos)
      << resumed.log();
  EXPECT_EQ(std::filesystem::last_write_time(dir / "frame1.png"), frame1_time);
  for (const char* frame : {"frame1.png", "frame2.png", "frame3.png"})
    EXPECT_EQ(read_file(dir / frame), read_file(dir / "reference" / frame)) << frame;
  EXPECT_FALSE(std::filesystem::exists(dir / "frame2.png.mjray-state"));
  std::filesystem::remove_all(dir);
}

TEST(GoldenRender, ResumeFinishesInterruptedJpegAndExrFramesIdentically) {
  // As for PNG: the state beside a partial frame holds the film, so the resumed frame has the
  // uninterrupted one's pixels (and, for JPEG, bytes; EXR also records the render time).
  for (const char* format : {"jpg", "exr"}) {
    const auto dir = test::make_temp_dir(std::string("animation-") + format);
    std::string script = sphere_field(1200, 150, 100, std::string("'frame' .. i .. '.") + format + "'");
    script = "for i = 1, 2 do\n" + script + "end\n";
    const auto scene = test::write_file(dir / "scene.lua", script);
    const std::string mjray = test::mjray_binary().string();
    ASSERT_EQ(run("'" + mjray + "' --quiet --outdir '" + (dir / "reference").string() + "' '" + scene.string() + "'"), 0);
    const std::string frame1 = std::string("frame1.") + format, frame2 = std::string("frame2.") + format;
    ASSERT_NO_FATAL_FAILURE(interrupt_in_frame_two({"--accel", "none", "-j", "1", scene.string()}, dir, format))
        << format;
    Child resumed({"--resume", scene.string()});
    EXPECT_EQ(resumed.exit_code(), 0) << resumed.log();
    EXPECT_NE(resumed.log().find("mjray: kept " + (dir / frame1).string() + " (complete)\n"), std::string::npos)
        << resumed.log();
    for (const std::string& frame : {frame1, frame2}) {
      EXPECT_EQ(read_image(dir / frame).pixels(), read_image(dir / "reference" / frame).pixels()) << frame;
      if (std::string(format) == "jpg") {
        EXPECT_EQ(read_file(dir / frame), read_file(dir / "reference" / frame)) << frame;
      }
    }
    EXPECT_FALSE(std::filesystem::exists(dir / (frame2 + ".mjray-state")));
    std::filesystem::remove_all(dir);
  }
}

TEST(GoldenRender, ResumeKeepsACompleteImageOnlyWhenTheSameSceneMadeIt) {
  const auto dir = test::make_temp_dir("resume-complete");
  const std::string mjray = test::mjray_binary().string();
  for (const char* image : {"one.png", "one.ppm", "one.jpg", "one.exr"}) {
    const auto scene = test::write_file(dir / "scene.lua", sphere_field(10, 8, 6, std::string("'") + image + "'"));
    const auto log = dir / "log.txt";
    const auto mjray_run = [&](const std::string& options) {
      return run("'" + mjray + "' " + options + " '" + scene.string() + "' 2> '" + log.string() + "'");
    };
    ASSERT_EQ(mjray_run("--quiet"), 0);
    const std::string bytes = read_file(dir / image);
    EXPECT_EQ(mjray_run("--resume"), 0);
    EXPECT_EQ(read_file(log), "mjray: kept " + (dir / image).string() + " (complete)\n");
    // Other options, or a changed scene: refused, saying what differs; the image stays.
    EXPECT_EQ(mjray_run("--resume -s 2"), 1);
    EXPECT_NE(read_file(log).find("a different scene or different options made this one (-s: 1 then, 2 now)"),
              std::string::npos) << read_file(log);
    test::write_file(scene, sphere_field(12, 8, 6, std::string("'") + image + "'"));
    EXPECT_EQ(mjray_run("--resume"), 1);
    EXPECT_NE(read_file(log).find("(scene scene.lua changed)"), std::string::npos) << read_file(log);
    EXPECT_EQ(read_file(dir / image), bytes);
    // An image mjray did not finish records nothing, and is not taken as complete.
    Image foreign(8, 6);
    write_image(foreign, dir / image);
    EXPECT_EQ(mjray_run("--resume"), 1);
    EXPECT_NE(read_file(log).find("this one records none"), std::string::npos) << read_file(log);
  }
  std::filesystem::remove_all(dir);
}

TEST(GoldenRender, InterruptedAntialiasingPassResumesWhereItStoppedToTheSameBytes) {
  const auto dir = test::make_temp_dir("aa-resume");
  const auto scene = test::write_file(dir / "scene.lua", sphere_field(3000, 150, 100, "'aa.png'"));
  const std::string mjray = test::mjray_binary().string();
  const auto full_json = dir / "full.json";
  ASSERT_EQ(run("'" + mjray + "' --quiet -a 3 --stats-json '" + full_json.string() + "' --output '" +
                (dir / "reference.png").string() + "' '" + scene.string() + "'"), 0);

  // Where the interrupt lands depends on the machine's load: a busy machine may let the pass
  // end before a progress line names it, or before the interrupt. Such a try is made again.
  std::optional<RenderCheckpoint> state;
  size_t finished = 0;
  std::string tries;
  for (int attempt = 0; attempt < 3 && !state; ++attempt) {
    Child first({"-a", "3", "--accel", "none", "-j", "1", scene.string()});
    const bool in_pass = first.wait_for("(anti-aliasing pass 1)");
    if (in_pass) {
      // Longer each try: a busy machine may not finish a pixel in the first 300 ms.
      std::this_thread::sleep_for(std::chrono::milliseconds(300) * (1 << attempt));
      first.interrupt();
    }
    const int code = first.exit_code();
    tries += first.log();
    if (code == 0) continue;  // it ended before the interrupt
    ASSERT_EQ(code, 130) << first.log();
    RenderCheckpoint interrupted = read_checkpoint(dir / "aa.png.mjray-state");
    ASSERT_EQ(interrupted.antialias_pass, 1);
    finished = 0;
    for (const uint8_t done : interrupted.pass_done) finished += done;
    ASSERT_LE(finished, interrupted.pass_pixels.size());
    if (finished > 0 && finished < interrupted.pass_pixels.size()) state = std::move(interrupted);
  }
  ASSERT_TRUE(state) << "no try was interrupted part of the way through the anti-aliasing pass:\n" << tries;

  const auto resumed_json = dir / "resumed.json";
  ASSERT_EQ(run("'" + mjray + "' --quiet --resume -a 3 --stats-json '" + resumed_json.string() + "' '" +
                scene.string() + "'"), 0);
  EXPECT_EQ(read_file(dir / "aa.png"), read_file(dir / "reference.png"));
  // The resumed run redid none of the finished anti-aliasing pixels.
  EXPECT_EQ(supersampled_in(resumed_json) + (long long)finished, supersampled_in(full_json));
  std::filesystem::remove_all(dir);
}

TEST(GoldenRender, ProgressCountsAntialiasingWorkAndShowsThePassesTheStatisticsCount) {
  const auto dir = test::make_temp_dir("aa-progress");
  const auto scene = test::write_file(dir / "scene.lua", sphere_field(3000, 150, 100, "'aa.png'"));
  // The estimate follows the clock: on a machine busy with other work a phase's rate can
  // swing so far that no tenth is crossed during anti-aliasing. Those timing-dependent checks
  // pass if one of three runs shows them; the rest hold in every run.
  bool kept_reporting = false;
  std::string texts;
  for (int attempt = 0; attempt < 3 && !kept_reporting; ++attempt) {
    Child child({"-a", "3", "--accel", "none", "-j", "1", "--stats", scene.string()});
    ASSERT_EQ(child.exit_code(), 0) << child.log();
    const std::string& text = child.log();
    texts += text;
    // Lines keep coming while anti-aliasing runs, and the first pass was not taken for (almost) all the work.
    std::regex aa_line(R"(mjray: +(\d+)% done[^\n]*\(anti-aliasing pass (\d+)\))");
    int lines = 0, first_percent = -1, highest_pass = 0;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), aa_line); it != std::sregex_iterator(); ++it) {
      if (first_percent < 0) first_percent = std::stoi((*it)[1]);
      highest_pass = std::max(highest_pass, std::stoi((*it)[2]));
      ++lines;
    }
    kept_reporting = lines >= 2 && first_percent < 90;
    std::smatch passes;
    ASSERT_TRUE(std::regex_search(text, passes, std::regex(R"(supersampled in (\d+) anti-aliasing passes)"))) << text;
    EXPECT_LE(highest_pass, std::stoi(passes[1])) << text;
  }
  EXPECT_TRUE(kept_reporting) << texts;
  std::filesystem::remove_all(dir);
}

TEST(GoldenRender, TerminalBarLeavesNoOldTextBehind) {
  const auto dir = test::make_temp_dir("tty");
  const auto scene = test::write_file(dir / "scene.lua", sphere_field(1200, 150, 100, "'aa.png'"));
  const auto log = dir / "typescript";
  // script(1) gives mjray a terminal; a machine without pseudo-terminals (no /dev/pts in a
  // bare container) cannot run this test.
  if (run("script -qec true /dev/null >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "no pseudo-terminal can be made here (script -qec true fails)";
  const std::string command = "'" + test::mjray_binary().string() + "' -a 2 --accel none -j 1 '" + scene.string() + "'";
  ASSERT_EQ(run("script -qec \"" + command + "\" '" + log.string() + "' >/dev/null"), 0);
  const std::string text = read_file(log);
  size_t bars = 0;
  for (size_t at = text.find('\r'); at != std::string::npos; at = text.find('\r', at + 1)) {
    const size_t end = text.find_first_of("\r\n", at + 1);
    if (end == std::string::npos || text.compare(at, 2, "\r\n") == 0) continue;
    const std::string bar = text.substr(at + 1, end - at - 1);
    if (bar.rfind("[", 0) != 0) continue;
    ++bars;
    EXPECT_EQ(bar.substr(bar.size() - 3), "\033[K") << bar;
  }
  EXPECT_GE(bars, 2u) << text;
  EXPECT_NE(text.find("100.0%"), std::string::npos) << text;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mjray
