// Every CS 488 corpus scene renders unchanged through the real program: into an image of the
// size it asks for, and, at the size of its reference (reference_images_test.cpp), into the
// reference's pixels.

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "mjray/io/image_reader.h"
#include "support/corpus_scenes.h"
#include "support/reference_image.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

struct CorpusScene {
  const char* path;  ///< under shared/corpus/cs488/
  const char* image; ///< the file its gr.render names
  int width;
  int height;
};

const CorpusScene kScenes[] = {
    {"hmhealey-cs488a4/data/hier.lua", "hier.png", 256, 256},
    {"hmhealey-cs488a4/data/instance.lua", "instance.png", 256, 256},
    {"hmhealey-cs488a4/data/macho-cows.lua", "macho_cows.png", 256, 256},
    {"hmhealey-cs488a4/data/nonhier.lua", "nonhier.png", 256, 256},
    {"hmhealey-cs488a4/data/nonhier2.lua", "nonhier.png", 256, 256},
    {"hmhealey-cs488a4/data/sample.lua", "island.png", 1024, 1024},
    {"hmhealey-cs488a4/data/simple-cows.lua", "simple_cows.png", 256, 256},
    {"hmhealey-cs488a4/data/simple.lua", "simple.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/hier.lua", "hier.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/instance.lua", "instance.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/macho-cows.lua", "macho-cows.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/mucho-macho-cows.lua", "real-macho-cows-newview.png", 512, 512},
    {"themarkrizkallah-cs488/A4/Assets/nonhier.lua", "nonhier.png", 512, 512},
    {"themarkrizkallah-cs488/A4/Assets/nonhier2.lua", "nonhier.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/sample.lua", "sample.png", 512, 512},
    {"themarkrizkallah-cs488/A4/Assets/simple-cows.lua", "simple-cows.png", 256, 256},
    {"themarkrizkallah-cs488/A4/Assets/simple.lua", "simple.png", 512, 512},
};

class CorpusRender : public ::testing::TestWithParam<CorpusScene> {};

TEST_P(CorpusRender, RendersUnchangedToTheSizeItAsksFor) {
  MJRAY_REQUIRE_SHARED(shared);
  const CorpusScene& scene = GetParam();
  const auto script = shared / "corpus/cs488" / scene.path;
  ASSERT_TRUE(std::filesystem::exists(script)) << script;
  const auto out = test::make_temp_dir("corpus");
  const auto log = out / "stderr.txt";
  const std::string command = "'" + test::mjray_binary().native() + "' --quiet --outdir '" + out.string() +
                              "' '" + script.string() + "' 2> '" + log.string() + "'";
  const int status = std::system(command.c_str());
  std::ifstream log_stream(log);
  const std::string messages((std::istreambuf_iterator<char>(log_stream)), {});
  ASSERT_EQ(status, 0) << messages;

  const Image image = read_image(out / scene.image);
  EXPECT_EQ(image.width(), scene.width);
  EXPECT_EQ(image.height(), scene.height);

  // The pixels too: the program at the reference's size (the same camera) gives the image
  // that the reference test's job library gave when the reference was made.
  const double shrink = std::min(1.0, 128.0 / std::max(scene.width, scene.height));
  const std::string size = std::to_string(std::max(1, int(scene.width * shrink))) + "x" +
                           std::to_string(std::max(1, int(scene.height * shrink)));
  const auto small = out / "small.png";
  ASSERT_EQ(std::system(("'" + test::mjray_binary().native() + "' --quiet --size " + size + " --output '" + small.string() +
                         "' '" + script.string() + "' 2> '" + log.string() + "'").c_str()),
            0);
  EXPECT_TRUE(test::matches_reference(read_image(small), "corpus/" + test::identifier(scene.path)));
  std::filesystem::remove_all(out);
}

std::string scene_name(const ::testing::TestParamInfo<CorpusScene>& info) {
  std::string name = info.param.path;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusRender, ::testing::ValuesIn(kScenes), scene_name);

}  // namespace
}  // namespace mjray
