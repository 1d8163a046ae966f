// Renders with photon maps (--caustics, --gi) as users run them: the same image for any
// thread count, accelerator and stop-and-resume; the options, statistics and fingerprint
// through the program.

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "mjray/accel/make_accelerator.h"
#include "mjray/job/job_fingerprint.h"
#include "mjray/render/image_render.h"
#include "support/scene_builder.h"
#include "support/scratch_files.h"
#include "support/test_job.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

/// Glass, a mirror and coloured diffuse walls under a point and an area light.
RenderJob caustic_room(int size) {
  const Material glass = FresnelMaterial{{{0, 0, 0}, {0.5f, 0.5f, 0.5f}, 100}, 1, 1.5f};
  RenderJob job;
  job.root = test::group({test::mesh(test::floor_quad(6), PhongMaterial{{0.7f, 0.7f, 0.7f}, {0.2f, 0.2f, 0.2f}, 20}),
                          test::box({-6, 0, 3}, {6, 6, 3.5f}, PhongMaterial{{0.7f, 0.2f, 0.2f}, {0, 0, 0}, 1}),
                          test::sphere({-0.8f, 0.7f, 0}, 0.7f, glass),
                          test::box({0.5f, 0, -0.5f}, {1.5f, 0.6f, 0.5f}, glass),
                          test::sphere({1.8f, 0.5f, 1.5f}, 0.5f, ReflectiveMaterial{{{0.2f, 0.2f, 0.3f}, {0, 0, 0}, 1}, 0.7f})});
  job.width = job.height = size;
  job.camera = {{0, 3, -5}, {0, -0.5f, 1}, {0, 1, 0}, 50};
  job.ambient = {0.1f, 0.1f, 0.1f};
  job.lights = {PointLight{{-2, 5, 4}, {0.8f, 0.8f, 0.8f}, {1, 0, 0}},
                AreaLight{{2, 4, -1}, {1, 0, 0}, {0, 0, 1}, {0.4f, 0.4f, 0.4f}, {1, 0, 0}}};
  return job;
}

JobOptions photon_options(int threads, const std::string& accel = "bvh") {
  JobOptions o;
  o.accel.kind = accel;
  o.integrator.area_light_samples = 2;
  o.photons.caustic_photons = 30000;
  o.photons.global_photons = 20000;
  o.photons.gather_rays = 8;
  o.render.threads = threads;
  o.render.tile_size = 8;
  return o;
}

TEST(GoldenPhotons, IdenticalForAnyThreadCountAndAccelerator) {
  const Image reference = test::TestJob(caustic_room(40), photon_options(1)).render();
  for (const int threads : {2, 3}) {
    EXPECT_EQ(test::TestJob(caustic_room(40), photon_options(threads)).render().pixels(), reference.pixels())
        << threads << " threads";
  }
  std::vector<std::string> accelerators = {"none", "grid"};
  if (accelerator_names().find("embree") != std::string::npos) accelerators.push_back("embree");
  for (const std::string& accel : accelerators)
    EXPECT_EQ(test::TestJob(caustic_room(40), photon_options(2, accel)).render().pixels(), reference.pixels()) << accel;
  // And the photons change the picture.
  JobOptions plain = photon_options(2);
  plain.photons = {};
  EXPECT_NE(test::TestJob(caustic_room(40), plain).render().pixels(), reference.pixels());
}

TEST(GoldenPhotons, StopThenResumeGivesTheSameImage) {
  // As a real resume: the second render rebuilds its photon maps in a new job.
  JobOptions options = photon_options(2);
  options.render.antialias_samples = 2;
  const Image reference = test::TestJob(caustic_room(40), options).render();
  for (const int stop_after : {3, 20}) {
    const test::TestJob first_job(caustic_room(40), options);
    const PreparedJob& a = first_job.prepared();
    ImageRender first(a.camera(), 40, 40, a.integrator(), options.render);
    first.stop_after_tiles(stop_after);
    ASSERT_FALSE(first.run());
    JobOptions three = options;
    three.render.threads = 3;  // and another thread count
    const test::TestJob second_job(caustic_room(40), three);
    const PreparedJob& b = second_job.prepared();
    ImageRender second(b.camera(), 40, 40, b.integrator(), three.render);
    second.resume_from(first.checkpoint());
    ASSERT_TRUE(second.run());
    EXPECT_EQ(second.image().pixels(), reference.pixels()) << "stopped after " << stop_after;
  }
}

/// Progressive caustics under a noise target: passes of photons and passes of samples.
JobOptions progressive_options(int threads) {
  JobOptions o = photon_options(threads);
  o.photons.caustic_passes = 4;
  o.render.noise_threshold = 0.05f;
  o.render.max_samples_per_pixel = 64;
  return o;
}

