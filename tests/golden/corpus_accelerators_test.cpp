// Every corpus scene gives the same image, bit for bit, through every accelerator: brute
// force, the uniform grid at several sizes and its optimal size, the BVH and Embree.
// Rendered in-process at a reduced size (same camera) to keep brute force affordable.

#include <gtest/gtest.h>

#include "mjray/integrator/whitted_integrator.h"
#include "mjray/accel/make_accelerator.h"
#include "mjray/lua/scene_loader.h"
#include "mjray/render/image_render.h"
#include "support/corpus_scenes.h"
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
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace mjray
