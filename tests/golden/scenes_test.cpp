// Every scene the project ships (scenes/*.lua, scenes/features/*.lua, docs/images/*.lua) renders through the
// program with the options its header names, into every image the script asks for, at its
// size. What the images show is checked against references in reference_images_test.cpp.

#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "mjray/io/image_reader.h"
#include "mjray/lua/scene_loader.h"
#include "support/corpus_scenes.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

class ShippedScene : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(ShippedScene, RendersEveryImageItAsksForAtItsSize) {
  const auto& scene = GetParam();
  const auto out = test::make_temp_dir("scene");
  const auto log = out / "log.txt";
  // From the repository's root, as README says: docs/images' scenes read scenes/Assets. The
  // headers that render for minutes (photons to a noise target) stop after 10 s, which still
  // writes their one image at its size (ShippedReference renders them whole, smaller).
  const std::string command = "cd '" + test::source_dir().string() + "' && '" + test::mjray_binary().native() +
                              "' --quiet --time-limit 10" + test::header_options(scene) + " --outdir '" + out.string() +
                              "' '" + scene.string() + "' 2> '" + log.string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command << "\n" << std::ifstream(log).rdbuf();
  SceneLoadOptions options;
  options.allowed_read_folders = {test::source_dir()};
  const SceneDescription description = load_scene(scene, options);
  for (const RenderJob& job : description.jobs) {
    const Image image = read_image(out / job.output.filename());
    EXPECT_EQ(image.width(), job.width) << job.output;
    EXPECT_EQ(image.height(), job.height) << job.output;
  }
  std::filesystem::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Golden, ShippedScene, ::testing::ValuesIn(test::shipped_scenes()),
                         [](const auto& test_info) { return test_info.param.stem().string(); });

}  // namespace
}  // namespace mjray