TEST(GoldenPhotons, ProgressiveCausticsUnderANoiseTargetAreIdenticalForAnyThreadCountAndResume) {
  RenderStats stats;
  const Image reference = test::TestJob(caustic_room(40), progressive_options(1)).render(&stats);
  EXPECT_GE(stats.antialias_passes, 2);  // the noise target refined some pixels twice or more
  EXPECT_GT(stats.pixels_supersampled, 0u);
  EXPECT_LT(stats.pixels_supersampled, 40u * 40u * 2);
  for (const int threads : {2, 3})
    EXPECT_EQ(test::TestJob(caustic_room(40), progressive_options(threads)).render().pixels(), reference.pixels())
        << threads << " threads";
  JobOptions one_pass = progressive_options(2);
  one_pass.photons.caustic_passes = 1;
  EXPECT_NE(test::TestJob(caustic_room(40), one_pass).render().pixels(), reference.pixels());
  // Stopped in the first pass, and in the noise passes, then resumed on other threads.
  for (const auto& [tiles, chunks] : {std::pair{5, -1}, std::pair{-1, 1}, std::pair{-1, 2}}) {
    const test::TestJob first_job(caustic_room(40), progressive_options(2));
    const PreparedJob& a = first_job.prepared();
    ImageRender first(a.camera(), 40, 40, a.integrator(), progressive_options(2).render);
    first.stop_after_tiles(tiles);
    first.stop_after_pixel_chunks(chunks);
    ASSERT_FALSE(first.run()) << tiles << " " << chunks;
    const test::TestJob second_job(caustic_room(40), progressive_options(3));
    const PreparedJob& b = second_job.prepared();
    ImageRender second(b.camera(), 40, 40, b.integrator(), progressive_options(3).render);
    second.resume_from(first.checkpoint());
    ASSERT_TRUE(second.run());
    EXPECT_EQ(second.image().pixels(), reference.pixels()) << "stopped after " << tiles << " tiles, " << chunks << " chunks";
  }
}

TEST(GoldenPhotons, FingerprintNamesThePhotonCounts) {
  const SceneDescription scene = test::single_job_scene(caustic_room(8));
  JobOptions options;
  const std::string off = job_fingerprint(scene, 0, options);
  EXPECT_NE(off.find("--caustics=0\n"), std::string::npos) << off;
  options.photons.caustic_photons = 1000000;
  options.photons.global_photons = 5000;
  const std::string on = job_fingerprint(scene, 0, options);
  EXPECT_NE(on.find("--caustics=1000000\n"), std::string::npos) << on;
  EXPECT_NE(on.find("--gi=5000\n"), std::string::npos) << on;
  EXPECT_EQ(fingerprint_difference(off, on), "--caustics: 0 then, 1000000 now; --gi: 0 then, 5000 now");
}

// --- through the program -------------------------------------------------------------------

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(GoldenPhotons, ProgramTakesPhotonCountsAndReportsThePhotonPass) {
  const auto dir = test::make_temp_dir("photons");
  {
    std::ofstream scene(dir / "scene.lua");
    scene << "local root = gr.node('root')\n"
             "local floor = gr.nh_box('floor', {-5, -1, -5}, 10)\n"
             "floor:set_material(gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1))\n"
             "root:add_child(floor)\n"
             "local ball = gr.nh_sphere('ball', {0, 9.8, 0}, 0.8)\n"
             "ball:set_material(gr.fresneldiectricmaterial({0, 0, 0}, {0.5, 0.5, 0.5}, 100, 1.0, 1.5))\n"
             "root:add_child(ball)\n"
             "gr.render(root, 'x.png', 16, 12, {0, 14, -12}, {0, -0.6, 1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1},\n"
             "          {gr.light({0, 14, 0}, {1, 1, 1}, {1, 0, 0})})\n";
  }
  const std::string mjray = "'" + test::mjray_binary().string() + "'";
  const std::string scene = "'" + (dir / "scene.lua").string() + "'";
  const std::string log = (dir / "log.txt").string(), json = (dir / "stats.json").string();
  ASSERT_EQ(run(mjray + " --quiet --stats --caustics 2e4 --gi 5000 --stats-json '" + json + "' " + scene + " 2> '" + log +
                "'"), 0) << test::read_file(log);
  const std::string summary = test::read_file(log);
  EXPECT_NE(summary.find("photons   caustic 20000 emitted"), std::string::npos) << summary;
  EXPECT_NE(summary.find("global 5000 emitted"), std::string::npos) << summary;
  EXPECT_NE(summary.find("photon pass"), std::string::npos) << summary;
  const std::string stats = test::read_file(json);
  const auto job = nlohmann::json::parse(stats).at(0);
  for (const char* key : {"photons_caustic_emitted", "photons_caustic_stored", "photons_global_emitted",
                          "photons_global_stored", "photon_irradiance_samples", "photon_rays", "seconds_photons",
                          "seconds_photon_trace", "seconds_photon_build", "seconds_photon_irradiance",
                          "photon_map_bytes"})
    EXPECT_TRUE(job.contains(key)) << key << " missing from " << stats;
  EXPECT_EQ(job["photons_caustic_emitted"], 20000) << stats;
  // Without photon options there are no photon statistics.
  ASSERT_EQ(run(mjray + " --quiet --stats-json '" + json + "' " + scene), 0);
  EXPECT_EQ(test::read_file(json).find("\"photon"), std::string::npos);
  // Counts that are not whole numbers of photons are refused as a bad command line.
  for (const char* bad : {"--caustics -1", "--caustics 1.5", "--gi x", "--gi 1e12", "--caustics"})
    EXPECT_EQ(run(mjray + " --quiet " + bad + " " + scene + " 2> /dev/null"), 2) << bad;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mjray
