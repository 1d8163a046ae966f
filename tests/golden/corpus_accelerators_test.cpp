// Every corpus scene gives the same image, bit for bit, through every accelerator: brute
// force, the uniform grid at several sizes and its optimal size, the BVH and Embree.
// Rendered in-process at a reduced size (same camera) to keep brute force affordable.

#include <gtest/gtest.h>

#include "mjray/integrator/whitted_integrator.h"
#include "mjray/accel/make_accelerator.h"
#include "mjray/lua/scene_loader.h"
#include "mjray/render/image_render.h"
#include "support/corpus_scenes.h"
#include "support/scene_builder.h"
#include "support/test_job.h"
#include "support/test_paths.h"

namespace mjray {
namespace {


std::vector<AcceleratorOptions> accelerators() {
  std::vector<AcceleratorOptions> all = {{"grid", 1}, {"grid", 8}, {"grid", 37}, {"grid", 0}, {"bvh"}};
  if (accelerator_names().find("embree") != std::string::npos) all.push_back({"embree"});
  return all;
}

class CorpusAccelerators : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusAccelerators, EveryAcceleratorGivesTheBruteForceImage) {
  MJRAY_REQUIRE_SHARED(shared);
  const SceneDescription scene = load_scene(shared / "corpus/cs488" / GetParam(), {});
  for (RenderJob job : scene.jobs) {
    // Keep the camera and aspect ratio; shrink the image.
    const double shrink = 72.0 / std::max(job.width, job.height);
    job.width = std::max(1, int(job.width * shrink));
    job.height = std::max(1, int(job.height * shrink));
    auto render_with = [&](const AcceleratorOptions& accel) {
      JobOptions options;
      options.accel = accel;
      return test::render(job, options);
    };
    const Image reference = render_with({"none"});
    for (const AcceleratorOptions& options : accelerators())
      EXPECT_EQ(render_with(options).pixels(), reference.pixels())
          << options.kind << " (grid size " << options.grid_size << ") differs from brute force";
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusAccelerators, ::testing::ValuesIn(test::corpus_scenes()),
                         [](const auto& test_info) {
                           std::string name = test_info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace mjray

namespace mjray {
namespace {

TEST(GoldenAccelerators, CoincidentSurfacesTieTheSameWayEverywhere) {
  // Two quads in one place, red then blue, and two unit spheres in one place: every camera ray
  // meets two primitives at exactly the same t. The lower primitive id wins, through every
  // accelerator.
  RenderJob job;
  job.root = test::group({test::mesh(test::floor_quad(3), PhongMaterial{{0.9f, 0.1f, 0.1f}, {0, 0, 0}, 1}),
                          test::mesh(test::floor_quad(3), PhongMaterial{{0.1f, 0.1f, 0.9f}, {0, 0, 0}, 1}),
                          test::sphere({0, 1, 0}, 0.8f, PhongMaterial{{0.1f, 0.8f, 0.1f}, {0, 0, 0}, 1}),
                          test::sphere({0, 1, 0}, 0.8f, PhongMaterial{{0.8f, 0.8f, 0.1f}, {0, 0, 0}, 1})});
  job.width = 48;
  job.height = 36;
  job.camera = {{0.3f, 4, 5}, {-0.05f, -0.6f, -1}, {0, 1, 0}, 50};
  job.ambient = {0.3f, 0.3f, 0.3f};
  job.lights = {PointLight{{2, 6, 3}, {0.7f, 0.7f, 0.7f}, {1, 0, 0}}};
  const Image reference = test::render(job);
  // The lower ids are the red quad and the green sphere.
  EXPECT_GT(reference.at(2, 33).r, 3 * reference.at(2, 33).b);
  EXPECT_GT(reference.at(24, 14).g, 3 * reference.at(24, 14).b);
  for (const AcceleratorOptions& options : accelerators()) {
    JobOptions o;
    o.accel = options;
    EXPECT_EQ(test::render(job, o).pixels(), reference.pixels()) << options.kind << " (grid " << options.grid_size << ")";
  }
}

}  // namespace
}  // namespace mjray
