// The render as a user lives it: identical images for any thread count and tile size, stop and
// resume to the same bytes (through a stop hook and a real SIGINT), statistics and progress.

#include <csignal>
#include <fstream>
#include <regex>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "mjray/render/image_render.h"
#include "support/scene_builder.h"
#include "support/test_job.h"
#include "support/scratch_files.h"
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
  const PinholeCamera& camera = job.prepared().camera();
  const Integrator& integrator = job.prepared().integrator();
};

TEST(GoldenRender, IdenticalForAnyThreadCountTileSizeAndAntialiasing) {
  Fixture f;
  for (const int aa : {0, 3}) {
    RenderSettings base;
    base.threads = 1;
    base.antialias_samples = aa;
    const Image reference = render_image(f.camera, 64, 64, f.integrator, base);
    for (const auto& [threads, tile] : {std::pair{2, 16}, {3, 16}, {2, 5}, {3, 64}}) {
      RenderSettings s = base;
      s.threads = threads;
      s.tile_size = tile;
      EXPECT_EQ(render_image(f.camera, 64, 64, f.integrator, s).pixels(), reference.pixels())
          << threads << " threads, tile " << tile << ", -a " << aa;
    }
  }
}

TEST(GoldenRender, StopAfterSomeTilesThenResumeGivesTheSameImage) {
  Fixture f;
  for (const int aa : {0, 3}) {
    RenderSettings s;
    s.threads = 2;
    s.tile_size = 8;
    s.antialias_samples = aa;
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
      EXPECT_EQ(second.image().pixels(), reference.pixels()) << "stopped after " << stop_after << ", -a " << aa;
      std::filesystem::remove_all(dir);
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
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string out = (dir / "slow.png").string();
    execl(mjray.c_str(), mjray.c_str(), "--quiet", "--accel", "none", "-j", "1", "--output", out.c_str(),
          scene.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
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

  ASSERT_EQ(run("'" + mjray + "' --quiet --resume --output '" + (dir / "slow.png").string() + "' '" + scene.string() + "'"), 0);
  EXPECT_EQ(read_file(dir / "slow.png"), read_file(dir / "reference.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "slow.png.mjray-state"));
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
    EXPECT_GT(percent, previous) << text;
    previous = percent;
    ++count;
  }
  EXPECT_GE(count, 1) << text;
  EXPECT_EQ(previous, 100) << text;

  const std::string stats = read_file(json);
  for (const char* key : {"seconds_total", "seconds_parse", "seconds_build", "seconds_render", "primitives", "accel",
                          "threads", "rays_primary", "rays_secondary", "rays_shadow", "rays_per_second",
                          "pixels_supersampled", "peak_rss_bytes"})
    EXPECT_NE(stats.find(std::string("\"") + key + "\": "), std::string::npos) << key << " missing from " << stats;
  EXPECT_EQ(stats.front(), '[');
  EXPECT_NE(stats.find("\"primitives\": 3000"), std::string::npos) << stats;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mjray
